#include "stdlib/default_robot.h"

namespace rs::stdlib {

using rs::vm::JointKind;
using rs::vm::MotorSpec;

// Joints 1..4: type, letter, precision and encoder range are the paper's
// Table 6 ("Joint parameters"; no coupling on any joint).
//
// The gripper: the paper's Table 4 should give its precision and range, but
// the surviving text of that table holds only box coordinates. We assume
// 0.5 degrees per unit over 0..120 (60 degrees of finger travel), with
// min = open and max = closed as for every gripper.
//
// Speeds: the paper gives none (the Mark III controller sets them), so these
// are our choice, not measurements: a plausible pace for a small teaching arm,
// slow enough to follow on screen, each axis scaled to what it carries:
//   E 400 u/s = 47 deg/s  base turn; a full sweep (2000 u) takes 5 s
//   D 400 u/s = 89 deg/s  elbow, lighter load than the base
//   C 300 u/s = 36 len/s  vertical slide; a lead screw is the slowest axis
//   B 500 u/s = 112 deg/s wrist roll, almost no inertia
//   A 200 u/s = 100 deg/s gripper; fully open to closed in 0.6 s
std::vector<MotorSpec> rhinoScaraMotors() {
  return {
      {'E', JointKind::Revolute, 0.1175, -1000, 1000, 400},
      {'D', JointKind::Revolute, 0.2233, -550, 550, 400},
      {'C', JointKind::Prismatic, 0.1200, -350, 350, 300},
      {'B', JointKind::Revolute, 0.2233, -700, 700, 500},
      {'A', JointKind::Gripper, 0.5, 0, 120, 200},
  };
}

std::string_view rhinoScaraName() { return "rhino-scara"; }

std::string_view rhinoScaraCellName() { return "scara-pick"; }

}  // namespace rs::stdlib
