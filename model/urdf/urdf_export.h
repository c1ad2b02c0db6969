// A robot written as URDF (the Robot Description Format of ROS): links with
// their geometry as boxes, joints with limits and velocities from the
// motors, the gripper's fingers on their own branches, COUPLING as mimic
// joints, and a fixed link `tool0` at the tool centre point (the ROS-
// Industrial convention). Encoder 0 on every motor is the zero pose. The
// layout, the names and every choice: docs/models.md, "Writing URDF".
#pragma once

#include <string>
#include <string_view>

#include "diag/result.h"
#include "model/urdf/urdf_export_pose.h"
#include "model/workcell/model.h"

namespace rs::urdf {

struct ExportOptions {
  /// Millimetres per length unit of the description: 1, the library's
  /// unit, unless a file says otherwise (the paper's drawing units are 2 mm).
  double millimetresPerUnit = 1;
  /// The description's up axis, turned to URDF's z.
  UpAxis up = UpAxis::Y;
};

/// The edge of a LINE's thin box, and the least edge of any box: 2 mm.
inline constexpr double kThinBoxMetres = 0.002;

/// The names the export gives.
inline constexpr std::string_view kBaseLink = "base_link";
inline constexpr std::string_view kToolLink = "tool0";
/// "joint_3": the joint of motor (arm joint) 3, counted from 1.
std::string jointName(int joint);
/// "link_3": the link joint 3 moves.
std::string linkName(int joint);

/// The URDF document of `robot` (built: with its chain), the same bytes for
/// the same robot and options. A refusal for a robot without a chain or a
/// length unit that is not a positive finite number of millimetres.
diag::Result<std::string> exportUrdf(const workcell::Robot& robot, const ExportOptions& options = {});

}  // namespace rs::urdf
