#include "model/kinematics/forward_kinematics.h"

#include "model/kinematics/trig.h"

namespace rs::kinematics {

namespace {

// A_i = F_{i-1}_i for joint variable q, from the precomputed cos/sin of α
// (and of θ for a prismatic joint). Joints do not depend on each other
// here, so the CPU overlaps their sine/cosine work.
void fillA(const Joint& joint, double q, Eigen::Isometry3d& A) {
  double ct = joint.cosTheta, st = joint.sinTheta, d = q;
  if (joint.type() == JointType::Revolute) {
    sinCosDegrees(q, st, ct);
    d = joint.dh.d;
  }
  const double ca = joint.cosAlpha, sa = joint.sinAlpha, a = joint.dh.a;
  auto& m = A.matrix();
  m.col(0).head<3>() = Eigen::Vector3d(ct, st, 0.0);
  m.col(1).head<3>() = Eigen::Vector3d(-ca * st, ca * ct, sa);
  m.col(2).head<3>() = Eigen::Vector3d(sa * st, -sa * ct, ca);
  m.col(3).head<3>() = Eigen::Vector3d(a * ct, a * st, d);
}

// F_0_i = F_0_{i-1} · A_i, using A_i's structure. With X, Y, Z, o the
// columns of F_0_{i-1} and v = cosθ Y − sinθ X:
//   x_i = cosθ X + sinθ Y,  y_i = cosα v + sinα Z,  z_i = cosα Z − sinα v,
//   o_i = o + a cosθ X + a sinθ Y + d Z.
// The bottom row stays (0 0 0 1).
void chain(const Eigen::Isometry3d& previous, const Eigen::Isometry3d& A, Eigen::Isometry3d& current) {
  const auto& P = previous.matrix();
  const auto& m = A.matrix();
  const double ct = m(0, 0), st = m(1, 0), sa = m(2, 1), ca = m(2, 2);
  const Eigen::Vector3d X = P.col(0).head<3>(), Y = P.col(1).head<3>(), Z = P.col(2).head<3>();
  const Eigen::Vector3d v = ct * Y - st * X;
  auto& F = current.matrix();
  F.col(0).head<3>() = ct * X + st * Y;
  F.col(1).head<3>() = ca * v + sa * Z;
  F.col(2).head<3>() = ca * Z - sa * v;
  F.col(3).head<3>() = P.col(3).head<3>() + m(0, 3) * X + m(1, 3) * Y + m(2, 3) * Z;
}

}  // namespace

bool forwardKinematics(const ChainModel& model, ChainData& data, std::span<const double> q) {
  const auto n = static_cast<std::size_t>(model.size());
  if (q.size() != n || data.A.size() != n + 1 || data.F_0_i.size() != n + 1) return false;
  for (std::size_t i = 1; i <= n; ++i) {
    fillA(model.joints()[i - 1], q[i - 1], data.A[i]);
  }
  for (std::size_t i = 1; i <= n; ++i) {
    chain(data.F_0_i[i - 1], data.A[i], data.F_0_i[i]);
  }
  return true;
}

Eigen::Vector3d positionWithJoint(const ChainModel& model, const ChainData& data, std::size_t i, double value) {
  const auto n = static_cast<std::size_t>(model.size());
  Eigen::Isometry3d A, F[2];
  fillA(model.joints()[i], value, A);
  chain(data.F_0_i[i], A, F[0]);
  std::size_t at = 0;
  for (std::size_t k = i + 2; k <= n; ++k, at ^= 1) chain(F[at], data.A[k], F[at ^ 1]);
  return F[at].translation();
}

std::optional<Eigen::Isometry3d> transform(const ChainModel& model, const ChainData& data, int i, int j) {
  const int n = model.size();
  if (i < 0 || j < 0 || i > n || j > n || data.A.size() != static_cast<std::size_t>(n) + 1) return std::nullopt;
  if (i > j) return transform(model, data, j, i)->inverse(Eigen::Isometry);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int k = i + 1; k <= j; ++k) T = T * data.A[static_cast<std::size_t>(k)];
  return T;
}

Eigen::Isometry3d toolPose(const ChainModel& model, const ChainData& data) {
  if (!model.hasTool()) return model.F_world_0() * data.F_0_i.back();
  return model.F_world_0() * data.F_0_i.back() * model.F_n_tool();
}

}  // namespace rs::kinematics
