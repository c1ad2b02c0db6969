// A scenario's expectations against a run of a cell of several robots
// (cell_test.h): each routed to the robot its `LABEL.` names (or, for a
// robot's motors, lines, variables and tool centre point without one, the
// program under test's robot) and checked on that robot's run with its own
// end; the rest (the cell's end, time, objects, devices, collisions) on the
// cell; one robot's line before another's on both robots' watches.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/cell_run.h"
#include "tools/testrun/expectation.h"

namespace rs::testrun {

class CellChecker {
 public:
  /// Before the run: watches each robot's run for what it must answer.
  /// `outcome` is the cell's, read after the run; `under` the program under
  /// test (an index of the cell run's programs), if any. All must outlive
  /// the checker.
  CellChecker(runtime::CellRun& cell, const vm::RunOutcome& outcome, const std::vector<Expectation>& expectations,
              std::optional<std::size_t> under, const std::string& file);
  ~CellChecker();
  CellChecker(const CellChecker&) = delete;
  CellChecker& operator=(const CellChecker&) = delete;

  /// After the run: every expectation that does not hold, in the order
  /// written; with `impliedFinished`, a cell that did not finish first.
  std::vector<diag::Diagnostic> check(bool impliedFinished);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rs::testrun
