#include "tests/collision/sampling_sweep.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace collisiontest {

std::optional<SampledHit> samplingSweep(const rs::workcell::CollisionModel& model, rs::workcell::CollisionData& data,
                                        const rs::runtime::SimMachine& machine, const rs::runtime::World& world,
                                        std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                        rs::vm::Micros start, rs::vm::Micros end, std::uint64_t& checks,
                                        double step) {
  if (!model.movable()) return std::nullopt;
  std::vector<Eigen::Isometry3d> poses(model.cell().objects.size());
  const rs::workcell::CollisionQuery query = world.collisionQuery(before, after, poses);
  std::vector<double> weights(model.motorWeights().size());
  if (query.held) {
    double reach = 0;
    for (const rs::workcell::CollisionPiece& piece : model.objectBodies()[*query.held].pieces)
      for (const Eigen::Vector3d& p : piece.points) reach = std::max(reach, (query.heldOffset * p).norm());
    model.motorWeightsCarrying(reach, weights);
  } else {
    weights.assign(model.motorWeights().begin(), model.motorWeights().end());
  }
  std::vector<std::int32_t> at(before.begin(), before.end());
  const auto travel = [&](rs::vm::Micros t) {
    double sum = 0;
    for (std::size_t m = 0; m < weights.size() && m < at.size(); ++m)
      sum += weights[m] * std::abs(static_cast<double>(machine.positionAt(m, t)) - at[m]);
    return sum;
  };
  (void)after;
  rs::vm::Micros t = start;
  rs::vm::Micros stride = 1;  // the last step's length: where the search for the next starts
  while (true) {
    ++checks;
    if (const std::optional<rs::workcell::Contact> c = data.findContact(at, query)) return SampledHit{t, *c};
    if (t >= end) return std::nullopt;
    rs::vm::Micros next = end;
    if (travel(end) > step) {
      // The latest time within the bound, by bisection. Each motor goes one
      // way in a move, so the travel grows with time and that time is
      // unique: a search that first gallops out from the last step's length
      // finds the same one as a bisection over the whole rest of the move
      // (the reference's answer is unchanged), in a few evaluations
      // instead of about twenty.
      rs::vm::Micros lo = t, hi = end;  // travel(lo) <= bound < travel(hi)
      for (rs::vm::Micros probe = stride; t + probe < end; probe *= 2) {
        if (travel(t + probe) > step) {
          hi = t + probe;
          break;
        }
        lo = t + probe;
      }
      while (hi - lo > 1) {
        const rs::vm::Micros mid = lo + (hi - lo) / 2;
        (travel(mid) <= step ? lo : hi) = mid;
      }
      next = lo > t ? lo : hi;
    }
    stride = std::max<rs::vm::Micros>(1, next - t);
    t = next;
    for (std::size_t m = 0; m < at.size(); ++m) at[m] = machine.positionAt(m, t);
  }
}

}  // namespace collisiontest
