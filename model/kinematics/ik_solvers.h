// The closed form of each family and the numeric method, as InverseKinematics
// (ik.h) calls them. Each appends its solutions to `out` (joint values in
// degrees or length units) or sets out.error; none allocates, except the
// numeric method's workspace.
#pragma once

#include <cmath>
#include <span>

#include "model/kinematics/ik.h"

namespace rs::kinematics::ik {

/// Which configurations a closed form works out: every one (solve), or
/// only the one asked for (solveConfig). Each form is a tree of branch
/// points (shoulder, elbow, wrist); it asks `takes` at each and walks only
/// the branches taken, so that one configuration costs one path through the
/// same code, and its result is bit for bit the all-solutions one.
struct Branches {
  bool all = true;
  std::uint8_t config = 0;  ///< IkConfig bits, when !all
  /// Whether the branch where `bit` is set (`set`) or clear is wanted.
  bool takes(IkConfig bit, bool set) const { return all || ((config & bit) != 0) == set; }
  /// For solveTwoLink: -1 both elbows, else the one (0: elbow +, 1: elbow -).
  int elbow() const { return all ? -1 : (config & kElbowDown) ? 1 : 0; }
};

void solveCartesian(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, IkSolutions& out);
void solveScara(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const Branches& want, IkSolutions& out);
void solveArticulated5(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, std::span<const double> ref,
                       const Branches& want, IkSolutions& out);
void solveArticulated6(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const Branches& want,
                       IkSolutions& out);
void solveSpherical6(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const Branches& want,
                     IkSolutions& out);
void solveNumeric(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, std::span<const double> ref,
                  IkSolutions& out);

/// F_0_j for joint values q (joints 1..j), without allocating.
Eigen::Isometry3d frameOf(const ChainModel& m, const double* q, int j);

/// θ_1 where the lateral coordinate of point T (frame 0) along z_1 is
/// `lateral`: up to two angles (radians), the front one first; false with
/// out.error set when T is too near joint 1's axis.
bool baseAngles(const FamilyShape& f, const Eigen::Vector3d& T, double lateral, double angles[2], IkSolutions& out);

/// Joints 4, 5, 6 of a spherical wrist from the rotation R_3_6 they must
/// make: both solutions into a and b (q[3..5]); false when too near the
/// straight wrist.
bool solveWrist(const ChainModel& m, const Eigen::Matrix3d& R_3_6, IkSolution& a, IkSolution& b, IkError& error);

/// An angle in degrees from atan2 (within ±540) into (-180, 180], as
/// normalizeDegrees but without std::remainder's cost.
inline double wrapDegrees(double d) {
  double r = d - 360.0 * std::nearbyint(d * (1.0 / 360.0));
  if (r <= -180.0) r += 360.0;
  if (r > 180.0) r -= 360.0;
  return r + 0.0;
}

/// The nearest two links reach, |l1 - l2|, for a message: 0 when it is
/// within 1e-9 of their sum (equal links, whose difference is rounding
/// noise: "reach 0 to 457.2", not "reach 2.842e-14 to 457.2").
inline double innerReach(double l1, double l2) {
  const double inner = std::abs(l1 - l2);
  return inner <= 1e-9 * (l1 + l2) ? 0.0 : inner;
}

void fail(IkSolutions& out, IkErrorKind kind, double distance, std::string message, std::string hint);

}  // namespace rs::kinematics::ik
