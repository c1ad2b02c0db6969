// The numeric method, for chains no closed form fits: damped least squares
// (Levenberg–Marquardt without adaptation), deterministic by construction:
//
//   start     the reference joint values (the previous point; home first)
//   error     e = (p* - p, L·ω), ω the rotation error of the axes the user
//             wrote (0.5 Σ x_k × x_k* over n, s, a when both were written,
//             a × a* or n × n* when one was, nothing when none was)
//   step      Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e, λ = 0.001 · L, L the arm's size
//             (FamilyShape::reach), J the geometric Jacobian of the rows kept
//   stop      |p* - p| ≤ 1e-9 L and |ω| ≤ 1e-9, or after 200 steps
//
// No randomness, no restarts, fixed counts and constants: the same inputs
// give the same answer wherever IEEE doubles are computed the same way.
// Only the one solution it converges to is returned.
#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/angles.h"
#include "model/kinematics/ik_solvers.h"

namespace rs::kinematics::ik {

namespace {

constexpr int kIterations = 200;
constexpr double kDamping = 0.001;  // × L
constexpr double kTolerance = 1e-9;

using Matrix6X = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, kMaxIkJoints>;

Eigen::Vector3d rotationError(const Eigen::Matrix3d& R, const ToolTarget& t) {
  const Eigen::Matrix3d& G = t.rotation;
  if (t.approachGiven && t.normalGiven)
    return 0.5 * (R.col(0).cross(G.col(0)) + R.col(1).cross(G.col(1)) + R.col(2).cross(G.col(2)));
  if (t.approachGiven) return R.col(2).cross(G.col(2));
  if (t.normalGiven) return R.col(0).cross(G.col(0));
  return Eigen::Vector3d::Zero();
}

}  // namespace

void solveNumeric(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, std::span<const double> ref,
                  IkSolutions& out) {
  const int n = m.size();
  const double L = f.reach;
  IkSolution s;
  for (int i = 0; i < n; ++i) s.q[static_cast<std::size_t>(i)] = ref[static_cast<std::size_t>(i)];
  std::array<Eigen::Isometry3d, kMaxIkJoints + 1> F;
  Matrix6X J(6, n);
  Eigen::Matrix<double, 6, 1> e;
  double positionError = 0, angleError = 0;
  for (int step = 0; step <= kIterations; ++step) {
    F[0] = Eigen::Isometry3d::Identity();
    for (int i = 1; i <= n; ++i)
      F[static_cast<std::size_t>(i)] = F[static_cast<std::size_t>(i - 1)] * dhTransform(m.joint(i).dh, s.q[static_cast<std::size_t>(i - 1)]);
    const Eigen::Isometry3d& tool = F[static_cast<std::size_t>(n)];
    e.head<3>() = t.position - tool.translation();
    const Eigen::Vector3d w = rotationError(tool.linear(), t);
    e.tail<3>() = L * w;
    positionError = e.head<3>().norm(), angleError = w.norm();
    if (positionError <= kTolerance * L && angleError <= kTolerance) {
      for (int i = 0; i < n; ++i)
        if (m.joint(i + 1).type() == JointType::Revolute)
          s.q[static_cast<std::size_t>(i)] = normalizeDegrees(s.q[static_cast<std::size_t>(i)]);
      out.solutions[0] = s;
      out.count = 1;
      return;
    }
    if (step == kIterations) break;
    const bool orient = t.approachGiven || t.normalGiven;
    for (int i = 1; i <= n; ++i) {
      const Eigen::Vector3d z = F[static_cast<std::size_t>(i - 1)].linear().col(2);
      const Eigen::Vector3d o = F[static_cast<std::size_t>(i - 1)].translation();
      auto col = J.col(i - 1);
      if (m.joint(i).type() == JointType::Revolute) {
        col.head<3>() = z.cross(tool.translation() - o) * kDegToRad;  // per degree
        col.tail<3>() = orient ? Eigen::Vector3d(L * z * kDegToRad) : Eigen::Vector3d::Zero();
      } else {
        col.head<3>() = z;
        col.tail<3>().setZero();
      }
    }
    const double lambda = kDamping * L;
    const Eigen::Matrix<double, 6, 6> A = J * J.transpose() + lambda * lambda * Eigen::Matrix<double, 6, 6>::Identity();
    const Eigen::Matrix<double, 6, 1> y = A.ldlt().solve(e);
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxIkJoints, 1> dq = J.transpose() * y;
    for (int i = 0; i < n; ++i) s.q[static_cast<std::size_t>(i)] += dq[i];
  }
  fail(out, IkErrorKind::NotConverged, positionError,
       fmt::format("the numeric method got no nearer than {:.4g} (and {:.3g} degrees) to the pose in {} steps: it "
                   "is out of reach, or too far from the previous point to find from there",
                   positionError, angleError * kRadToDeg, kIterations),
       "check the point is within reach; or put a point between the previous one and this one");
}

}  // namespace rs::kinematics::ik
