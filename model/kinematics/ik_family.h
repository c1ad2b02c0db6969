// Kinematic families for inverse kinematics, recognised from the derived
// D-H table (never from a robot's name), so that any arm built like a
// library arm gets its closed form:
//
//   Cartesian     three prismatic joints (the gantry)
//   Scara         every joint axis parallel, 2..3 revolute and at most one
//                 prismatic joint (Rhino SCARA, Adept One)
//   Articulated5  a base joint, three parallel pitch joints across it and
//                 a roll joint along the tool (Rhino XR-3, SCOROBOT,
//                 Rhino XR-4, Movemaster RV-M1)
//   Articulated6  base, shoulder and elbow, then a spherical wrist
//                 (PUMA 560, ABB IRB 120)
//   Spherical6    revolute base and shoulder, a prismatic reach, then a
//                 spherical wrist (Stanford arm)
//   Numeric       anything else: damped least squares (ik_numeric.h)
//
// The exact conditions are in detectFamily (ik_family.cpp) and
// docs/models.md.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <string_view>

#include "model/kinematics/chain_model.h"
#include "model/kinematics/ik_planar.h"

namespace rs::kinematics {

enum class IkFamily : std::uint8_t { Cartesian, Scara, Articulated5, Articulated6, Spherical6, Numeric };

/// "cartesian", "scara", "articulated-5", "articulated-6", "spherical-6", "numeric".
std::string_view familyName(IkFamily family);
/// One line saying what the arm's tool orientation can do, for messages.
std::string_view familyOrientation(IkFamily family);

/// A family and the constants of its closed form.
struct FamilyShape {
  IkFamily kind = IkFamily::Numeric;
  PlanarRun run;  ///< Scara: joints 1..n; Articulated5: 2..4; Articulated6: 2..3
  /// Cartesian: each prismatic joint's direction in frame 0 (columns), its
  /// inverse, and the tool position with every d at 0.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity(), axesInverse = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  /// Articulated and Spherical6: z_1 = lateralSign · (-sin θ1, cos θ1, 0).
  double lateralSign = 0;
  /// A length of the arm's size (the sum of its |a| and |d|, at least 1):
  /// the scale of tolerances and of the numeric method's damping.
  double reach = 1;
  std::string numericReason;  ///< why no closed form fits (Numeric only)
};

FamilyShape detectFamily(const ChainModel& model);

}  // namespace rs::kinematics
