// One program as a test: its `; test:` settings and `; expect:` lines
// read, the program compiled (for the cell it names) or its expected
// compile errors matched, its run made and checked. Nothing a test file
// holds stops other tests: every problem ends up in the result.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "diag/source_file.h"
#include "runtime/run/run.h"
#include "tools/testrun/coverage.h"
#include "vm/machine.h"

namespace rs::testrun {

enum class TestStatus : std::uint8_t {
  Passed,
  Failed,  ///< an expectation does not hold, or the program does not compile
  Error,   ///< the test could not start: a bad expectation, an unreadable file, an unknown cell
};

struct TestResult {
  std::string file;  ///< the program, or the scenario file
  std::string name;  ///< the scenario ("" for a program's own expectations)
  TestStatus status = TestStatus::Passed;
  std::size_t expectations = 0;  ///< how many were checked
  vm::Micros simulated = 0;      ///< the run's simulated time (0 when nothing ran)
  std::uint64_t steps = 0;
  /// Why it failed or could not start, in the compiler's style.
  std::vector<diag::Diagnostic> problems;
  /// What a run that passed or failed is warned about, without failing
  /// it: a gripper that closed but never took an object
  /// (runtime/run/empty_close.h).
  std::vector<diag::Diagnostic> warnings;
  /// The texts of the files the problems and warnings point into, for their carets.
  std::vector<std::shared_ptr<const diag::SourceFile>> sources;
  const diag::SourceFile* sourceOf(const std::string& file) const;
  /// With coverage asked for and a run made: what each program ran (one
  /// program, or each robot's of a cell).
  std::vector<ProgramCoverage> coverage;
  /// Golden traces written by --update.
  std::vector<std::string> updated;
  /// A scenario's grade, in hundredths of a point (scenario_file.h): what
  /// it earned and the most it could (0 and 0 for a program's own
  /// expectations). Passed earns the most; failed earns, where the
  /// scenario gives partial credit, the points of the expectations that
  /// held in a run that was made; an error earns nothing.
  std::int64_t points = 0, maxPoints = 0;
  /// The program compiled and ran (its expectations were checked).
  bool ran = false;
};

struct RunnerOptions {
  std::vector<std::string> libDirs;  ///< --lib
  bool coverage = false;             ///< count what each run executes
  bool update = false;               ///< write golden traces that differ or are missing
  std::string collisions;            ///< --collisions (empty: error)
};

/// What grading (`--spec`) allows a submission's run when its scenario sets
/// no limit: far more than a correct program of an exercise needs, little
/// enough that one that never ends costs a fraction of a second
/// (docs/testing.md, "Grading").
inline constexpr std::uint64_t kGradingMaxSteps = 1'000'000;
inline constexpr std::uint32_t kGradingMaxSeconds = 120;
/// ... and knots of straight lines (vm::RunLimits::maxKnots): a line costs
/// its knots, and a MOVES loop on a cell of the student's choosing (motors
/// that make a line take no time) would otherwise run a million lines.
/// About 0.2 s of a grader's CPU at most (docs/performance.md).
inline constexpr std::uint64_t kGradingMaxKnots = 200'000;
/// ... and instructions in a row while the clock stands still: a loop
/// that polls without a DELAY is named for what it is, long before the
/// step limit.
inline constexpr std::uint64_t kGradingMaxStepsAtOneInstant = 100'000;

/// The tests in `path`: a program's own expectations (one result), or
/// every scenario of a scenario file (`.rstest`, one result each).
std::vector<TestResult> runTestPath(const std::string& path, const RunnerOptions& options);

/// Every scenario of the scenario file `spec` against `program` (when not
/// empty, instead of the program the file names): grading.
std::vector<TestResult> runScenarios(const std::string& spec, const std::string& program, const RunnerOptions& options);

std::string_view statusName(TestStatus status);

}  // namespace rs::testrun
