#include "model/workcell/tool_tracker.h"

#include <algorithm>

#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"

namespace rs::workcell {

ToolTracker::ToolTracker(const PlacedRobot& robot)
    : chain_(robot.robot.chain->placedAt(robot.F_world_design * robot.robot.frames.front())),
      data_(chain_),
      encoders_(static_cast<std::size_t>(chain_.size()), 0.0),
      q_(static_cast<std::size_t>(chain_.size()), 0.0) {}

std::array<double, 3> ToolTracker::tcp(std::span<const std::int32_t> encoders) {
  const Eigen::Vector3d p = frame(encoders).translation();
  return {p.x(), p.y(), p.z()};
}

Eigen::Isometry3d ToolTracker::frame(std::span<const std::int32_t> encoders) {
  for (std::size_t i = 0; i < encoders_.size() && i < encoders.size(); ++i) encoders_[i] = encoders[i];
  // The same motors as a recent call: its frame (a take, the sensors' look
  // and the trace ask at the same instant; a loop comes back to its poses).
  for (std::size_t k = 0; k < knownCount_; ++k)
    if (known_[k].encoders == encoders_) return known_[k].frame;
  kinematics::jointValuesFromEncoders(chain_, std::span<const double>(encoders_), q_);
  kinematics::forwardKinematics(chain_, data_, q_);
  Known& slot = known_[nextSlot_];
  slot.encoders = encoders_, slot.frame = kinematics::toolPose(chain_, data_);
  nextSlot_ = (nextSlot_ + 1) % kKept, knownCount_ = std::min(knownCount_ + 1, kKept);
  return slot.frame;
}

}  // namespace rs::workcell
