// The few box and beam tests the cell's devices and sensors share: boxes
// and beams are closed sets, touching counts, with kTouch of slack.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "model/workcell/devices.h"

namespace rs::runtime {

inline constexpr double kTouch = 1e-7;

/// The world box round `b` placed at `pose`.
inline Eigen::AlignedBox3d transformedBox(const Eigen::AlignedBox3d& b, const Eigen::Isometry3d& pose) {
  Eigen::AlignedBox3d out;
  if (b.isEmpty()) return out;
  // Unturned (a part on a belt, a fixture): each corner is c + t, the same
  // bits the product below gives, without eight products.
  if (pose.linear() == Eigen::Matrix3d::Identity()) return {b.min() + pose.translation(), b.max() + pose.translation()};
  for (int c = 0; c < 8; ++c) out.extend(pose * b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
  return out;
}

inline bool boxesTouch(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  for (int k = 0; k < 3; ++k)
    if (a.min()[k] > b.max()[k] + kTouch || b.min()[k] > a.max()[k] + kTouch) return false;
  return true;
}

/// The segment a..b meets the box (slabs, with the touch slack).
inline bool beamTouches(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::AlignedBox3d& box) {
  double lo = 0, hi = 1;
  const Eigen::Vector3d e = b - a;
  for (int k = 0; k < 3; ++k) {
    const double mn = box.min()[k] - kTouch, mx = box.max()[k] + kTouch;
    if (std::abs(e[k]) < 1e-15) {
      if (a[k] < mn || a[k] > mx) return false;
      continue;
    }
    double t0 = (mn - a[k]) / e[k], t1 = (mx - a[k]) / e[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0), hi = std::min(hi, t1);
    if (lo > hi) return false;
  }
  return true;
}

/// Whether `sensor` sees something whose box is `box`.
inline bool sensorTouches(const workcell::Sensor& sensor, const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return false;
  return sensor.shape == workcell::Sensor::Shape::Beam ? beamTouches(sensor.a, sensor.b, box)
                                                       : boxesTouch(box, sensor.zone);
}

}  // namespace rs::runtime
