// D-H frames from a chain's joint axes: what lets robotsim print the D-H
// table of any URDF arm (docs/models.md, "Reading URDF", "The D-H
// frames"). robotsim's convention (model/kinematics/dh.h): joint i turns
// about or slides along z_{i-1}, so z_{i-1} is joint i's axis, and x_i is
// the common normal of z_{i-1} and z_i. Where D-H leaves a choice, this
// file makes it, the same way every time:
//
//  - frames 1..n-1, first: where the link joint i moves has a home frame
//    that is already a D-H frame of joint i (its z along the joint's axis,
//    its origin on it: the joint turns the link about the link's own z; its
//    x perpendicular to z_i and meeting it), x_i is that frame's x and o_i
//    where its x meets z_i. robotsim's export writes every link so, so an
//    exported robot reads back to its own table; a URDF whose link frames
//    are not D-H frames (the joint about the link's y, or x missing z_i)
//    gets the choices below;
//  - frame 0: the frame of the link joint 1 hangs from, where its z is
//    along joint 1's axis (either sense) and its origin on it (with z_0
//    the axis; the export's base_link or link_0); otherwise on joint 1's
//    axis at the foot of the root link's origin, x_0 the root's x made
//    perpendicular to z_0 (the root's y if x is along the axis);
//  - skew axes: o_i at the foot of the common normal on z_i, x_i from z_{i-1}
//    towards z_i (so a_i > 0);
//  - intersecting axes: o_i at the crossing, x_i = z_{i-1} × z_i (so a_i = 0,
//    0 < α_i < 180);
//  - parallel axes: the common normal through o_{i-1} (so d_i = 0, the
//    library's convention), x_i from z_{i-1} towards z_i;
//  - collinear axes: o_i = o_{i-1}, x_i = x_{i-1} (θ_i = d_i = a_i = 0 at home);
//  - frame n: the tip link's frame where it obeys the D-H rules (x_n
//    perpendicular to and meeting z_{n-1}); otherwise o_n at the foot of the
//    tip's origin on z_{n-1}, z_n = z_{n-1}, x_n = x_{n-1}, and the tip is
//    the tool frame in frame n.
//
// A prismatic joint's axis is a direction only; its line is taken through
// the URDF joint's origin.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "model/kinematics/dh.h"

namespace rs::urdf {

/// How z_{i-1} and z_i lie: which D-H case row i is.
enum class AxisRelation { Collinear, Parallel, Intersecting, Skew };

std::string_view relationName(AxisRelation r);

struct DhAxis {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit
  /// The home frame of the link this joint moves (its URDF child), where
  /// the file gives one: frame i is taken from it when it already is a D-H
  /// frame of the joint (see the file's comment).
  std::optional<Eigen::Isometry3d> link;
  /// The home frame of the link it hangs from (its URDF parent): frame 0 is
  /// taken from joint 1's where that already is a D-H frame 0.
  std::optional<Eigen::Isometry3d> parent;
};

struct DhFrames {
  std::vector<Eigen::Isometry3d> frames;   ///< F_0..F_n, in the axes' coordinates
  std::optional<Eigen::Isometry3d> tool;   ///< the tip, where it is not frame n
  std::vector<AxisRelation> relations;     ///< row i (1..n-1) at i-1: z_{i-1} to z_i
};

/// Lines closer than this (the axes' length unit) meet; directions whose
/// cross product is shorter than kParallel are parallel.
inline constexpr double kMeet = 1e-7;
inline constexpr double kParallel = 1e-9;

/// The D-H frames of joints whose axes at home are `axes` (1..n, n >= 1),
/// for a robot whose root and tip frames are given in the same coordinates.
DhFrames dhFramesFromAxes(std::span<const DhAxis> axes, const Eigen::Isometry3d& F_root,
                          const Eigen::Isometry3d& F_tip);

}  // namespace rs::urdf
