// The one place a problem of the kinematics core (a frame, chain or gripper
// that cannot be built: kinematics::KinematicsError) or of the pose solver
// (a tool pose with no answer: workcell::PoseProblem, made from
// kinematics::IkError) becomes a Diagnostic. The core knows what a problem
// is about (a frame's, a joint's or a gripper vector's index, a part of the
// pose); the reader that asked knows where that was written: it says so in
// KinematicsPlaces, and this function picks the place and the words. Here,
// in the compiler's lowest room, because the program compiler (points
// written as poses) and the description reader above it both need it.
#pragma once

#include <functional>
#include <string>
#include <variant>

#include "diag/diagnostic.h"
#include "model/kinematics/error.h"
#include "model/workcell/pose_solver.h"

namespace rs::compiler {

/// Where the reader wrote each thing a problem can be about. A function
/// left empty, or answering line 0, has no place of its own: the next one
/// down the list is asked, and `whole` answers last.
struct KinematicsPlaces {
  std::string file;
  /// What the message is about, before its colon: "robot 'arm'",
  /// "gripper 'g'", "link 'base'", "point P1".
  std::string subject;
  /// The construct as a whole (the robot, gripper or link line, the pose's AT).
  diag::Pos whole;
  /// A joint error's (bad precision, bad coupling) joint, 1..n.
  std::function<diag::Pos(int joint)> joint = {};
  /// A gripper error's vector (kinematics::GripperPart).
  std::function<diag::Pos(int part)> gripperPart = {};
  /// Any other error's frame, 0..n (-1: the whole chain).
  std::function<diag::Pos(int frame)> frame = {};
  /// The part of a pose a pose problem is about.
  std::function<diag::Pos(workcell::PoseField field)> poseField = {};
};

using KinematicsProblem = std::variant<kinematics::KinematicsError, workcell::PoseProblem>;

/// "SUBJECT: MESSAGE" at the place the problem is about, with the pose
/// solver's hint and code.
diag::Diagnostic kinematicsDiagnostic(const KinematicsProblem& problem, const KinematicsPlaces& places);

}  // namespace rs::compiler
