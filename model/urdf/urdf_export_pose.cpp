#include "model/urdf/urdf_export_pose.h"

#include <cmath>

namespace rs::urdf {

Eigen::Matrix3d upTurn(UpAxis up) {
  Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
  if (up == UpAxis::Y) turn << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // Rx(+90°), written exactly
  return turn;
}

Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R) {
  // R = Rz(y)·Ry(p)·Rx(r): first column (cy cp, sy cp, -sp), last row (-sp, cp sr, cp cr).
  const double cosPitch = std::hypot(R(0, 0), R(1, 0));
  const double pitch = std::atan2(-R(2, 0), cosPitch);
  if (cosPitch < 1e-12) return {0.0, pitch, std::atan2(-R(0, 1), R(1, 1))};
  return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

namespace {

Origin originOf(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  return {translation, rpyFromRotation(rotation)};
}

}  // namespace

Origin DesignToUrdf::inBase(const Eigen::Isometry3d& F_design_X) const {
  return originOf(turn_ * F_design_X.linear(), metres(turn_ * F_design_X.translation()));
}

Origin DesignToUrdf::relative(const Eigen::Isometry3d& F_design_A, const Eigen::Isometry3d& F_design_B) const {
  const Eigen::Isometry3d F_A_B = F_design_A.inverse(Eigen::Isometry) * F_design_B;
  return originOf(F_A_B.linear(), metres(F_A_B.translation()));
}

Eigen::Vector3d DesignToUrdf::directionIn(const Eigen::Isometry3d& F_design_A, const Eigen::Vector3d& direction) const {
  return F_design_A.linear().transpose() * direction;
}

}  // namespace rs::urdf
