// The other robots of a cell as obstacles in one robot's swept check
// (issue 36): a copy of the cell with every other robot's links and
// gripper appended to its objects as fixtures (named "link 2 (upper_arm)
// of robot 'right'"), and their poses as those robots' motors stand. The
// collision watch of a robot in a cell run checks against this view; the
// world, the devices and every picture keep the cell itself. A robot that
// can never reach the moving one (their bases farther apart than the sum
// of their reaches, what either may carry included: CollisionModel::reach)
// is left out, and costs its checks nothing.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <span>
#include <vector>

#include "model/workcell/collision_model.h"
#include "model/workcell/model.h"
#include "runtime/sim/moving_parts.h"
#include "runtime/sim/sim_machine.h"

namespace rs::runtime {

class RobotObstacles final : public MovingParts {
 public:
  /// Robot `robot` of `cell` moves; the others are its obstacles. `cell`
  /// must outlive this.
  RobotObstacles(const workcell::Workcell& cell, std::size_t robot);
  ~RobotObstacles();
  RobotObstacles(const RobotObstacles&) = delete;
  RobotObstacles& operator=(const RobotObstacles&) = delete;

  /// The cell's objects, then the other robots' parts.
  const workcell::Workcell& view() const { return view_; }
  /// The index of the first other robot's part among view()'s objects.
  std::size_t firstPart() const { return first_; }
  bool any() const { return view_.objects.size() > first_; }
  /// The machine of robot `r` (null: it stands at home); it must outlive this.
  void machine(std::size_t r, const SimMachine* machine);
  /// Every other robot's parts' poses with its motors at time `at` of its
  /// move under way (SimMachine::positionAt), into `poses`: one per part,
  /// in view()'s order from firstPart() on.
  void pose(vm::Micros at, std::span<Eigen::Isometry3d> poses) override;
  /// The most any point of one other robot (or what it may carry) moves
  /// from t0 to t1: the counts each motor covers times its weight.
  double travel(vm::Micros t0, vm::Micros t1) override;
  std::span<const std::int32_t> motorsAt(std::size_t robot, vm::Micros t) override;

 private:
  struct Other;
  workcell::Workcell view_;
  std::size_t first_ = 0;
  std::vector<std::unique_ptr<Other>> others_;
};

}  // namespace rs::runtime
