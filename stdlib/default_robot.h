// The robot a program runs on when no robot file is given: the Rhino SCARA
// that the ROBOTSIM paper models in its last section.
#pragma once

#include <string_view>
#include <vector>

#include "vm/image.h"

namespace rs::stdlib {

/// The Rhino SCARA's motors in program order: joints 1..4 (letters E, D, C,
/// B, as in the paper's Table 6), then the gripper motor A.
std::vector<rs::vm::MotorSpec> rhinoScaraMotors();

/// The library name of that robot: "rhino-scara".
std::string_view rhinoScaraName();

/// The library workcell that robot stands in, with its kinematic model:
/// "scara-pick" (what a hint offers a program compiled for these motors).
std::string_view rhinoScaraCellName();

}  // namespace rs::stdlib
