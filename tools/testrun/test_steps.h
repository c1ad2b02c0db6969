// The steps of a test that a run of one robot (test_file.cpp) and a run of
// a cell of several (cell_test.cpp) share: where a named file is, the run
// request a test's settings make, the expected compile errors matched, the
// hint that says how to get past a limit.
#pragma once

#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "launch/run_request.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/test_file.h"
#include "vm/machine.h"

namespace rs::testrun {

/// `name` as a file beside `program` (relative to its folder); with
/// `mayBeLibraryName`, kept as written when no such file is there.
std::string besideProgram(const std::string& program, const std::string& name, bool mayBeLibraryName);

/// The run's stimuli, inputs, limits (grading's where the settings give
/// none) and collision mode.
launch::RunRequest runRequestOf(const TestSettings& settings, const std::string& settingsFile, bool expectsCollision,
                                const RunnerOptions& options, bool grading);

/// The compile errors `diags` against the expect-error lines (program `file`).
void matchCompileErrors(const std::vector<Expectation>& expectations, const std::vector<diag::Diagnostic>& diags,
                        const std::string& file, bool grading, TestResult& r);

/// A hint on each problem that names the limit `outcome` stopped at.
void hintLimit(const vm::RunOutcome& outcome, const TestSettings& settings, bool grading, TestResult& r);

}  // namespace rs::testrun
