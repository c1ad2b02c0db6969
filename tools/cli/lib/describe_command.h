// `robotsim describe CELL|ROBOT [--json]`: what a workcell holds, in
// numbers a student can check a program against: the robot's motors
// (letter, joint type, precision, range, speed, coupling), where it stands
// and how far it reaches; every object's box, centre and what it stands
// on; its devices and the wires to its inputs (describe_devices.h); the
// inputs and outputs.
#pragma once

#include <ostream>

#include "tools/cli/lib/robot_commands.h"

namespace rs::cli {

/// Its options: the cell or robot, --lib, --json.
void addDescribeOptions(CLI::App* cmd, RobotQuery& q);

/// Uses q.robot (the cell or robot), q.libDirs and q.json.
int describeCommand(const RobotQuery& q, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
