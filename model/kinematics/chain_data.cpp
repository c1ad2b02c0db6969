#include "model/kinematics/chain_data.h"

#include "model/kinematics/forward_kinematics.h"

namespace rs::kinematics {

ChainData::ChainData(const ChainModel& model)
    : A(static_cast<std::size_t>(model.size()) + 1, Eigen::Isometry3d::Identity()),
      F_0_i(static_cast<std::size_t>(model.size()) + 1, Eigen::Isometry3d::Identity()) {
  std::vector<double> home;
  home.reserve(static_cast<std::size_t>(model.size()));
  for (const Joint& joint : model.joints()) home.push_back(joint.home);
  [[maybe_unused]] const bool ok = forwardKinematics(model, *this, home);
}

}  // namespace rs::kinematics
