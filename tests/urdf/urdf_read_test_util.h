// Helpers of the URDF reader's tests: the files of tests/urdf/data_read,
// and a forward kinematics of a URDF file computed here from its joint
// origins and axes alone (urdfdom's model, Eigen), independent of the
// reader's chain and D-H code.
#pragma once

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <urdf_parser/urdf_parser.h>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"
#include "model/urdf/urdf_read.h"

namespace urdftest {

inline std::filesystem::path dataRead(const std::string& name) {
  return std::filesystem::path(ROBOTSIM_SOURCE_DIR) / "tests/urdf/data_read" / name;
}

inline rs::urdf::UrdfRead readData(const std::string& name, const rs::urdf::UrdfOptions& options = {}) {
  return rs::urdf::readUrdfFile(dataRead(name), options);
}

/// The URDF's own forward kinematics: root to tip, the moving joints at
/// `q` (radians or metres, in chain order; a mimic joint follows its
/// master), as a pose in the root link (metres, z up).
struct UrdfFk {
  std::vector<urdf::JointConstSharedPtr> path;  // root to tip, every joint
  std::vector<std::string> moving;              // the moving joints' names, in order

  UrdfFk(const std::filesystem::path& file, const std::string& tip) {
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDFFile(file.string());
    REQUIRE(model);
    keep = model;
    for (urdf::LinkConstSharedPtr l = model->getLink(tip); l && l->parent_joint; l = l->getParent())
      path.insert(path.begin(), l->parent_joint);
    for (const auto& j : path)
      if (j->type != urdf::Joint::FIXED) moving.push_back(j->name);
  }

  Eigen::Isometry3d pose(const std::vector<double>& q) const {
    Eigen::Isometry3d F = Eigen::Isometry3d::Identity();
    for (const auto& j : path) {
      const urdf::Pose& o = j->parent_to_joint_origin_transform;
      Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
      origin.linear() = Eigen::Quaterniond(o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z).toRotationMatrix();
      origin.translation() = Eigen::Vector3d(o.position.x, o.position.y, o.position.z);
      F = F * origin;
      if (j->type == urdf::Joint::FIXED) continue;
      double v = valueOf(j->name, q);
      if (j->mimic) v = j->mimic->multiplier * valueOf(j->mimic->joint_name, q) + j->mimic->offset;
      const Eigen::Vector3d axis = Eigen::Vector3d(j->axis.x, j->axis.y, j->axis.z).normalized();
      Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
      if (j->type == urdf::Joint::PRISMATIC) m.translation() = v * axis;
      else m.linear() = Eigen::AngleAxisd(v, axis).toRotationMatrix();
      F = F * m;
    }
    return F;
  }

 private:
  double valueOf(const std::string& name, const std::vector<double>& q) const {
    for (std::size_t i = 0; i < moving.size(); ++i)
      if (moving[i] == name) return q[i];
    return 0.0;
  }
  urdf::ModelInterfaceSharedPtr keep;
};

/// A root-link pose (metres, z up) in design coordinates (millimetres, y
/// up): x stays, z becomes y, y becomes -z; written out here, not taken
/// from the reader.
inline Eigen::Isometry3d toDesign(const Eigen::Isometry3d& F) {
  Eigen::Matrix3d M;
  M << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = M * F.linear();
  out.translation() = 1000.0 * (M * F.translation());
  return out;
}

}  // namespace urdftest
