// A test on a cell of several robots, each running its own program on the
// cell's one clock (docs/testing.md, "A cell of several robots"): the
// cell's PROGRAMs, the scenario's `program LABEL FILE` lines and the
// program under test (on the robot `test: robot LABEL` names) run together
// through launch::prepareCellRun and runtime::CellRun. `LABEL.` before an
// expectation checks that robot's run; an expectation without it is the
// program under test's robot's (motors, lines, variables, tcp) or the
// cell's (its end, time, objects, devices, collisions).
#pragma once

#include <string>

#include "launch/program.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/test_file.h"

namespace rs::testrun {

struct CellCheck {
  bool done = false;  ///< the test was made here (a cell run, or it could not start)
  /// Not done, and one robot of the cell has a program: that program on
  /// that robot is a run of one (test_file.cpp makes it, as always).
  std::string program, robot;
};

/// The test of `request` (its cell set) when it is a run of several robots.
CellCheck checkCell(const launch::ProgramRequest& request, const ParsedExpectations& parsed,
                    const std::string& settingsFile, const RunnerOptions& options, bool grading, TestResult& r);

/// A run of one robot: `parsed` without the expectations whose `LABEL.`
/// names another robot than the one `cell` drives (each a problem in
/// `problems`, at the label: a robot without a program, or none of the
/// cell's; no cell at all).
ParsedExpectations ownRobotOnly(const ParsedExpectations& parsed, const workcell::Workcell* cell,
                                const std::string& file, std::vector<diag::Diagnostic>& problems);

}  // namespace rs::testrun
