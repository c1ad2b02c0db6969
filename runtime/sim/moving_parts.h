// Parts that move on their own clock while a robot's move is checked: a
// cell run's other robots (runtime/run/robot_obstacles.h), appended to the
// objects of the collision watch's cell. The watch poses them at each
// check of a move and keeps its checks close enough that the move and
// they together cannot close a gap unseen (runtime/sim/collision_watch.h).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>

#include "vm/machine.h"

namespace rs::runtime {

class MovingParts {
 public:
  /// Their poses with their motors at time t, one per part, into `poses`.
  virtual void pose(vm::Micros t, std::span<Eigen::Isometry3d> poses) = 0;
  /// A bound on how far any point of theirs, or of a part one of them
  /// carries, moves from t0 to t1 (0: none moves).
  virtual double travel(vm::Micros t0, vm::Micros t1) = 0;
  /// The motors of robot `robot` of the cell at time t (empty: it is not
  /// one of them), valid until the next call.
  virtual std::span<const std::int32_t> motorsAt(std::size_t robot, vm::Micros t) = 0;

 protected:
  ~MovingParts() = default;
};

}  // namespace rs::runtime
