// From motor encoder counts to joint values: the paper's precision and
// next-joint coupling.
#pragma once

#include <cstdint>
#include <span>

#include "model/kinematics/chain_model.h"

namespace rs::kinematics {

/// Joint values q (θ in degrees, d in length units) from motor encoder
/// counts, without allocating:
///
///   1. q_i = home_i + precision_i × encoders[encoder_i]      for i = 1..n
///   2. for n = 1..N-1 in order, when joint n has coupling ON:
///        q_{n+1} -= (q_n − home_n)
///
/// so joint n+1 cancels joint n's motion away from home. Step 2 runs in
/// joint order on the already coupled values: with coupling ON for joints 2
/// and 3, joint 4 cancels joint 3's whole motion, which includes joint 3's
/// cancelling of joint 2.
///
/// Returns false, leaving q untouched, when q.size() != n or `encoders`
/// has fewer than model.encoderCount() entries (longer is fine: a motor
/// table holds the gripper after the arm).
bool jointValuesFromEncoders(const ChainModel& model, std::span<const double> encoders, std::span<double> q);
/// The same for whole encoder counts, as the Machine interface reports them.
bool jointValuesFromEncoders(const ChainModel& model, std::span<const std::int32_t> encoders, std::span<double> q);

}  // namespace rs::kinematics
