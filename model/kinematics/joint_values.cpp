#include "model/kinematics/joint_values.h"

namespace rs::kinematics {

namespace {

template <class Count>
bool fromEncoders(const ChainModel& model, std::span<const Count> encoders, std::span<double> q) {
  const auto n = static_cast<std::size_t>(model.size());
  if (q.size() != n || encoders.size() < static_cast<std::size_t>(model.encoderCount())) return false;
  for (std::size_t k = 0; k < n; ++k) {
    const Joint& joint = model.joints()[k];
    q[k] = joint.home + joint.precision * static_cast<double>(encoders[static_cast<std::size_t>(joint.encoder)]);
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Joint& joint = model.joints()[k];
    if (joint.coupling) q[k + 1] -= q[k] - joint.home;
  }
  return true;
}

}  // namespace

bool jointValuesFromEncoders(const ChainModel& model, std::span<const double> encoders, std::span<double> q) {
  return fromEncoders(model, encoders, q);
}

bool jointValuesFromEncoders(const ChainModel& model, std::span<const std::int32_t> encoders, std::span<double> q) {
  return fromEncoders(model, encoders, q);
}

}  // namespace rs::kinematics
