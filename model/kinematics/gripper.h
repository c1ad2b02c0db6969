// The gripper (the paper's DESIGN GRIPPER): a base link that does not move
// and two fingers that turn about the axes r2 and r3 as the gripper closes.
// Everything is drawn in the gripper's design coordinates G, open, at home.
//
// Sense of rotation: r2 and r3 are directed lines (from their first point to
// their second). Closing turns finger 2 by +φ about r2 and finger 3 by +φ
// about r3, both right-handed about the axis as given, where
// φ = precision × encoder (degrees; encoder min = open, max = closed).
// That is the paper's Fig. 2: with r2 pointing out of the page, finger 2
// turns counter-clockwise as seen; with r3 pointing into the page, finger 3
// turns clockwise as seen.
#pragma once

#include <Eigen/Geometry>

#include "model/kinematics/error.h"
#include "model/kinematics/frame.h"

namespace rs::kinematics {

/// The points a gripper description gives, in its design coordinates G.
struct GripperPoints {
  Eigen::Vector3d r2From, r2To;              ///< finger 2's axis
  Eigen::Vector3d r3From, r3To;              ///< finger 3's axis
  Eigen::Vector3d normalFrom, normalTo;      ///< n: the end effector's x axis
  Eigen::Vector3d approachFrom, approachTo;  ///< a: its z axis; starts at normalFrom (the TCP)
};

/// A validated gripper.
struct GripperModel {
  Line r2, r3;
  Eigen::Isometry3d F_G_E = Eigen::Isometry3d::Identity();  ///< end-effector frame (origin at the TCP) in G
  double precision = 1.0;                                   ///< degrees of finger rotation per encoder count
};

/// Which of a gripper's vectors an error is about: its KinematicsError::index,
/// so that a reader points at the line that gave the vector.
enum GripperPart : int {
  kGripperWhole = -1,     ///< the precision
  kGripperNormal = 0,     ///< the normal vector (and the frame n and a make)
  kGripperApproach = 1,   ///< the approach vector's start
  kGripperAxis2 = 2,      ///< finger 2's axis r2
  kGripperAxis3 = 3,      ///< finger 3's axis r3
};

/// Builds a gripper. Errors (their index a GripperPart): a degenerate or
/// non-finite axis, n not perpendicular to a, an approach vector that does
/// not start at the normal vector's start (within tol.distance), a
/// precision of zero or not finite.
Built<GripperModel> makeGripper(const GripperPoints& points, double precision, const Tolerances& tol = {});

/// Where the fingers are relative to the gripper base: the motions, in G,
/// that take each finger from its drawn (open) position to its current one.
struct FingerTransforms {
  Eigen::Isometry3d finger2 = Eigen::Isometry3d::Identity();  ///< +φ about r2
  Eigen::Isometry3d finger3 = Eigen::Isometry3d::Identity();  ///< +φ about r3
};

/// The finger motions at gripper encoder count `encoder` (φ = precision × encoder).
FingerTransforms fingerTransforms(const GripperModel& gripper, double encoder);

/// F_world_G: the gripper's design coordinates in the world, given the
/// robot's end-effector frame F_world_E (toolPose). A point p drawn on
/// finger 2 is then at F_world_G * finger2 * p.
Eigen::Isometry3d gripperPlacement(const Eigen::Isometry3d& F_world_E, const GripperModel& gripper);

}  // namespace rs::kinematics
