#include "model/kinematics/ik_planar.h"

#include <algorithm>
#include <cmath>

#include "model/kinematics/angles.h"

namespace rs::kinematics {

namespace {

// cos α of a D-H twist that must be 0 or 180 degrees: ±1, or 0 when it is neither.
double mirrorOf(double alphaDegrees) {
  const double c = std::cos(alphaDegrees * kDegToRad);
  if (std::abs(c - 1.0) < 1e-12) return 1.0;
  if (std::abs(c + 1.0) < 1e-12) return -1.0;
  return 0.0;
}

}  // namespace

bool makePlanarRun(const ChainModel& model, int first, int last, const Eigen::Vector3d& Q, PlanarRun& run) {
  run = PlanarRun{};
  run.first = first, run.last = last;
  if (first < 1 || last > model.size() || first >= last) return false;
  double sigma = 1.0, fixed = 0.0;
  int group = -1;  // -1: the constant part C, before the first revolute joint
  for (int i = first; i <= last; ++i) {
    const Joint& j = model.joint(i);
    if (j.type() == JointType::Revolute) {
      if (run.revolutes == 3) return false;
      group = run.revolutes++;
      run.revolute[static_cast<std::size_t>(group)] = i;
      run.sign[static_cast<std::size_t>(group)] = sigma;
    } else {
      if (run.prismatic != 0) return false;
      run.prismatic = i, run.prismaticSign = sigma;
      fixed += sigma * j.dh.theta * kDegToRad;
    }
    Eigen::Vector2d u(j.dh.a, 0.0);
    double along = sigma * (j.type() == JointType::Prismatic ? 0.0 : j.dh.d);
    if (i == last) {
      const double ca = j.cosAlpha, sa = j.sinAlpha;
      const Eigen::Vector3d Qr(Q.x(), ca * Q.y() - sa * Q.z(), sa * Q.y() + ca * Q.z());
      u = Eigen::Vector2d(j.dh.a + Qr.x(), sigma * Qr.y());
      along += sigma * Qr.z();
    } else {
      const double m = mirrorOf(j.dh.alpha);
      if (m == 0.0) return false;
      sigma *= m;
    }
    run.along += along;
    const Eigen::Vector2d term = rotate2(fixed, u);
    if (group < 0)
      run.offset += term;
    else
      run.link[static_cast<std::size_t>(group)] += term;
  }
  run.fixedHeading = fixed;
  if (run.revolutes < 2) return false;
  return run.link[0].norm() > 1e-9 && run.link[1].norm() > 1e-9;
}

bool solveTwoLink(const Eigen::Vector2d& W, const Eigen::Vector2d& V0, const Eigen::Vector2d& V1,
                  std::array<Eigen::Vector2d, 2>& phis, double& miss, double& sinElbow, int only) {
  const double l0 = V0.norm(), l1 = V1.norm(), r = W.norm();
  // The links' own directions: 0 for the usual (a, 0) links, no atan2 then.
  const double b0 = V0.y() == 0.0 && V0.x() > 0 ? 0.0 : std::atan2(V0.y(), V0.x());
  const double b1 = V1.y() == 0.0 && V1.x() > 0 ? 0.0 : std::atan2(V1.y(), V1.x());
  const double c = (r * r - l0 * l0 - l1 * l1) / (2.0 * l0 * l1);
  miss = 0.0;
  if (c > 1.0) miss = r - (l0 + l1);
  if (c < -1.0) miss = std::abs(l0 - l1) - r;
  if (miss > 0.0) return false;
  const double cc = std::clamp(c, -1.0, 1.0);
  const double gamma = std::acos(cc);  // angle from link 0's direction to link 1's
  sinElbow = std::sqrt(std::max(0.0, 1.0 - cc * cc));
  const double towards = std::atan2(W.y(), W.x());
  for (int k = 0; k < 2; ++k) {
    if (only >= 0 && k != only) continue;
    const double g = k == 0 ? gamma : -gamma;
    const double sg = k == 0 ? sinElbow : -sinElbow;
    const double d0 = towards - std::atan2(l1 * sg, l0 + l1 * cc);  // direction of link 0
    const double phi0 = d0 - b0;
    const double phi1 = d0 + g - b1;
    phis[static_cast<std::size_t>(k)] = Eigen::Vector2d(phi0, phi1);
  }
  return true;
}

}  // namespace rs::kinematics
