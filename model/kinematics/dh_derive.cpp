#include "model/kinematics/dh_derive.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/kinematics/angles.h"

namespace rs::kinematics {

namespace {

// Rounding noise (1e-13 where 0 was meant) would print as "-0.0000".
double clean(double value) { return std::abs(value) < 1e-12 ? 0.0 : value + 0.0; }

// The row joining frame i-1 to frame i, or the D-H rule frame i breaks.
// Everything is worked out in frame i-1, where z_{i-1} is the z axis:
// x_i = R.col(0) must have no z component (perpendicular), and the line
// through o_i along x_i must pass through the z axis (meet). Then
// o_i = d z + a x_i, so d = p.z and a = p · x_i.
Built<DhRow> deriveRow(const Eigen::Isometry3d& previous, const Eigen::Isometry3d& current, JointType type, int i,
                        const Tolerances& tol) {
  Built<DhRow> result;
  const Eigen::Matrix3d R = previous.linear().transpose() * current.linear();
  const Eigen::Vector3d p = previous.linear().transpose() * (current.translation() - previous.translation());
  const Eigen::Vector3d x = R.col(0);
  if (std::abs(x.z()) > tol.cosine) {
    const double angle = std::acos(std::clamp(x.z(), -1.0, 1.0)) * kRadToDeg;
    result.errors.push_back({ErrorKind::XNotPerpendicularToPreviousZ, i,
                             fmt::format("x{} is not perpendicular to z{} (the angle between them is {:g} degrees), "
                                         "as the D-H convention requires",
                                         i, i - 1, angle)});
    return result;
  }
  const Eigen::Vector2d xPlanar = Eigen::Vector2d(x.x(), x.y()).normalized();
  const double gap = p.y() * xPlanar.x() - p.x() * xPlanar.y();  // p · (z × x_i)
  if (std::abs(gap) > tol.distance) {
    result.errors.push_back({ErrorKind::XMissesPreviousZ, i,
                             fmt::format("x{} does not meet z{} (they pass {:g} apart), as the D-H convention "
                                         "requires",
                                         i, i - 1, std::abs(gap))});
    return result;
  }
  DhRow row;
  row.type = type;
  row.theta = clean(normalizeDegrees(std::atan2(xPlanar.y(), xPlanar.x()) * kRadToDeg));
  row.alpha = clean(normalizeDegrees(std::atan2(R(2, 1), R(2, 2)) * kRadToDeg));
  row.a = clean(p.x() * xPlanar.x() + p.y() * xPlanar.y());
  row.d = clean(p.z());
  result.value = row;
  return result;
}

}  // namespace

Built<std::vector<DhRow>> deriveDh(std::span<const Eigen::Isometry3d> frames, std::span<const JointType> types,
                                    const Tolerances& tol) {
  Built<std::vector<DhRow>> result;
  if (frames.size() != types.size() + 1) {
    result.errors.push_back({ErrorKind::CountMismatch, -1,
                             fmt::format("{} joints need {} frames (base to end effector), but {} are given",
                                         types.size(), types.size() + 1, frames.size())});
    return result;
  }
  std::vector<DhRow> table;
  table.reserve(types.size());
  for (std::size_t i = 1; i < frames.size(); ++i) {
    auto row = deriveRow(frames[i - 1], frames[i], types[i - 1], static_cast<int>(i), tol);
    if (row.value) {
      table.push_back(*row.value);
    } else {
      result.errors.insert(result.errors.end(), row.errors.begin(), row.errors.end());
    }
  }
  if (result.errors.empty()) result.value = std::move(table);
  return result;
}

}  // namespace rs::kinematics
