#include "model/kinematics/frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/kinematics/angles.h"

namespace rs::kinematics {

namespace {

KinematicsError error(ErrorKind kind, int index, std::string message) { return {kind, index, std::move(message)}; }

KinematicsError notFinite(std::string_view what, int index) {
  return error(ErrorKind::NotFinite, index, fmt::format("{} has a coordinate that is not a finite number", what));
}

KinematicsError zeroLength(std::string_view what, int index) {
  return error(ErrorKind::DegenerateAxis, index, fmt::format("{} has zero length", what));
}

}  // namespace

Built<Line> lineThrough(const Eigen::Vector3d& from, const Eigen::Vector3d& to, std::string_view name,
                         const Tolerances& tol, int index) {
  Built<Line> result;
  if (!from.allFinite() || !to.allFinite()) {
    result.errors.push_back(notFinite(name, index));
    return result;
  }
  const Eigen::Vector3d span = to - from;
  const double length = span.norm();
  if (!std::isfinite(length)) {
    result.errors.push_back(notFinite(name, index));
  } else if (length <= tol.length) {
    result.errors.push_back(zeroLength(name, index));
  } else {
    result.value = Line{from, span / length};
  }
  return result;
}

// Checks every input before building, so that one call reports all of a
// frame's problems (both axes degenerate, say) rather than the first.
Built<Eigen::Isometry3d> frameFromAxes(const Eigen::Vector3d& origin, const Eigen::Vector3d& xDirection,
                                        const Eigen::Vector3d& zDirection, const Tolerances& tol, int index,
                                        AxisNames names) {
  Built<Eigen::Isometry3d> result;
  if (!origin.allFinite()) result.errors.push_back(notFinite("the origin", index));
  const double xLength = xDirection.norm();
  const double zLength = zDirection.norm();
  if (!std::isfinite(xLength)) {
    result.errors.push_back(notFinite(names.x, index));
  } else if (xLength <= tol.length) {
    result.errors.push_back(zeroLength(names.x, index));
  }
  if (!std::isfinite(zLength)) {
    result.errors.push_back(notFinite(names.z, index));
  } else if (zLength <= tol.length) {
    result.errors.push_back(zeroLength(names.z, index));
  }
  if (!result.errors.empty()) return result;

  const Eigen::Vector3d x = xDirection / xLength;
  Eigen::Vector3d z = zDirection / zLength;
  const double cosine = x.dot(z);
  if (std::abs(cosine) > tol.cosine) {
    const double angle = std::acos(std::clamp(cosine, -1.0, 1.0)) * kRadToDeg;
    result.errors.push_back(error(ErrorKind::AxesNotPerpendicular, index,
                                  fmt::format("{} and {} are not perpendicular (the angle between them is {:g} "
                                              "degrees)",
                                              names.x, names.z, angle)));
    return result;
  }
  z = (z - cosine * x).normalized();
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  frame.linear().col(0) = x;
  frame.linear().col(1) = z.cross(x);
  frame.linear().col(2) = z;
  frame.translation() = origin;
  result.value = frame;
  return result;
}

Built<Eigen::Isometry3d> frameFromPoints(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r,
                                          const Tolerances& tol, int index) {
  return frameFromAxes(p, q - p, r - p, tol, index);
}

Eigen::Isometry3d rotationAboutLine(const Line& line, double degrees) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = Eigen::AngleAxisd(degrees * kDegToRad, line.direction).toRotationMatrix();
  motion.translation() = line.point - motion.linear() * line.point;
  return motion;
}

}  // namespace rs::kinematics
