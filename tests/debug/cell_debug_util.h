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
