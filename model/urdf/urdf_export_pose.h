// From a robot's design coordinates to URDF's: the turn that stands the
// drawing up on URDF's z, the length unit made metres, and a frame as the
// `<origin xyz rpy>` URDF writes it.
//
// A description is drawn y up (the library's convention; `UpAxis::Z` for
// one drawn z up, like scorobot) in any length unit. URDF is z up in
// metres. The turn is Rx(+90°) for a y-up drawing, (x, y, z) -> (x, -z, y),
// none for a z-up one: its matrix holds only 0 and ±1, so no frame loses a
// bit to it. A length becomes units × millimetres-per-unit / 1000 metres
// (divided last, so that 950 mm is 0.95 m, not 0.9500000000000001);
// angles are radians.
#pragma once

#include <Eigen/Geometry>

namespace rs::urdf {

/// Which axis of the design coordinates is up.
enum class UpAxis { Y, Z };

/// The rotation F_base_design: design coordinates in URDF's base_link.
Eigen::Matrix3d upTurn(UpAxis up);

/// A frame as URDF's `<origin>` says it: a translation (metres) and fixed-
/// axis roll, pitch, yaw (radians), R = Rz(yaw)·Ry(pitch)·Rx(roll).
struct Origin {
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
};

/// roll, pitch, yaw of `R`. Pitch is in [-π/2, π/2]; at a pitch of ±π/2
/// (cos pitch below 1e-12) roll is 0 and yaw takes the whole turn about z,
/// so that the angles always give R back.
Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R);

/// Frames of the design coordinates as URDF origins.
class DesignToUrdf {
 public:
  DesignToUrdf(double millimetresPerUnit, UpAxis up) : mm_(millimetresPerUnit), turn_(upTurn(up)) {}

  /// Frame X (given in design coordinates) in base_link: turned and scaled.
  Origin inBase(const Eigen::Isometry3d& F_design_X) const;
  /// Frame B in frame A (both given in design coordinates): A⁻¹·B, its
  /// translation scaled (a turn of both leaves their relative rotation).
  Origin relative(const Eigen::Isometry3d& F_design_A, const Eigen::Isometry3d& F_design_B) const;
  /// A direction given in design coordinates, in frame A.
  Eigen::Vector3d directionIn(const Eigen::Isometry3d& F_design_A, const Eigen::Vector3d& direction) const;
  /// Design length units as metres.
  double metres(double units) const { return units * mm_ / 1000; }
  Eigen::Vector3d metres(const Eigen::Vector3d& units) const { return units * mm_ / 1000; }

 private:
  double mm_;
  Eigen::Matrix3d turn_;
};

}  // namespace rs::urdf
