#include "model/kinematics/gripper.h"

#include <fmt/format.h>

#include <cmath>

namespace rs::kinematics {

namespace {

// The errors of one part, each marked with the part it is about.
template <class T>
void take(Built<T>& part, GripperPart which, std::vector<KinematicsError>& errors) {
  for (KinematicsError e : part.errors) {
    e.index = which;
    errors.push_back(std::move(e));
  }
}

std::string point(const Eigen::Vector3d& p) { return fmt::format("({:g}, {:g}, {:g})", p.x(), p.y(), p.z()); }

}  // namespace

Built<GripperModel> makeGripper(const GripperPoints& points, double precision, const Tolerances& tol) {
  Built<GripperModel> result;
  auto r2 = lineThrough(points.r2From, points.r2To, "axis r2", tol);
  auto r3 = lineThrough(points.r3From, points.r3To, "axis r3", tol);
  take(r2, kGripperAxis2, result.errors);
  take(r3, kGripperAxis3, result.errors);
  const Eigen::Vector3d tcp = points.normalFrom;
  if (tcp.allFinite() && points.approachFrom.allFinite() && (points.approachFrom - tcp).norm() > tol.distance) {
    result.errors.push_back({ErrorKind::TcpMismatch, kGripperApproach,
                             fmt::format("the approach vector starts at {}, not at the normal vector's start {}: "
                                         "both must start at the tool centre point",
                                         point(points.approachFrom), point(tcp))});
  }
  auto frame = frameFromAxes(tcp, points.normalTo - tcp, points.approachTo - points.approachFrom, tol, -1,
                             {"the normal vector", "the approach vector"});
  take(frame, kGripperNormal, result.errors);
  if (!std::isfinite(precision) || precision == 0.0) {
    result.errors.push_back({ErrorKind::BadPrecision, kGripperWhole,
                             fmt::format("the gripper has precision {}, but it must be a non-zero number", precision)});
  }
  if (result.errors.empty()) result.value = GripperModel{*r2.value, *r3.value, *frame.value, precision};
  return result;
}

FingerTransforms fingerTransforms(const GripperModel& gripper, double encoder) {
  const double phi = gripper.precision * encoder;
  return {rotationAboutLine(gripper.r2, phi), rotationAboutLine(gripper.r3, phi)};
}

Eigen::Isometry3d gripperPlacement(const Eigen::Isometry3d& F_world_E, const GripperModel& gripper) {
  return F_world_E * gripper.F_G_E.inverse(Eigen::Isometry);
}

}  // namespace rs::kinematics
