// Helpers shared by the kinematics tests.
#pragma once

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/chain_model.h"
#include "model/kinematics/frame.h"

namespace kintest {

using Eigen::Isometry3d;
using Eigen::Vector3d;

/// Joint types, short as the tables write them.
inline constexpr rs::kinematics::JointType R = rs::kinematics::JointType::Revolute;
inline constexpr rs::kinematics::JointType P = rs::kinematics::JointType::Prismatic;

/// The standard library's robot descriptions, in name order.
inline std::vector<std::filesystem::path> libraryRobots() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(ROBOTSIM_SOURCE_DIR) / "stdlib/robots"))
    if (e.path().extension() == ".rsd") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// The frame with origin `o`, x along `x`, z along `z` (global coordinates),
/// entered the description's way: x axis from o to o+100x, z from o to o+100z.
inline Isometry3d frameAt(const Vector3d& o, const Vector3d& x, const Vector3d& z) {
  auto frame = rs::kinematics::frameFromPoints(o, o + 100.0 * x, o + 100.0 * z);
  REQUIRE(frame.errors.empty());
  return *frame.value;
}

/// Largest absolute difference between two transforms' matrices.
inline double maxDiff(const Isometry3d& a, const Isometry3d& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

/// A model from frames with default drives (precision 1, own encoder, no coupling).
inline rs::kinematics::ChainModel modelFromFrames(const std::vector<Isometry3d>& frames,
                                                  const std::vector<rs::kinematics::JointType>& types,
                                                  std::vector<rs::kinematics::JointDrive> drives = {}) {
  if (drives.empty()) drives.resize(types.size());
  auto model = rs::kinematics::ChainModel::fromFrames(frames, types, drives);
  for (const auto& e : model.errors) INFO(e.message);
  REQUIRE(model.errors.empty());
  return *model.value;
}

}  // namespace kintest
