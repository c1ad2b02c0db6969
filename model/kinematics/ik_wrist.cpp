// The spherical wrist (joints 4, 5, 6 about axes through one point, each
// at right angles to the next), for the Articulated6 and Spherical6
// families. With s4 = sin α4, s5 = sin α5 (each ±1) and
// M = R_3_6 · Rx(α6)^T = Rz(θ4) Rx(α4) Rz(θ5) Rx(α5) Rz(θ6), the third
// column of M is
//
//   (s5 sin θ5 cos θ4,  s5 sin θ5 sin θ4,  -s4 s5 cos θ5),
//
// so θ5 comes from its last entry (two signs: the wrist flipped or not),
// θ4 from the first two, and θ6 from what is left once Rz(θ4) Rx(α4)
// Rz(θ5) Rx(α5) is taken off; the flipped solution follows from the first.
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/angles.h"
#include "model/kinematics/ik_solvers.h"

namespace rs::kinematics::ik {

namespace {

// Rz from an angle's cosine and sine (already at hand: no trigonometry).
Eigen::Matrix3d rotZ(double c, double s) {
  Eigen::Matrix3d R;
  R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}
Eigen::Matrix3d rotX(const Joint& j) {
  Eigen::Matrix3d R;
  R << 1, 0, 0, 0, j.cosAlpha, -j.sinAlpha, 0, j.sinAlpha, j.cosAlpha;
  return R;
}

}  // namespace

bool solveWrist(const ChainModel& m, const Eigen::Matrix3d& R_3_6, IkSolution& a, IkSolution& b, IkError& error) {
  const Joint &j4 = m.joint(4), &j5 = m.joint(5), &j6 = m.joint(6);
  const Eigen::Matrix3d M = R_3_6 * rotX(j6).transpose();
  const double s4 = j4.sinAlpha, s5 = j5.sinAlpha;
  const Eigen::Vector3d v = M.col(2);
  const double h = std::hypot(v.x(), v.y());
  if (h < std::sin(kSingularDegrees * kDegToRad)) {
    const double off = std::asin(std::min(1.0, h)) * kRadToDeg;
    error = IkError{IkErrorKind::Singular,
         fmt::format("near-singular pose: the wrist would be {:.3g} degrees from straight (joint 5), where joints 4 "
                     "and 6 turn about the same line",
                     off),
         fmt::format("tilt the approach at least {} degree from joint 4's axis, or teach this point in encoder counts",
                     kSingularDegrees),
         off};
    return false;
  }
  const double c5 = -s4 * s5 * v.z();
  // cos and sin of θ4 and θ5 straight from M's column (sin θ5 = h > 0).
  const double c4 = s5 * v.x() / h, s4v = s5 * v.y() / h;
  const Eigen::Matrix3d N = (rotZ(c4, s4v) * rotX(j4) * rotZ(c5, h) * rotX(j5)).transpose() * M;
  a.q[3] = wrapDegrees(std::atan2(s4v, c4) * kRadToDeg);
  a.q[4] = wrapDegrees(std::atan2(h, c5) * kRadToDeg);
  a.q[5] = wrapDegrees(std::atan2(N(1, 0), N(0, 0)) * kRadToDeg);
  // The flipped wrist: (θ4 + 180, -θ5, θ6 + 180) makes the same rotation,
  // since Rz(180) Rx(α) = Rx(-α) Rz(180) and, for α = ±90,
  // Rx(-α4) Rz(-θ5) Rx(-α5) = Rx(α4) Rz(θ5) Rx(α5).
  b.q[3] = wrapDegrees(a.q[3] + 180.0);
  b.q[4] = wrapDegrees(-a.q[4]);
  b.q[5] = wrapDegrees(a.q[5] + 180.0);
  b.config |= kWristFlip;
  return true;
}

}  // namespace rs::kinematics::ik
