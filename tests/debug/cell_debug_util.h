// Shared by the tests of `robotsim debug --cell`: a session driven in
// batch mode (-x) as a person would type it, and what the console printed
// after one of its commands.
#pragma once

#include <string>
#include <vector>

#include "tests/cli/cli_support.h"

namespace debugtest {

/// `robotsim debug --cell CELL EXTRA... -x FILE`, FILE holding `commands`.
inline rs::testing::CliResult runCellDebugger(const std::string& cell, const std::string& commands,
                                              std::vector<std::string> extra = {}) {
  rs::testing::TempDir dir;
  const std::string file = dir.write("session.cmds", commands);
  std::vector<std::string> args = {"debug", "--cell", cell};
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back("-x");
  args.push_back(file);
  return rs::testing::runCli(args);
}

/// A cell `two` of two XR-4s, `left` and `right` (as interlock.rsd places
/// them), running `left` and `right` (program text), with `extra` lines
/// in its WORKCELL block: the cell's file.
inline std::string writeTwoRobotCell(rs::testing::TempDir& dir, const std::string& left, const std::string& right,
                                     const std::string& extra = {}) {
  dir.write("l.rsp", left);
  dir.write("r.rsp", right);
  return dir.write("c.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
                            "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\n" + extra + "END\n");
}

/// gantry-cell's gantry (as `arm`) beside an XR-4 (`other`, a DELAY 1):
/// the gantry lowers by 1100 counts, closes its gripper on nothing above
/// a block and goes down 600 more into it (test_debug_cell_points.cpp
/// works out the times). The cell's file.
inline std::string writeGantryBeside(rs::testing::TempDir& dir) {
  dir.write("arm.rsp", "        MOVETO -2800 2800 0 0\n        MOVE 0 0 1100 0\n        MOVE 0 0 0 100\n"
                       "        MOVE 0 0 600 0\n        END\n");
  dir.write("o.rsp", "        DELAY 1\n        END\n");
  return dir.write("c.rsd", "WORKCELL gx\n  ROBOT gantry AT 0 1000 0 AS arm PROGRAM arm.rsp\n"
                            "  ROBOT rhino-xr4 AT 3000 750 0 AS other PROGRAM o.rsp\n"
                            "  OBJECT pallet AT 150 0 760\n  OBJECT block AT 200 30 700\n"
                            "  OBJECT block AT 280 30 700\n  OBJECT pallet AT 610 0 260\nEND\n");
}

/// What the console printed after the `nth` command `command` (up to the next prompt).
inline std::string afterCommand(const std::string& out, const std::string& command, std::size_t nth = 1) {
  std::size_t at = 0;
  for (std::size_t i = 0; i < nth; ++i) {
    at = out.find("(rsdb) " + command + "\n", at);
    if (at == std::string::npos) return "(command not found: " + command + ")";
    at += 8 + command.size();
  }
  const std::size_t end = out.find("(rsdb) ", at);
  return out.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

}  // namespace debugtest
