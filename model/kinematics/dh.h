// The Denavit–Hartenberg table: one row per joint, as in the paper's TABLE
// command (Fig. 6: AXIS θ α a d Home), and the matrix A_i each row stands for.
//
// D-H convention: standard (distal), as in the paper's matrix. Joint i moves
// about (revolute) or along (prismatic) z_{i-1}, and
//
//   A_i = F_{i-1}_i = Rotz(θ_i) · Transz(d_i) · Transx(a_i) · Rotx(α_i)
//
//       = | cosθ  -cosα sinθ   sinα sinθ   a cosθ |
//         | sinθ   cosα cosθ  -sinα cosθ   a sinθ |
//         |  0       sinα        cosα        d    |
//         |  0        0           0          1    |
//
//   θ_i  angle about z_{i-1} from x_{i-1} to x_i   (the variable of a revolute joint)
//   d_i  distance along z_{i-1} from o_{i-1} to where x_i meets z_{i-1}
//                                                    (the variable of a prismatic joint)
//   a_i  distance along x_i from z_{i-1} to o_i
//   α_i  angle about x_i from z_{i-1} to z_i
//
// Angles are in degrees, normalised to (-180, 180]; lengths in the
// description's units. A joint variable q is θ_i (degrees) for a revolute
// joint and d_i (length units) for a prismatic one.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace rs::kinematics {

enum class JointType : std::uint8_t { Revolute, Prismatic };

/// "revolute" or "prismatic".
std::string_view jointTypeName(JointType type);

/// One row of the D-H table; θ and d are their values at the home position.
struct DhRow {
  JointType type = JointType::Revolute;
  double theta = 0.0;  ///< degrees, at home
  double alpha = 0.0;  ///< degrees
  double a = 0.0;      ///< length units
  double d = 0.0;      ///< length units, at home

  /// The joint variable at home: θ for a revolute joint, d for a prismatic one.
  double home() const { return type == JointType::Revolute ? theta : d; }
  bool operator==(const DhRow&) const = default;
};

/// A_i for `row` with its joint variable set to `q` (θ in degrees for a
/// revolute joint, d for a prismatic one): the frame of link i in link i-1.
Eigen::Isometry3d dhTransform(const DhRow& row, double q);

/// The home frames F_0..F_n of a table, given the base frame F_0 in any
/// coordinates: F_i = F_{i-1} · A_i(home). The inverse of deriveDh.
std::vector<Eigen::Isometry3d> framesFromDh(const Eigen::Isometry3d& F_0, std::span<const DhRow> table);

}  // namespace rs::kinematics
