// Checks a finished run against the expectations of its program: each one
// that does not hold is a diagnostic at the expectation, saying what was
// expected, what happened, and when and at which source line it went wrong.
// What happened during the run comes from a RunWatch, the rest from the
// run's state at its end.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/run.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/run_watch.h"

namespace rs::testrun {

/// `run` must be finished; `watch` watched it for these expectations (it
/// may be null when RunWatch::needed says none needs it). Compile-error
/// expectations are not run expectations and are skipped. With
/// `impliedFinished`, a run that does not finish normally fails too (at the
/// instruction that stopped it).
std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const std::vector<Expectation>& expectations,
                                       const std::string& file, bool impliedFinished, const RunWatch* watch);

}  // namespace rs::testrun
