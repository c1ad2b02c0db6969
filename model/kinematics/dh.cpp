#include "model/kinematics/dh.h"

#include "model/kinematics/trig.h"

namespace rs::kinematics {

std::string_view jointTypeName(JointType type) {
  switch (type) {
    case JointType::Revolute: return "revolute";
    case JointType::Prismatic: return "prismatic";
  }
  return "?";
}

Eigen::Isometry3d dhTransform(const DhRow& row, double q) {
  const bool revolute = row.type == JointType::Revolute;
  const double d = revolute ? row.d : q;
  double ct, st, ca, sa;
  sinCosDegrees(revolute ? q : row.theta, st, ct);
  sinCosDegrees(row.alpha, sa, ca);
  Eigen::Isometry3d A;
  A.matrix() << ct, -ca * st, sa * st, row.a * ct,  //
      st, ca * ct, -sa * ct, row.a * st,            //
      0.0, sa, ca, d,                               //
      0.0, 0.0, 0.0, 1.0;
  return A;
}

std::vector<Eigen::Isometry3d> framesFromDh(const Eigen::Isometry3d& F_0, std::span<const DhRow> table) {
  std::vector<Eigen::Isometry3d> frames;
  frames.reserve(table.size() + 1);
  frames.push_back(F_0);
  for (const DhRow& row : table) frames.push_back(frames.back() * dhTransform(row, row.home()));
  return frames;
}

}  // namespace rs::kinematics
