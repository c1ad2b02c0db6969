// Checks a finished run against the expectations of its program: each one
// that does not hold is a diagnostic at the expectation, saying what was
// expected, what happened, and when and at which source line it went wrong.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/run.h"
#include "testrun/expectation.h"

namespace rs::testrun {

/// `run` must be finished and keep a log. Compile-error expectations are
/// not run expectations and are skipped. With `impliedFinished`, a run that
/// does not finish normally fails too (at `statusPos`).
std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const std::vector<Expectation>& expectations,
                                       const std::string& file, bool impliedFinished);

/// "finished", "deadlock", "step limit", ... as expectations spell them.
std::string_view statusWord(vm::StopReason reason);

}  // namespace rs::testrun
