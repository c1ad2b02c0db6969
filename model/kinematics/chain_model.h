// The chain model: everything about a robot arm that does not change while
// it moves (Pinocchio's Model). Built once, validated, then read-only; the
// per-motion buffers live in ChainData.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "model/kinematics/dh.h"
#include "model/kinematics/error.h"

namespace rs::kinematics {

/// How a joint is driven: its motor and the paper's JOINT information.
struct JointDrive {
  /// Degrees (revolute) or length units (prismatic) per encoder count;
  /// non-zero, and negative when the motor counts the other way.
  double precision = 1.0;
  /// Index of the joint's motor in the encoder vector; -1 means "the joint's
  /// own position": joint i reads encoder i-1.
  int encoder = -1;
  /// Next-joint coupling: joint i+1 moves to cancel this joint's motion.
  bool coupling = false;
};

/// One joint of a chain model, with values precomputed for the hot path.
struct Joint {
  DhRow dh;                ///< the D-H row (its type is the joint's type)
  double precision = 1.0;  ///< see JointDrive
  int encoder = 0;         ///< resolved encoder index, >= 0
  bool coupling = false;   ///< see JointDrive
  double home = 0.0;       ///< dh.home()
  double cosAlpha = 1.0, sinAlpha = 0.0;
  double cosTheta = 1.0, sinTheta = 0.0;  ///< of the home θ (used by prismatic joints)

  JointType type() const { return dh.type; }
};

/// An immutable serial chain: joints 1..n and the base placement F_world_0.
class ChainModel {
 public:
  /// Builds a model from a D-H table and one drive per row. Errors: counts
  /// that differ, non-finite table values, a bad precision, an encoder index
  /// that is negative or shared, coupling ON for the last joint or between
  /// joints of different types (degrees cannot cancel length units).
  static Built<ChainModel> fromDh(const Eigen::Isometry3d& F_world_0, std::span<const DhRow> table,
                                   std::span<const JointDrive> drives);

  /// Derives the table from home frames F_0..F_n (deriveDh) and builds the
  /// model with F_world_0 = frames[0], i.e. the frames' coordinates are the
  /// world's. Reports the errors of both steps.
  static Built<ChainModel> fromFrames(std::span<const Eigen::Isometry3d> frames, std::span<const JointType> types,
                                       std::span<const JointDrive> drives, const Tolerances& tol = {});

  /// The same chain with its base placed at `F_world_0` (a workcell's AT/ROTATE).
  ChainModel placedAt(const Eigen::Isometry3d& F_world_0) const;
  /// The same chain with a tool frame: the tool centre point's frame in
  /// frame n, for a tool that no D-H frame can be (a URDF arm's tip link,
  /// a description's TOOL). Identity by default: the tool is frame n.
  ChainModel withTool(const Eigen::Isometry3d& F_n_tool) const;

  /// Number of joints n (frames are 0..n).
  int size() const { return static_cast<int>(joints_.size()); }
  /// Joint i, 1 <= i <= n.
  const Joint& joint(int i) const { return joints_[static_cast<std::size_t>(i - 1)]; }
  std::span<const Joint> joints() const { return joints_; }
  /// The base frame (frame 0) in the world.
  const Eigen::Isometry3d& F_world_0() const { return F_world_0_; }
  /// The tool frame in frame n (withTool); identity unless one was given.
  const Eigen::Isometry3d& F_n_tool() const { return F_n_tool_; }
  bool hasTool() const { return hasTool_; }
  /// Smallest encoder vector the model can read: 1 + the largest index.
  int encoderCount() const { return encoderCount_; }
  /// The D-H table (the paper's TABLE).
  std::vector<DhRow> table() const;

 private:
  ChainModel() = default;
  std::vector<Joint> joints_;
  Eigen::Isometry3d F_world_0_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d F_n_tool_ = Eigen::Isometry3d::Identity();
  bool hasTool_ = false;
  int encoderCount_ = 0;
};

}  // namespace rs::kinematics
