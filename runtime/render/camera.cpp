#include "runtime/render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/kinematics/trig.h"

namespace rs::render {

namespace {

// How much of the picture the workcell may fill: a little less in height,
// to leave the legend room above it.
constexpr double kFitWidth = 0.9, kFitHeight = 0.84;

}  // namespace

// The points' bounding box in view coordinates gives the centre (turned
// back into the world) and the scale s that fits it; the radius is the
// one for which the camera formula gives s at zoom 1.
Fit fitView(std::span<const Eigen::Vector3d> points, const Camera& camera) {
  if (points.empty()) return {};
  const Eigen::Matrix3d R = viewRotation(camera.view);
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points) box.extend(R * p);
  const Eigen::Vector3d size = box.sizes();
  const double W = camera.width, H = camera.height;
  double s = std::numeric_limits<double>::infinity();
  if (size.x() > 1e-9 * (1 + box.max().cwiseAbs().maxCoeff())) s = std::min(s, kFitWidth * W / size.x());
  if (size.y() > 1e-9 * (1 + box.max().cwiseAbs().maxCoeff())) s = std::min(s, kFitHeight * H / size.y());
  const double unit = 0.45 * std::min(W, H);
  return {R.transpose() * box.center(), std::isfinite(s) ? unit / s : 1.0};
}

// At zoom z the scale is z·s1, so R(p + w − c') · z·s1 = R(p + w − c) · s1
// for p = pivot when p + w − c' = (p + w − c) / z.
Fit zoomAbout(const Fit& fit, const Camera& camera, const Eigen::Vector3d& pivot) {
  const Eigen::Vector3d shifted = pivot + camera.window;
  return {shifted - (shifted - fit.center) / camera.zoom, fit.radius};
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
