// Checks a finished run against the expectations of its program: each one
// that does not hold is a diagnostic at the expectation, saying what was
// expected, what happened, and when and at which source line it went wrong.
// What happened during the run comes from a RunWatch, the rest from the
// run's state at its end.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/run.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/run_watch.h"

namespace rs::testrun {

/// How the run being checked ended: a run of one, its outcome, its clock
/// and the source line it stopped at (endOf); a robot of a cell of several
/// (cell_test.h), the robot's own end, its label named in every message;
/// the cell as a whole, the cell's outcome and clock, and no line.
struct RunEnd {
  vm::RunOutcome outcome;
  vm::Micros at = 0;
  std::optional<std::uint32_t> line;
  std::string robot;     ///< "" or the robot's label: its failures begin "robot LABEL: "
  bool stopped = false;  ///< another robot's failure stopped it (the cell's emergency stop)
};

/// The end of a finished run of one.
RunEnd endOf(const runtime::Run& run);

/// `run` must be finished; `watch` watched it for these expectations (it
/// may be null when RunWatch::needed says none needs it). Compile-error
/// expectations are not run expectations and are skipped. With
/// `impliedFinished`, a run that does not finish normally fails too (at the
/// instruction that stopped it).
std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const std::vector<Expectation>& expectations,
                                       const std::string& file, bool impliedFinished, const RunWatch* watch);
/// The same for a run that ended as `end` says (`run` may be a robot of a
/// cell run, or one standing for the cell's world and devices).
std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const RunEnd& end,
                                       const std::vector<Expectation>& expectations, const std::string& file,
                                       bool impliedFinished, const RunWatch* watch);

}  // namespace rs::testrun
