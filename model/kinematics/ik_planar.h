// A planar run: joints k..m of a chain whose axes z_{k-1} .. z_{m-1} are
// all parallel (α_k .. α_{m-1} each 0 or 180). Seen along their common
// axis, the run is a planar linkage: the SCARA's whole arm, the upper arm
// and forearm of an articulated arm. The closed forms of ik_*.cpp stand on
// it.
//
// Expanding A_k ··· A_m Q (Q a point fixed in frame m), a mirror
// Rx(180) = diag(1, -1, -1) commutes with Rz(θ) as Rz(-θ), so, in frame
// k-1 coordinates (x, y in the plane, z along the axes):
//
//   plane:   P = Σ_i Rz(ψ_i) u_i,    ψ_i = Σ_{j=k..i} σ_j θ_j
//   along:   h = Σ_i σ_i d_i + σ_m Q'_z
//
// with σ_k = 1, σ_{j+1} = σ_j cos α_j (±1), u_i = (a_i, 0) for i < m,
// u_m = (a_m + Q'_x, σ_m Q'_y), Q' = Rx(α_m) Q. Grouping the terms by the
// revolute joints r_0 < r_1 < ... of the run:
//
//   P = C + Rz(Φ_0) V_0 + Rz(Φ_1) V_1 (+ Rz(Φ_2) V_2),
//   Φ_g = Σ_{l<=g} σ_{r_l} θ_{r_l},  ψ_m = Φ_last + c_m,
//
// where C and each V_g are constant vectors (a prismatic joint's θ is
// fixed) and c_m the sum of the fixed angles.
#pragma once

#include <Eigen/Core>
#include <array>

#include "model/kinematics/chain_model.h"

namespace rs::kinematics {

struct PlanarRun {
  int first = 0, last = 0;            ///< joints k and m (1-based)
  int revolutes = 0;                  ///< revolute joints in the run (2 or 3)
  std::array<int, 3> revolute{};      ///< their numbers
  std::array<double, 3> sign{};       ///< σ of each
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  ///< C
  std::array<Eigen::Vector2d, 3> link{};             ///< V_0, V_1, V_2
  double fixedHeading = 0;            ///< c_m, radians
  double along = 0;                   ///< h with every prismatic d at 0
  int prismatic = 0;                  ///< the run's prismatic joint (0: none)
  double prismaticSign = 0;           ///< its σ
};

/// The run of joints first..last of `model` carrying the point `Q` of frame
/// `last`; false when an axis is not parallel or the run has not 2..3
/// revolute joints with links of non-zero length, or more than one
/// prismatic joint.
bool makePlanarRun(const ChainModel& model, int first, int last, const Eigen::Vector3d& Q, PlanarRun& run);

/// Two-link planar problem W = Rz(Φ_0) V_0 + Rz(Φ_1) V_1: both solutions
/// (the elbow one way and the other) as (Φ_0, Φ_1) in radians, or false
/// with `miss`, how far W is outside the annulus the links reach (> 0).
/// `sinElbow` gets |sin| of the angle between the two links' directions,
/// which is 0 at the stretched and folded singular poses. With `only` 0
/// or 1, only phis[only] is worked out (the same bits as with both).
bool solveTwoLink(const Eigen::Vector2d& W, const Eigen::Vector2d& V0, const Eigen::Vector2d& V1,
                  std::array<Eigen::Vector2d, 2>& phis, double& miss, double& sinElbow, int only = -1);

/// A 2-D rotation by `angle` radians applied to v.
inline Eigen::Vector2d rotate2(double angle, const Eigen::Vector2d& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace rs::kinematics
