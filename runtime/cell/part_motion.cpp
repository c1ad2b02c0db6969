// The parts' motions as the pictures replay them (devices.h, PartMotion):
// a record whenever a part's motion changes, kept only when asked.
#include <algorithm>

#include "runtime/cell/devices.h"

namespace rs::runtime {

Eigen::Isometry3d PartMotion::poseAt(vm::Micros t) const {
  Eigen::Isometry3d p = pose;
  const double speed = velocity.norm();
  if (speed <= 0 || t <= at) return p;
  p.translation() += velocity / speed * std::min(speed * static_cast<double>(t - at) / 1e6, travel);
  return p;
}

// A part's motion changed when where it is now is not where its last
// record puts it, or it moves at another velocity: a new record.
void CellDevices::recordChangedMotions(vm::Micros now) {
  const std::size_t n = state_.number.size();
  if (emitted_.size() != n) emitted_.assign(n, std::nullopt);
  for (std::size_t o = 0; o < n; ++o) {
    if (cell_.objects[o].kind != workcell::ObjectKind::Part) continue;
    if (world_.holder(o)) {
      emitted_[o].reset();
      continue;
    }
    const Eigen::Isometry3d& pose = world_.restingPose(o);
    const Eigen::Vector3d& v = state_.velocity[o];
    if (const std::optional<PartMotion>& last = emitted_[o]) {
      const Eigen::Isometry3d predicted = last->poseAt(now);
      const bool same = (predicted.matrix() - pose.matrix()).cwiseAbs().maxCoeff() < 1e-6 && last->velocity == v;
      if (same) continue;
    } else if (v.isZero() && !emittedAny_) {
      // Before the first instant every part is where the cell placed it: no record needed.
      if ((pose.matrix() - cell_.objects[o].F_world_design.matrix()).cwiseAbs().maxCoeff() < 1e-9) {
        emitted_[o] = PartMotion{now, o, pose, v, 0.0};
        continue;
      }
    }
    PartMotion m{now, o, pose, v, v.isZero() ? 0.0 : state_.travel[o]};
    emitted_[o] = m;
    motions_.push_back(m);
  }
  emittedAny_ = true;
}

}  // namespace rs::runtime
