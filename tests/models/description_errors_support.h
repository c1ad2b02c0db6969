// What the description error tests share (tests/models/test_description_*):
// the diagnostics of loading a robot or a workcell from a scratch library,
// and small descriptions whose line numbers the tests count on.
#pragma once

#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "tests/models/models_support.h"

namespace rs::testing {

using Strings = std::vector<std::string>;

// Diagnostics of loading `root` as a robot, the scratch directory being the
// whole search path (no stdlib: nothing there can interfere).
inline Strings robotErrors(const TempDir& dir, const std::string& root) {
  compiler::Library lib({dir.path()});
  const auto robot = lib.robot(dir.file(root));
  Strings d = diagnosticList(lib.diagnostics(), dir.path().string());
  if (!d.empty()) CHECK_FALSE(robot);
  return d;
}

inline Strings workcellErrors(const TempDir& dir, const std::string& root) {
  compiler::Library lib({dir.path()});
  const auto cell = lib.workcell(dir.file(root));
  Strings d = diagnosticList(lib.diagnostics(), dir.path().string());
  if (!d.empty()) CHECK_FALSE(cell);
  return d;
}

inline const std::string kBase = lines({
    "LINK base",                 // 1
    "  LINE 0 0 0 0 0 1",        // 2
    "END",                       // 3
});

// A complete gripper on lines 1..9 and its palm link on lines 10..12; the
// tool centre point is the origin, n = +x, a = -z.
inline const Strings kGripperLines{
    "GRIPPER hand",                      // 1
    "  BASE palm",                       // 2
    "  FINGERS palm palm",               // 3
    "  LETTER A",                        // 4
    "  PRECISION 0.5",                   // 5
    "  RANGE 0 40",                      // 6
    "  AXIS2 0 -1 0  1 -1 0",            // 7
    "  AXIS3 0 1 0  -1 1 0",             // 8
    "  NORMAL 0 0 0  1 0 0",             // 9
    "  APPROACH 0 0 0  0 0 -1",          // 10
    "END",                               // 11
    "LINK palm",                         // 12
    "  LINE 0 0 0 0 0 1",                // 13
    "END",                               // 14
};

// A one-link robot carrying `hand`, after the gripper (starts on line 15).
inline const Strings kHandRobotLines{
    "ROBOT r",                                               // 15
    "  LINK palm FRAME ORIGIN 0 0 10 XAXIS 1 0 10 ZAXIS 0 0 11",  // 16
    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",  // 17
    "  GRIPPER hand",                                        // 18
    "END",                                                   // 19
};

inline std::string gripperFile(Strings gripper) {
  gripper.insert(gripper.end(), kHandRobotLines.begin(), kHandRobotLines.end());
  return lines(gripper);
}

}  // namespace rs::testing
