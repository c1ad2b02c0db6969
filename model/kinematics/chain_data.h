// The chain workspace (Pinocchio's Data): every buffer the algorithms write,
// allocated once from a model so that forward kinematics never allocates.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "model/kinematics/chain_model.h"

namespace rs::kinematics {

/// Results of the last forwardKinematics call on one model. Both vectors
/// have n+1 entries, indexed by joint/frame number; entry 0 is the identity.
struct ChainData {
  /// Sized for `model` and filled with its home pose.
  explicit ChainData(const ChainModel& model);

  std::vector<Eigen::Isometry3d> A;      ///< A[i] = F_{i-1}_i, the D-H matrix of joint i
  std::vector<Eigen::Isometry3d> F_0_i;  ///< F_0_i[i]: frame i in the base frame
};

}  // namespace rs::kinematics
