#include "model/workcell/grasp.h"

#include <cmath>

namespace rs::workcell {

namespace {

// Points on a face of the box count as inside (a tool centre point on a
// block's top face grips it); the slack absorbs rounding in the kinematics.
constexpr double kInsideSlack = 1e-6;

}  // namespace

Grasping::Grasping(const Workcell& cell, std::size_t robot) : cell_(&cell) {
  for (const PlacedObject& o : cell.objects) {
    resting_.push_back(o.F_world_design);
    boxes_.push_back(boundsOf(o.shape));
  }
  letGo_.assign(resting_.size(), std::nullopt);
  if (robot >= cell.robots.size()) return;
  const PlacedRobot& placed = cell.robots[robot];
  if (!placed.robot.hasGripper || !placed.robot.chain) return;
  tool_.emplace(placed);
  gripperMotor_ = static_cast<std::size_t>(placed.robot.chain->size());
}

std::optional<std::size_t> Grasping::smallestAt(const Eigen::Vector3d& point, bool partsOnly) const {
  std::optional<std::size_t> best;
  double bestVolume = 0;
  for (std::size_t o = 0; o < boxes_.size(); ++o) {
    if (boxes_[o].isEmpty() || (partsOnly && cell_->objects[o].kind != ObjectKind::Part)) continue;
    const Eigen::Vector3d local = resting_[o].inverse(Eigen::Isometry) * point;
    const Eigen::AlignedBox3d slack(boxes_[o].min().array() - kInsideSlack, boxes_[o].max().array() + kInsideSlack);
    if (!slack.contains(local)) continue;
    const double volume = boxes_[o].volume();
    if (!best || volume < bestVolume) best = o, bestVolume = volume;  // strict: the first of equals
  }
  return best;
}

std::optional<std::pair<std::size_t, double>> Grasping::nearestObject(const Eigen::Vector3d& point) const {
  std::optional<std::pair<std::size_t, double>> best;
  for (std::size_t o = 0; o < boxes_.size(); ++o) {
    if (boxes_[o].isEmpty()) continue;
    const Eigen::Vector3d local = resting_[o].inverse(Eigen::Isometry) * point;
    const double d = boxes_[o].exteriorDistance(local);
    if (!best || d < best->second) best = {o, d};
  }
  return best;
}

std::optional<GraspChange> Grasping::step(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                          bool mayTake) {
  if (!tool_ || gripperMotor_ >= before.size() || gripperMotor_ >= after.size()) return std::nullopt;
  const std::int32_t from = before[gripperMotor_], to = after[gripperMotor_];
  if (from == to) return std::nullopt;
  const bool closing = to > from;  // RANGE max is closed (min <= max always)
  if (!closing) {
    if (!held_) return std::nullopt;
    // Let go as the opening begins, and settle from where it is then.
    const std::size_t o = *held_;
    const Eigen::Isometry3d F_world_E = tool_->frame(before);
    const Settled settled = settle(*cell_, resting_, o, F_world_E * offset_);
    resting_[o] = settled.pose;
    // Settled by no more than the rest tolerance, a take at this very frame
    // holds it by the offset it had (it goes back up or down by that
    // little): a loop that puts a part down a hair off its support and
    // takes it again leaves the world bit for bit as it was.
    letGo_[o] = LetGo{F_world_E, std::abs(settled.drop) <= kSettleTolerance
                                     ? offset_
                                     : F_world_E.inverse(Eigen::Isometry) * settled.pose};
    held_.reset();
    return GraspChange{o, false, settled};
  }
  if (held_ || !mayTake) return std::nullopt;  // closing further on what it holds
  const Eigen::Isometry3d F_world_E = tool_->frame(after);
  const std::optional<std::size_t> o = partAt(F_world_E.translation());
  if (!o) return std::nullopt;
  held_ = o;
  const std::optional<LetGo>& letGo = letGo_[*o];
  offset_ = letGo && letGo->frame.matrix() == F_world_E.matrix() ? letGo->offset
                                                                  : F_world_E.inverse(Eigen::Isometry) * resting_[*o];
  return GraspChange{*o, true, {}};
}

Settled Grasping::settleHeld(std::span<const std::int32_t> encoders) {
  if (!held_ || !tool_) return {};
  return settle(*cell_, resting_, *held_, tool_->frame(encoders) * offset_);
}

void Grasping::reset() {
  held_.reset();
  for (std::size_t o = 0; o < resting_.size(); ++o) resting_[o] = cell_->objects[o].F_world_design;
  letGo_.assign(resting_.size(), std::nullopt);
}

Eigen::Isometry3d Grasping::toolFrame(std::span<const std::int32_t> encoders) {
  return tool_ ? tool_->frame(encoders) : Eigen::Isometry3d::Identity();
}

Eigen::Isometry3d Grasping::objectPose(std::size_t o, std::span<const std::int32_t> encoders) {
  if (held_ && *held_ == o && tool_) return tool_->frame(encoders) * offset_;
  return resting_[o];
}

}  // namespace rs::workcell
