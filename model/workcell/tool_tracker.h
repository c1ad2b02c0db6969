// The tool centre point of a placed robot as its motors move: what the
// trace and the run summary show when a program runs on a workcell. Holds
// its own preallocated kinematics workspace (no allocation per call).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/workcell/model.h"

namespace rs::workcell {

class ToolTracker {
 public:
  /// `robot` must outlive the tracker.
  explicit ToolTracker(const PlacedRobot& robot);

  /// TCP in world coordinates for the given motor positions (arm joints
  /// first; a trailing gripper value is ignored).
  std::array<double, 3> tcp(std::span<const std::int32_t> encoders);
  /// The end-effector frame (the last frame: origin at the tool centre
  /// point) in world coordinates, for the same motor positions.
  Eigen::Isometry3d frame(std::span<const std::int32_t> encoders);

 private:
  kinematics::ChainModel chain_;  // placed in the world
  kinematics::ChainData data_;
  std::vector<double> encoders_, q_;
  // The last few frames worked out, and for what: a loop takes and lets go
  // at the same few poses, so the kinematics runs once for each.
  struct Known {
    std::vector<double> encoders;
    Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  };
  static constexpr std::size_t kKept = 4;
  std::array<Known, kKept> known_;
  std::size_t knownCount_ = 0, nextSlot_ = 0;
};

}  // namespace rs::workcell
