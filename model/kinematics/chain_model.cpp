#include "model/kinematics/chain_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/kinematics/dh_derive.h"
#include "model/kinematics/trig.h"

namespace rs::kinematics {

namespace {

Joint makeJoint(const DhRow& row, const JointDrive& drive, int i) {
  Joint joint;
  joint.dh = row;
  joint.precision = drive.precision;
  joint.encoder = drive.encoder == -1 ? i - 1 : drive.encoder;
  joint.coupling = drive.coupling;
  joint.home = row.home();
  sinCosDegrees(row.alpha, joint.sinAlpha, joint.cosAlpha);
  sinCosDegrees(row.theta, joint.sinTheta, joint.cosTheta);
  return joint;
}

bool finiteRow(const DhRow& row) {
  return std::isfinite(row.theta) && std::isfinite(row.alpha) && std::isfinite(row.a) && std::isfinite(row.d);
}

// Checks one joint on its own (values, precision, encoder index).
void checkJoint(const Joint& joint, int i, std::vector<KinematicsError>& errors) {
  if (!finiteRow(joint.dh)) {
    errors.push_back({ErrorKind::NotFinite, i, fmt::format("joint {} has a D-H value that is not a finite number", i)});
  }
  if (!std::isfinite(joint.precision) || joint.precision == 0.0) {
    errors.push_back({ErrorKind::BadPrecision, i,
                      fmt::format("joint {} has precision {}, but it must be a non-zero number", i, joint.precision)});
  }
  if (joint.encoder < 0) {
    errors.push_back(
        {ErrorKind::BadEncoder, i, fmt::format("joint {} reads encoder {}, but indices start at 0", i, joint.encoder)});
  }
}

// Checks what joints say about each other: shared encoders and coupling.
void checkPairs(std::span<const Joint> joints, std::vector<KinematicsError>& errors) {
  const int n = static_cast<int>(joints.size());
  for (int i = 1; i <= n; ++i) {
    const Joint& joint = joints[static_cast<std::size_t>(i - 1)];
    for (int k = 1; k < i; ++k) {
      if (joints[static_cast<std::size_t>(k - 1)].encoder == joint.encoder && joint.encoder >= 0) {
        errors.push_back({ErrorKind::BadEncoder, i,
                          fmt::format("joint {} reads encoder {}, which joint {} already reads", i, joint.encoder, k)});
      }
    }
    if (!joint.coupling) continue;
    if (i == n) {
      errors.push_back({ErrorKind::BadCoupling, i,
                        fmt::format("joint {} has coupling ON, but there is no joint {} to couple", i, i + 1)});
    } else if (joints[static_cast<std::size_t>(i)].type() != joint.type()) {
      errors.push_back({ErrorKind::BadCoupling, i,
                        fmt::format("joint {} has coupling ON, but joint {} is {} and joint {} is {}: coupled "
                                    "joints must be of the same type",
                                    i, i, jointTypeName(joint.type()), i + 1,
                                    jointTypeName(joints[static_cast<std::size_t>(i)].type()))});
    }
  }
}

}  // namespace

Built<ChainModel> ChainModel::fromDh(const Eigen::Isometry3d& F_world_0, std::span<const DhRow> table,
                                      std::span<const JointDrive> drives) {
  Built<ChainModel> result;
  if (table.size() != drives.size()) {
    result.errors.push_back(
        {ErrorKind::CountMismatch, -1,
         fmt::format("the D-H table has {} rows but {} joint drives are given", table.size(), drives.size())});
    return result;
  }
  if (!F_world_0.matrix().allFinite()) {
    result.errors.push_back({ErrorKind::NotFinite, 0, "the base placement is not a finite transform"});
  }
  ChainModel model;
  model.F_world_0_ = F_world_0;
  model.joints_.reserve(table.size());
  for (std::size_t k = 0; k < table.size(); ++k) {
    const int i = static_cast<int>(k) + 1;
    model.joints_.push_back(makeJoint(table[k], drives[k], i));
    checkJoint(model.joints_.back(), i, result.errors);
    model.encoderCount_ = std::max(model.encoderCount_, model.joints_.back().encoder + 1);
  }
  checkPairs(model.joints_, result.errors);
  if (result.errors.empty()) result.value = std::move(model);
  return result;
}

Built<ChainModel> ChainModel::fromFrames(std::span<const Eigen::Isometry3d> frames, std::span<const JointType> types,
                                          std::span<const JointDrive> drives, const Tolerances& tol) {
  auto table = deriveDh(frames, types, tol);
  if (!table.value) return {std::nullopt, std::move(table.errors)};
  return fromDh(frames[0], *table.value, drives);
}

ChainModel ChainModel::placedAt(const Eigen::Isometry3d& F_world_0) const {
  ChainModel placed = *this;
  placed.F_world_0_ = F_world_0;
  return placed;
}

ChainModel ChainModel::withTool(const Eigen::Isometry3d& F_n_tool) const {
  ChainModel tooled = *this;
  tooled.F_n_tool_ = F_n_tool;
  tooled.hasTool_ = !F_n_tool.matrix().isIdentity(0.0);
  return tooled;
}

std::vector<DhRow> ChainModel::table() const {
  std::vector<DhRow> rows;
  rows.reserve(joints_.size());
  for (const Joint& joint : joints_) rows.push_back(joint.dh);
  return rows;
}

}  // namespace rs::kinematics
