// The chain of a URDF tree: the path from the root link to the tip, with
// fixed joints folded into the links they join and every other link drawn
// with the chain link it hangs from (docs/models.md, "Reading URDF").
// Frames here are in the robot's design coordinates: millimetres, y up
// (urdf_units.h of this file's functions: designFrame, designPoint).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include <urdf_model/model.h>

#include "model/kinematics/dh.h"

namespace rs::urdf {

/// URDF's metres with z up to a robotsim design's millimetres with y up:
/// the turn Rx(-90°) (x stays, URDF y becomes -z, URDF z becomes y), whose
/// matrix holds only 0 and ±1, so it rounds nothing; then × 1000.
Eigen::Vector3d designPoint(const Eigen::Vector3d& metres);
Eigen::Vector3d designDirection(const Eigen::Vector3d& direction);
Eigen::Isometry3d designFrame(const Eigen::Isometry3d& F_root_x);

/// A URDF pose (origin xyz, rpy as urdfdom's quaternion) as a transform.
Eigen::Isometry3d transformOf(const ::urdf::Pose& pose);

/// One moving joint of the chain.
struct ChainJoint {
  std::string name;
  kinematics::JointType type = kinematics::JointType::Revolute;
  bool continuous = false;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< a point of its axis at home (design)
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  ///< the axis, unit (design)
  /// The home frames of the link it moves (its URDF child) and of the link
  /// it hangs from (its URDF parent); design.
  Eigen::Isometry3d F_design_child = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d F_design_parent = Eigen::Isometry3d::Identity();
  bool hasLimits = false;
  double lower = 0, upper = 0, velocity = 0;  ///< URDF units: radians or metres (per second)
  /// Set on a joint whose successor mimics it as COUPLING expresses.
  bool coupling = false;
  /// A joint that mimics its predecessor has no motion of its own.
  bool mimics = false;
};

/// A URDF link and its home frame, drawn as part of a robotsim link.
struct ChainLink {
  ::urdf::LinkConstSharedPtr link;
  Eigen::Isometry3d F_root_link = Eigen::Isometry3d::Identity();  ///< metres, z up
};

/// What is wrong, about which element (a joint's or a link's name): the
/// reader finds its XML line.
struct ChainProblem {
  bool joint = true;
  std::string name;
  std::string message;
  std::string hint;
  bool warning = false;
};

struct UrdfChain {
  std::string root, tip;
  std::vector<ChainJoint> joints;                ///< joints 1..n in order
  std::vector<std::vector<ChainLink>> links;     ///< robotsim links 0..n: the URDF links each draws
  Eigen::Isometry3d F_design_root = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d F_design_tip = Eigen::Isometry3d::Identity();
  std::vector<ChainProblem> problems;            ///< errors (the chain is then unusable) and warnings
  bool ok() const;
};

/// The chain from the model's root to `tip` (empty: the one leaf the
/// moving joints lead to), each joint at its home value (0; a mimic joint
/// at its offset).
UrdfChain extractChain(const ::urdf::ModelInterface& model, const std::string& tip);

}  // namespace rs::urdf
