#include "runtime/collision_watch.h"

#include <fmt/format.h>

#include "runtime/world.h"

namespace rs::runtime {

std::string_view collisionModeName(CollisionMode mode) {
  switch (mode) {
    case CollisionMode::Error: return "error";
    case CollisionMode::Warn: return "warn";
    case CollisionMode::Off: return "off";
  }
  return "";
}

std::optional<CollisionMode> collisionModeByName(std::string_view name) {
  for (CollisionMode m : {CollisionMode::Error, CollisionMode::Warn, CollisionMode::Off})
    if (name == collisionModeName(m)) return m;
  return std::nullopt;
}

CollisionWatch::CollisionWatch(const workcell::Workcell& cell)
    : model_(cell), data_(model_), poses_(cell.objects.size()), weights_(model_.motorWeights().size()) {}

std::string CollisionWatch::describe(const workcell::Contact& contact) const {
  return fmt::format("{} hits {}", model_.describe(contact.a), model_.describe(contact.b));
}

// How far, at most, any point has moved from the last check (motors at_)
// to time t: each motor's counts covered times its weight.
double CollisionWatch::travel(const SimMachine& machine, vm::Micros t) const {
  double sum = 0;
  for (std::size_t m = 0; m < weights_.size() && m < at_.size(); ++m)
    sum += weights_[m] * std::abs(static_cast<double>(machine.positionAt(m, t)) - at_[m]);
  return sum;
}

const CollisionEvent* CollisionWatch::sweep(const SimMachine& machine, const World& world,
                                            std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                            vm::Micros start, vm::Micros end) {
  if (!model_.movable()) return nullptr;
  const workcell::CollisionQuery query = world.collisionQuery(before, after, poses_);
  if (query.held) {
    double reach = 0;
    for (const workcell::CollisionPiece& piece : model_.objectBodies()[*query.held].pieces)
      for (const Eigen::Vector3d& p : piece.points) reach = std::max(reach, (query.heldOffset * p).norm());
    model_.motorWeightsCarrying(reach, weights_);
  } else {
    std::copy(model_.motorWeights().begin(), model_.motorWeights().end(), weights_.begin());
  }
  at_.assign(before.begin(), before.end());
  sample_.resize(at_.size());
  vm::Micros t = start;
  while (true) {
    ++checks_;
    if (const std::optional<workcell::Contact> c = data_.findContact(at_, query)) {
      events_.push_back({t, *c, at_});
      return &events_.back();
    }
    if (t >= end) return nullptr;
    // The latest time whose travel from the last check is within the
    // bound; when one count already goes farther, the first time it moves.
    vm::Micros next = end;
    if (travel(machine, end) > workcell::kSweepStep) {
      vm::Micros lo = t, hi = end;  // travel(lo) <= bound < travel(hi)
      while (hi - lo > 1) {
        const vm::Micros mid = lo + (hi - lo) / 2;
        (travel(machine, mid) <= workcell::kSweepStep ? lo : hi) = mid;
      }
      next = lo > t ? lo : hi;
    }
    t = next;
    for (std::size_t m = 0; m < at_.size(); ++m) at_[m] = machine.positionAt(m, t);
  }
}

}  // namespace rs::runtime
