// Forward kinematics (Pinocchio-style free functions on model + data): the
// pose of every link frame from the joint values, and the transformation
// matrices of the paper's MATRIX command.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <span>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/chain_model.h"

namespace rs::kinematics {

/// Fills data.A[i] = A_i(q_i) and data.F_0_i[i] = A_1···A_i for i = 1..n.
/// q holds θ in degrees (revolute) or d in length units (prismatic), one
/// per joint. No allocation. Returns false, leaving data untouched, when
/// q.size() != n or `data` was not made for a model of this size.
bool forwardKinematics(const ChainModel& model, ChainData& data, std::span<const double> q);

/// The tool centre point's position in frame 0 (F_0_n's origin) were joint
/// `i` (0-based) at `value` and every other joint as in the last
/// forwardKinematics on `data`: the products forwardKinematics would make,
/// so the same bits, without redoing the joints before i (the straight-line
/// planner asks this of each joint at every knot). `data` is left as it is.
Eigen::Vector3d positionWithJoint(const ChainModel& model, const ChainData& data, std::size_t i, double value);

/// T_j^i: the matrix taking coordinates in frame j to frame i (F_i_j), from
/// the last forwardKinematics: A_{i+1}···A_j for i < j, the identity for
/// i = j, the inverse of T_i^j for i > j. Empty when i or j is not in 0..n.
std::optional<Eigen::Isometry3d> transform(const ChainModel& model, const ChainData& data, int i, int j);

/// F_world_tool: the end-effector frame (tool centre point, x = n, z = a)
/// in the world, from the last forwardKinematics: frame n, or the chain's
/// tool frame in it (ChainModel::withTool).
Eigen::Isometry3d toolPose(const ChainModel& model, const ChainData& data);

}  // namespace rs::kinematics
