#include "model/workcell/reach.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"

namespace rs::workcell {

namespace {

// The seven quantities searched: -x, +x, -y, +y, -z, +z of the tool
// centre point in the world, and its distance from joint 1's axis.
constexpr int kObjectives = 7;
constexpr int kGridEvaluations = 100000;

class Search {
 public:
  explicit Search(const PlacedRobot& placed)
      : robot_(placed.robot),
        chain_(placed.robot.chain->placedAt(placed.F_world_design * placed.robot.frames.front())),
        data_(chain_),
        counts_(static_cast<std::size_t>(chain_.size()), 0.0),
        q_(static_cast<std::size_t>(chain_.size()), 0.0) {}

  std::size_t motors() const { return counts_.size(); }
  std::int32_t min(std::size_t m) const { return robot_.joints[m].min; }
  std::int32_t max(std::size_t m) const { return robot_.joints[m].max; }

  // The seven quantities at the given counts, each to be made as large as
  // possible.
  std::array<double, kObjectives> values(std::span<const std::int32_t> counts) {
    for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] = counts[i];
    kinematics::jointValuesFromEncoders(chain_, std::span<const double>(counts_), q_);
    kinematics::forwardKinematics(chain_, data_, q_);
    const Eigen::Vector3d p = kinematics::toolPose(chain_, data_).translation();
    const Eigen::Vector3d in0 = chain_.F_world_0().inverse() * p;  // in frame 0: z0 is joint 1's axis
    return {-p.x(), p.x(), -p.y(), p.y(), -p.z(), p.z(), std::hypot(in0.x(), in0.y())};
  }

 private:
  const Robot& robot_;
  kinematics::ChainModel chain_;
  kinematics::ChainData data_;
  std::vector<double> counts_, q_;
};

// Grid points of one motor: `n` counts evenly spread from min to max (both
// included), and 0 (home) when it lies in the range.
std::vector<std::int32_t> gridOf(std::int32_t lo, std::int32_t hi, int n) {
  std::vector<std::int32_t> g;
  for (int k = 0; k < n; ++k)
    g.push_back(static_cast<std::int32_t>(std::lround(lo + (static_cast<double>(hi) - lo) * k / std::max(1, n - 1))));
  if (lo <= 0 && 0 <= hi) g.push_back(0);
  std::sort(g.begin(), g.end());
  g.erase(std::unique(g.begin(), g.end()), g.end());
  return g;
}

// From `start`, moves one motor at a time by `step` counts while that
// improves objective `o`, halving the step down to one count.
void climb(Search& search, int o, std::vector<std::int32_t>& at, double& best) {
  std::int64_t widest = 1;  // 64 bits: a range may span more than 2^31 counts
  for (std::size_t m = 0; m < at.size(); ++m)
    widest = std::max(widest, (static_cast<std::int64_t>(search.max(m)) - search.min(m)) / 8);
  for (std::int64_t step = widest; step >= 1; step /= 2) {
    for (bool improved = true; improved;) {
      improved = false;
      for (std::size_t m = 0; m < at.size(); ++m)
        for (const std::int32_t dir : {-1, 1}) {
          const std::int32_t before = at[m];
          const std::int64_t next = static_cast<std::int64_t>(before) + dir * step;
          if (next < search.min(m) || next > search.max(m)) continue;
          at[m] = static_cast<std::int32_t>(next);
          const double v = search.values(at)[static_cast<std::size_t>(o)];
          if (v > best + 1e-12) best = v, improved = true;
          else at[m] = before;
        }
    }
  }
}

}  // namespace

Reach reachOf(const PlacedRobot& robot) {
  Search search(robot);
  const std::size_t n = search.motors();
  const int perMotor =
      n == 0 ? 1 : std::max(2, static_cast<int>(std::floor(std::pow(kGridEvaluations, 1.0 / static_cast<double>(n)))));
  std::vector<std::vector<std::int32_t>> grids;
  for (std::size_t m = 0; m < n; ++m) grids.push_back(gridOf(search.min(m), search.max(m), perMotor));

  std::array<double, kObjectives> best;
  best.fill(-INFINITY);
  std::array<std::vector<std::int32_t>, kObjectives> bestAt;
  std::vector<std::size_t> index(n, 0);
  std::vector<std::int32_t> at(n, 0);
  // Every grid point, as an odometer over the motors.
  for (bool more = true; more;) {
    for (std::size_t m = 0; m < n; ++m) at[m] = grids[m][index[m]];
    const std::array<double, kObjectives> v = search.values(at);
    for (int o = 0; o < kObjectives; ++o)
      if (v[static_cast<std::size_t>(o)] > best[static_cast<std::size_t>(o)])
        best[static_cast<std::size_t>(o)] = v[static_cast<std::size_t>(o)], bestAt[static_cast<std::size_t>(o)] = at;
    more = false;
    for (std::size_t m = 0; m < n && !more; ++m) {
      if (++index[m] < grids[m].size()) more = true;
      else index[m] = 0;
    }
  }
  for (int o = 0; o < kObjectives; ++o)
    climb(search, o, bestAt[static_cast<std::size_t>(o)], best[static_cast<std::size_t>(o)]);

  Reach reach;
  reach.min = {-best[0], -best[2], -best[4]};
  reach.max = {best[1], best[3], best[5]};
  if (n > 0 && robot.robot.joints.front().type == kinematics::JointType::Revolute) reach.radius = best[6];
  return reach;
}

}  // namespace rs::workcell
