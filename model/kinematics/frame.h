// Frames: the link coordinate frames of a robot, built from the points a
// description gives ("x axis from P to Q, z axis from P to R").
//
// Frame-naming convention (as in Orocos KDL):
//
//   F_A_B is frame B expressed in frame A: the Eigen::Isometry3d whose
//   rotation columns are B's x, y, z axes and whose translation is B's
//   origin, all in A's coordinates. It maps coordinates in B to coordinates
//   in A, p_A = F_A_B * p_B, so frames chain left to right:
//   F_A_C = F_A_B * F_B_C, and F_B_A = F_A_B.inverse().
//
// Frame names used in this directory:
//   world  the workcell.
//   0..n   the D-H link frames: 0 is the base link, n the end effector
//          (the gripper's normal n is its x axis, approach a its z axis,
//          and its origin is the tool centre point).
//   G      a gripper's design coordinates (where its three links are drawn).
//   E      the end-effector frame as drawn in G (the n and a vectors).
// A description gives every link frame in its own global (design)
// coordinates at the home position; the workcell places that drawing in the
// world, which yields F_world_0. The D-H matrix A_i is F_{i-1}_i.
#pragma once

#include <Eigen/Geometry>
#include <string_view>

#include "model/kinematics/error.h"

namespace rs::kinematics {

/// A directed line: a point on it and a unit direction.
struct Line {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

/// What the axes are called in messages ("x axis", "normal vector", ...).
struct AxisNames {
  std::string_view x = "x axis";
  std::string_view z = "z axis";
};

/// The line from `from` through `to`, direction normalised. Errors: a
/// coordinate that is not finite, or the two points closer than
/// `tol.length` ("<name> has zero length"). Errors carry `index`.
Built<Line> lineThrough(const Eigen::Vector3d& from, const Eigen::Vector3d& to, std::string_view name,
                         const Tolerances& tol = {}, int index = -1);

/// The frame with origin `origin`, x axis along `xDirection` and z axis
/// along `zDirection` (y = z × x completes a right-handed frame). Both
/// directions are normalised; z is then made exactly perpendicular to x.
/// Errors (each carrying `index`): a coordinate that is not finite, an axis
/// shorter than `tol.length`, or |cos(x, z)| > `tol.cosine`.
Built<Eigen::Isometry3d> frameFromAxes(const Eigen::Vector3d& origin, const Eigen::Vector3d& xDirection,
                                        const Eigen::Vector3d& zDirection, const Tolerances& tol = {}, int index = -1,
                                        AxisNames names = {});

/// The frame given the description's way: x axis from `p` to `q`, z axis
/// from `p` to `r` (so `p` is the origin). Same checks as frameFromAxes.
Built<Eigen::Isometry3d> frameFromPoints(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r,
                                          const Tolerances& tol = {}, int index = -1);

/// The rigid motion that turns points by `degrees` about `line`,
/// right-handed about its direction (counter-clockwise seen from its tip).
Eigen::Isometry3d rotationAboutLine(const Line& line, double degrees);

}  // namespace rs::kinematics
