// How far a placed robot reaches: what `robotsim describe` tells a student
// who wonders whether a block is within the arm's range. Found by search
// over whole encoder counts (the only positions a motor takes): a grid
// over every motor's range, then a climb one motor at a time with halving
// steps down to one count. The search sees the same joint values as a run
// (precision, coupling), so what it finds is a pose a program can reach;
// an envelope found by search is at least as large as reported, and exact
// when each extreme lies at a grid point or on a single hill.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "model/workcell/model.h"

namespace rs::workcell {

struct Reach {
  /// The tool centre point's greatest distance from joint 1's axis (the z
  /// axis of frame 0); empty when joint 1 is prismatic (its axis is a
  /// direction of travel, not a centre).
  std::optional<double> radius;
  /// The box (world coordinates) the tool centre point was found to span.
  Eigen::Vector3d min = Eigen::Vector3d::Zero(), max = Eigen::Vector3d::Zero();
};

/// The reach of `robot`'s arm (its gripper's motor does not move the tool
/// centre point). Deterministic; about 10^5 forward kinematics.
Reach reachOf(const PlacedRobot& robot);

}  // namespace rs::workcell
