// A placed robot's encoder counts for a wanted tool pose: inverse
// kinematics (kinematics/ik.h) plus everything that makes its answer a
// point a program can use. What a target does not write is taken from the
// previous point; among the solutions the one whose move from the previous
// point is quickest is chosen (docs/language.md, "Points as tool poses").
// Shared by the compiler (points written as poses) and `robotsim ik`.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/kinematics/ik.h"
#include "model/workcell/model.h"

namespace rs::workcell {

/// A tool pose as a program writes it.
struct PoseRequest {
  bool robotFrame = false;  ///< the robot's design coordinates; else the world (the cell's)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< the tool centre point
  std::optional<Eigen::Vector3d> approach, normal;     ///< the tool's a (z) and n (x) axes
  std::optional<std::int32_t> grip;                    ///< the gripper motor's encoder count
  /// Only this configuration (kinematics::IkConfig bits, one of
  /// InverseKinematics::configurations()), solved alone; unset: every
  /// solution, the quickest move in range chosen.
  std::optional<std::uint8_t> configuration;
  /// Hints name the orientation as `robotsim ik`'s options (--approach
  /// X,Y,Z --normal X,Y,Z), not as a program writes it (APPROACH X Y Z).
  bool optionWords = false;
};

/// Which part of a request a problem is about (where a message points).
enum class PoseField : std::uint8_t { Position, Approach, Normal, Grip };

struct PoseProblem {
  PoseField field = PoseField::Position;
  std::string message;  ///< a sentence without a position
  std::string hint;
  /// A stable name: pose-vector, pose-unreachable, pose-singular,
  /// pose-orientation, pose-out-of-range, pose-grip (a literal: never dangles).
  std::string_view code;
};

struct PoseResult {
  std::vector<std::int32_t> encoders;  ///< one per motor: arm joints, then the gripper
  std::vector<double> q;               ///< the joint values chosen (before rounding to counts)
  std::uint8_t config = 0;             ///< kinematics::IkConfig bits of the chosen solution
  int solutions = 0;                   ///< how many solutions the pose has (before ranges)
  int inRange = 0;                     ///< how many of them fit the motors' ranges
  double rounding = 0;                 ///< how far rounding to encoder counts moves the tool centre point
  /// solveAnyOrientation: how many free orientations were tried besides the
  /// kept one (0: the kept one did), and how far the chosen one is turned
  /// from it (degrees).
  int orientationsTried = 0;
  double turned = 0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< the tool's n, s, a reached, in the request's coordinates
  std::optional<PoseProblem> problem;  ///< set when there is no answer
  bool ok() const { return !problem.has_value(); }
};

class PoseSolver {
 public:
  /// `robot` must have a chain and outlive the solver.
  explicit PoseSolver(const PlacedRobot& robot);

  /// Encoder counts for `request`; `reference` holds the previous point's
  /// counts (one per motor; the home position, all 0, for the first).
  /// `referenceQ`, when the previous point was itself a pose, is its exact
  /// joint values (PoseResult::q): what is kept is then kept exactly, not
  /// as rounded to whole counts, so it does not drift from point to point.
  PoseResult solve(const PoseRequest& request, std::span<const std::int32_t> reference,
                   std::span<const double> referenceQ = {}) const;

  /// As solve(), but a request with a position only (no approach, no
  /// normal) whose kept orientation does not reach it (out of reach, near a
  /// singular pose, a motor out of range) tries every orientation the arm
  /// leaves free before it refuses, nearest the kept one first
  /// (pose_orientation_search.cpp): the heading of a SCARA with a roll
  /// joint, the pitch of a five-axis arm, any turn of a six-axis wrist.
  PoseResult solveAnyOrientation(const PoseRequest& request, std::span<const std::int32_t> reference) const;

  const kinematics::InverseKinematics& ik() const { return ik_; }
  /// How many motors a point has (arm joints, then the gripper if any).
  std::size_t motorCount() const { return robot_.robot.joints.size() + (robot_.robot.hasGripper ? 1 : 0); }
  /// F_world_0 or F_design_0: frame 0 in the request's coordinates.
  const Eigen::Isometry3d& frame0(bool robotFrame) const { return robotFrame ? F_design_0_ : F_world_0_; }

 private:
  // What is kept from the previous point: its joint values, its counts, its tool's rotation in frame 0.
  struct Kept {
    std::vector<double> refQ, refEncoders;
    Eigen::Matrix3d R_ref = Eigen::Matrix3d::Identity();
  };
  Kept kept(std::span<const std::int32_t> reference, std::span<const double> referenceQ) const;
  std::optional<PoseProblem> targetOf(const PoseRequest& request, const Kept& k, kinematics::ToolTarget& target) const;
  PoseResult solveTarget(const PoseRequest& request, const kinematics::ToolTarget& target, const Kept& k,
                         std::span<const std::int32_t> reference) const;
  /// "APPROACH x y z NORMAL x y z" (or the options) of a rotation in frame 0.
  std::string orientationWords(const PoseRequest& request, const Eigen::Matrix3d& R_0) const;

  const PlacedRobot& robot_;
  kinematics::InverseKinematics ik_;
  Eigen::Isometry3d F_world_0_, F_design_0_;
};

}  // namespace rs::workcell
