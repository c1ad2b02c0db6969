#include "runtime/render/camera.h"

#include <algorithm>

#include "runtime/kinematics/trig.h"

namespace rs::render {

Fit fitBox(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return {};
  const double radius = 0.5 * box.diagonal().norm();
  return {box.center(), radius > 1e-9 ? radius : 1.0};
}

Eigen::Matrix3d viewRotation(const Eigen::Vector3d& degrees) {
  double sx, cx, sy, cy, sz, cz;
  kinematics::sinCosDegrees(degrees.x(), sx, cx);
  kinematics::sinCosDegrees(degrees.y(), sy, cy);
  kinematics::sinCosDegrees(degrees.z(), sz, cz);
  Eigen::Matrix3d Rx, Ry, Rz;
  Rx << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  Ry << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  Rz << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  return Rx * Ry * Rz;
}

// u = W/2 + s·(R(p + w − c)).x, v = H/2 − s·(R(p + w − c)).y: one affine map.
Projection::Projection(const Camera& camera, const Fit& fit) {
  scale_ = camera.zoom * 0.45 * std::min(camera.width, camera.height) / fit.radius;
  const Eigen::Matrix3d R = viewRotation(camera.view);
  const Eigen::Vector3d flip(scale_, -scale_, scale_);
  M_ = flip.asDiagonal() * R;
  t_ = M_ * (camera.window - fit.center) + Eigen::Vector3d(0.5 * camera.width, 0.5 * camera.height, 0.0);
}

}  // namespace rs::render
