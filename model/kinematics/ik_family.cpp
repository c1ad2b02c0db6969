#include "model/kinematics/ik_family.h"

#include <cmath>

#include "model/kinematics/dh.h"

namespace rs::kinematics {

namespace {

constexpr double kExact = 1e-9;  // D-H values that must be 0 (or a right angle) to this

bool zero(double v) { return std::abs(v) < kExact; }
bool rightAngle(const Joint& j) { return zero(j.cosAlpha); }    // α = ±90
bool parallel(const Joint& j) { return zero(j.sinAlpha); }      // α = 0 or 180
bool allRevolute(const ChainModel& m) {
  for (const Joint& j : m.joints())
    if (j.type() != JointType::Revolute) return false;
  return true;
}

bool cartesian(const ChainModel& m, FamilyShape& f) {
  if (m.size() != 3) return false;
  Eigen::Isometry3d F = Eigen::Isometry3d::Identity();
  for (int i = 1; i <= 3; ++i) {
    const Joint& j = m.joint(i);
    if (j.type() != JointType::Prismatic) return false;
    f.axes.col(i - 1) = F.linear().col(2);
    F = F * dhTransform(j.dh, 0.0);
  }
  if (std::abs(f.axes.determinant()) < 1e-6) return false;
  f.axesInverse = f.axes.inverse();
  f.origin = F.translation();
  f.kind = IkFamily::Cartesian;
  return true;
}

bool scara(const ChainModel& m, FamilyShape& f) {
  if (!makePlanarRun(m, 1, m.size(), Eigen::Vector3d::Zero(), f.run)) return false;
  f.kind = IkFamily::Scara;
  return true;
}

// A base joint whose axis z_0 is perpendicular to z_1 (α_1 = ±90): the rest
// of the arm moves in a plane that turns with joint 1.
bool base(const ChainModel& m, FamilyShape& f) {
  const Joint& j1 = m.joint(1);
  if (j1.type() != JointType::Revolute || !rightAngle(j1)) return false;
  f.lateralSign = -j1.sinAlpha;
  return true;
}

// Joints 4, 5, 6 turn about axes through one point (a_4 = a_5 = d_5 = 0),
// each at right angles to the next (α_4, α_5 = ±90).
bool sphericalWrist(const ChainModel& m) {
  const Joint &j4 = m.joint(4), &j5 = m.joint(5);
  return zero(j4.dh.a) && zero(j5.dh.a) && zero(j5.dh.d) && rightAngle(j4) && rightAngle(j5);
}

bool articulated5(const ChainModel& m, FamilyShape& f) {
  if (m.size() != 5 || !allRevolute(m) || !base(m, f)) return false;
  const Joint &j4 = m.joint(4), &j5 = m.joint(5);
  if (!rightAngle(j4) || !zero(j5.dh.a) || !parallel(j5)) return false;
  if (!makePlanarRun(m, 2, 4, Eigen::Vector3d(0, 0, j5.dh.d), f.run) || f.run.revolutes != 3) return false;
  f.kind = IkFamily::Articulated5;
  return true;
}

bool articulated6(const ChainModel& m, FamilyShape& f) {
  if (m.size() != 6 || !allRevolute(m) || !base(m, f) || !sphericalWrist(m)) return false;
  if (!makePlanarRun(m, 2, 3, Eigen::Vector3d(0, 0, m.joint(4).dh.d), f.run) || f.run.revolutes != 2) return false;
  f.kind = IkFamily::Articulated6;
  return true;
}

// R R P, then the wrist: joint 2 at right angles to joint 1 and to the
// prismatic reach, which runs through the wrist centre (a_3 = 0, α_3 = 0
// or 180, a_4 = 0).
bool spherical6(const ChainModel& m, FamilyShape& f) {
  if (m.size() != 6 || !sphericalWrist(m) || !base(m, f)) return false;
  const Joint &j2 = m.joint(2), &j3 = m.joint(3);
  if (j2.type() != JointType::Revolute || j3.type() != JointType::Prismatic) return false;
  for (int i = 4; i <= 6; ++i)
    if (m.joint(i).type() != JointType::Revolute) return false;
  if (!rightAngle(j2) || !zero(j3.dh.a) || !parallel(j3)) return false;
  f.kind = IkFamily::Spherical6;
  return true;
}

}  // namespace

std::string_view familyName(IkFamily family) {
  switch (family) {
    case IkFamily::Cartesian: return "cartesian";
    case IkFamily::Scara: return "scara";
    case IkFamily::Articulated5: return "articulated-5";
    case IkFamily::Articulated6: return "articulated-6";
    case IkFamily::Spherical6: return "spherical-6";
    case IkFamily::Numeric: return "numeric";
  }
  return "numeric";
}

std::string_view familyOrientation(IkFamily family) {
  switch (family) {
    case IkFamily::Cartesian: return "its tool never turns: the orientation is fixed";
    case IkFamily::Scara: return "its tool turns only about the axes of its joints (a SCARA)";
    case IkFamily::Articulated5:
      return "a five-axis arm keeps its approach in the plane of its arm (through joint 1's axis); it can pitch "
             "and roll the tool, not yaw it";
    case IkFamily::Articulated6:
    case IkFamily::Spherical6: return "its wrist sets any orientation";
    case IkFamily::Numeric: return "the numeric method meets the orientation only as far as the arm allows";
  }
  return "";
}

FamilyShape detectFamily(const ChainModel& model) {
  FamilyShape f;
  for (const Joint& j : model.joints()) f.reach += std::abs(j.dh.a) + std::abs(j.dh.d);
  f.reach = std::max(1.0, f.reach - 1.0);
  if (model.size() == 0) {
    f.numericReason = "the chain has no joints";
    return f;
  }
  if (cartesian(model, f) || scara(model, f) || articulated5(model, f) || articulated6(model, f) ||
      spherical6(model, f))
    return f;
  FamilyShape numeric;
  numeric.reach = f.reach;
  numeric.numericReason = "its D-H table matches none of the closed-form families";
  return numeric;
}

}  // namespace rs::kinematics
