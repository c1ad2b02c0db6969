#include "tools/testrun/test_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <streambuf>

#include "base/file_io.h"
#include "diag/read_input.h"
#include "launch/program.h"
#include "launch/run_request.h"
#include "runtime/run/empty_close.h"
#include "runtime/run/run.h"
#include "runtime/run/trace.h"
#include "tools/testrun/cell_test.h"
#include "tools/testrun/evaluate.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/golden_check.h"
#include "tools/testrun/golden_trace.h"
#include "tools/testrun/run_watch.h"
#include "tools/testrun/scenario_file.h"
#include "tools/testrun/test_steps.h"
#include "vm/image_file.h"

namespace rs::testrun {

namespace fs = std::filesystem;

std::string_view statusName(TestStatus status) {
  switch (status) {
    case TestStatus::Passed: return "PASSED";
    case TestStatus::Failed: return "FAILED";
    case TestStatus::Error: return "ERROR";
  }
  return "ERROR";
}

const diag::SourceFile* TestResult::sourceOf(const std::string& name) const {
  for (const auto& s : sources)
    if (s->name() == name) return s.get();
  return nullptr;
}

// A file named by a `; test:` line is relative to the program's folder; a
// cell that is no file there is a library name.
std::string besideProgram(const std::string& program, const std::string& name, bool mayBeLibraryName) {
  if (name.empty()) return name;
  const fs::path path = fs::path(name).is_absolute() ? fs::path(name) : fs::path(program).parent_path() / name;
  std::error_code ec;
  // A library name unless something but a folder is there (a FIFO there is
  // refused by its reader as what it is).
  if (mayBeLibraryName && (!fs::exists(path, ec) || fs::is_directory(path, ec))) return name;
  return path.lexically_normal().string();
}

// The compile errors against the expect-error lines: each expectation
// needs an error on its line whose message contains its text, each error
// an expectation. A program that expects no error gets the compiler's
// diagnostics as `robotsim check` prints them (a did-you-mean hint
// included); in a negative example an error it does not expect says so,
// and, when the compiler has no better hint, how to expect it (never when
// grading: a student cannot change the scenario file).
void matchCompileErrors(const std::vector<Expectation>& expectations, const std::vector<diag::Diagnostic>& diags,
                        const std::string& file, bool grading, TestResult& r) {
  bool negativeExample = false;
  std::vector<bool> matched(diags.size(), false);
  for (const Expectation& e : expectations) {
    if (e.kind != ExpectKind::CompileError) continue;
    negativeExample = true;
    ++r.expectations;
    bool found = false;
    std::string onLine;
    for (std::size_t i = 0; i < diags.size(); ++i) {
      const diag::Diagnostic& d = diags[i];
      if (d.severity != diag::Severity::Error || d.file != file || d.pos.line != e.pos.line) continue;
      if (d.message.find(e.message) != std::string::npos) {
        matched[i] = found = true;
      } else {
        onLine += fmt::format("{}'{}'", onLine.empty() ? "" : ", ", d.message);
      }
    }
    if (!found)
      r.problems.push_back({file, e.pos, diag::Severity::Error,
                            onLine.empty() ? fmt::format("expected a compile error containing '{}' on this line; "
                                                         "there is none",
                                                         e.message)
                                           : fmt::format("expected a compile error containing '{}' on this line; "
                                                         "the errors here: {}",
                                                         e.message, onLine)});
  }
  for (std::size_t i = 0; i < diags.size(); ++i) {
    if (matched[i] || diags[i].severity != diag::Severity::Error) continue;
    diag::Diagnostic d = diags[i];
    if (negativeExample) {
      d.message = "unexpected compile error: " + d.message;
      if (d.hint.empty() && !grading)
        d.hint = "mark an error a negative example must have with '; expect-error: TEXT' on its line";
    }
    r.problems.push_back(std::move(d));
  }
}

// How to get past a stop by a limit: a loop that never lets the clock move
// is the program's to fix; the grading limits (not those its scenario
// set) the scenario file's to raise.
void hintLimit(const vm::RunOutcome& outcome, const TestSettings& settings, bool grading, TestResult& r) {
  std::string hint;
  if (outcome.reason == vm::StopReason::InstantLimit)
    hint = "give the loop a DELAY, a move or a WAITFOR, or a way out";
  else if (grading && outcome.reason == vm::StopReason::StepLimit && !settings.maxSteps)
    hint = fmt::format("grading stops a run after {} instructions; a scenario that needs more says 'test: max-steps N'",
                       kGradingMaxSteps);
  else if (grading && outcome.reason == vm::StopReason::TimeLimit && settings.maxTime.empty())
    hint = fmt::format("grading stops a run at {} simulated seconds; a scenario that needs longer says 'test: "
                       "max-time SECONDS'",
                       kGradingMaxSeconds);
  else if (grading && outcome.reason == vm::StopReason::KnotLimit && !settings.maxKnots)
    hint = fmt::format("grading stops a run after {} knots of straight lines (MOVES, APPRO, DEPART); a scenario that "
                       "needs more says 'test: max-knots N'",
                       kGradingMaxKnots);
  else if (outcome.reason == vm::StopReason::KnotLimit)
    hint = "allow more with 'test: max-knots N'";
  if (hint.empty()) return;
  for (diag::Diagnostic& d : r.problems)
    if (d.hint.empty() && d.message.find(vm::stopReasonName(outcome.reason)) != std::string::npos) d.hint = hint;
}

launch::RunRequest runRequestOf(const TestSettings& settings, const std::string& settingsFile, bool expectsCollision,
                                const RunnerOptions& options, bool grading) {
  launch::RunRequest run;
  run.stimuliFile = besideProgram(settingsFile, settings.stimuliFile, false);
  run.inputs = settings.inputs;
  run.maxSteps = settings.maxSteps;
  run.maxTime = settings.maxTime;
  run.maxKnots = settings.maxKnots;
  if (grading && !run.maxSteps) run.maxSteps = kGradingMaxSteps;
  if (grading && !run.maxKnots) run.maxKnots = kGradingMaxKnots;
  if (grading && run.maxTime.empty()) run.maxTime = std::to_string(kGradingMaxSeconds);
  run.collisions = options.collisions;
  // A test that expects a collision lets the run go on past it.
  if (expectsCollision && run.collisions.empty()) run.collisions = "warn";
  return run;
}

namespace {

// The program at `program` checked against `parsed`, whose file names are
// relative to the folder of `settingsFile`. `r` has its file, name and the
// sources read so far. `grading`: a submission against a scenario file
// (--spec): the grading limits apply where the scenario sets none.
void check(const std::string& programGiven, const ParsedExpectations& parsed, const std::string& settingsFile,
           const RunnerOptions& options, bool grading, TestResult& r) {
  launch::ProgramRequest request{programGiven, besideProgram(settingsFile, parsed.settings.cell, true), options.libDirs};
  request.submission = grading;
  request.robot = parsed.settings.robot;
  // A cell of several robots with programs runs them all (cell_test.h).
  if (!request.cell.empty()) {
    const CellCheck cell = checkCell(request, parsed, settingsFile, options, grading, r);
    if (cell.done) return;
    if (!cell.program.empty()) request.file = cell.program, request.robot = cell.robot;
  }
  const std::string& program = request.file;
  if (program.empty()) {
    r.status = TestStatus::Error;
    r.problems.push_back({settingsFile, {}, diag::Severity::Error,
                          "the scenario file names no program: add 'program FILE', or give it with --spec"});
    return;
  }
  const launch::LoadedProgram loaded = launch::loadProgram(request);
  if (loaded.source && !r.sourceOf(loaded.source->name()))
    r.sources.push_back(std::make_shared<const diag::SourceFile>(*loaded.source));
  // Grading quotes no line of a file the submission names (its cell): a
  // diagnostic there shows its place and the offending token only, so a
  // `.rsd` holding anything else echoes no more than one word of it.
  if (loaded.descriptions && !grading)
    for (const diag::Diagnostic& d : loaded.diagnostics)
      if (const diag::SourceFile* s = loaded.descriptions->source(d.file))
        r.sources.push_back(std::make_shared<const diag::SourceFile>(*s));
  // A problem outside the program (its cell, an unreadable file) means the
  // test cannot start.
  for (const diag::Diagnostic& d : loaded.diagnostics)
    if (d.severity == diag::Severity::Error && (d.file != program || d.pos.line == 0)) {
      r.status = TestStatus::Error;
      r.problems.push_back(d);
    }
  if (r.status == TestStatus::Error) return;

  if (parsed.expectsCompileErrors() || !loaded.ok()) {
    matchCompileErrors(parsed.expectations, loaded.diagnostics, program, grading, r);
    if (parsed.expectsCompileErrors() && loaded.ok())
      r.problems.insert(r.problems.begin(), {program, {}, diag::Severity::Error,
                                             "the program compiled, but its expect-error lines ask for errors"});
    r.status = r.problems.empty() ? TestStatus::Passed : TestStatus::Failed;
    return;
  }

  // `LABEL.` before an expectation names the robot this run drives, or none.
  std::vector<diag::Diagnostic> labelProblems;
  const ParsedExpectations checked = ownRobotOnly(parsed, loaded.cell.get(), settingsFile, labelProblems);
  std::vector<GoldenTrace> traces;
  if (!openGoldenTraces(checked, settingsFile, traces, r)) return;
  const launch::RunRequest run = runRequestOf(checked.settings, settingsFile, checked.expectsCollision(), options, grading);
  std::vector<diag::Diagnostic> runProblems;
  std::optional<runtime::RunSpec> spec = launch::prepareRun(loaded, run, runProblems);
  if (!spec) {
    r.status = TestStatus::Error;
    r.problems = std::move(runProblems);
    return;
  }
  if (grading) spec->limits.maxStepsPerInstant = kGradingMaxStepsAtOneInstant;
  // --update may make the run again, for its trace.
  std::optional<runtime::RunSpec> again;
  if (options.update && !traces.empty()) again = *spec;
  std::optional<CoverageCounter> counter;
  if (options.coverage) counter.emplace(spec->image);
  runtime::Run running(std::move(*spec));
  std::optional<RunWatch> watch;
  if (RunWatch::needed(checked.expectations)) watch.emplace(running, checked.expectations);
  if (watch) running.observe(*watch);
  if (counter) running.observe(*counter);
  for (GoldenTrace& t : traces) {
    t.writers.push_back(std::make_unique<runtime::TraceWriter>(*t.stream, runtime::TraceFormat::Text, running));
    running.observe(*t.writers.back());
  }
  const vm::RunOutcome outcome = running.runToEnd();
  r.ran = true;
  if (watch) watch->finish(outcome);
  if (counter)
    r.coverage.push_back({program, loaded.source ? std::make_shared<const diag::SourceFile>(*loaded.source) : nullptr,
                          counter->coverage()});
  r.simulated = running.rig().clock();
  r.steps = outcome.steps;
  r.expectations = parsed.expectations.size() + (checked.statesStatus() ? 0 : 1);
  // An expectation of a scenario file points into it.
  r.problems = evaluate(running, checked.expectations, settingsFile, !checked.statesStatus(), watch ? &*watch : nullptr);
  if (std::optional<diag::Diagnostic> w = runtime::gripperWarning(running, program)) r.warnings.push_back(std::move(*w));
  if (!checked.statesStatus() && !r.problems.empty() && !outcome.ok()) r.problems.front().file = program;
  hintLimit(outcome, checked.settings, grading, r);
  r.problems.insert(r.problems.end(), labelProblems.begin(), labelProblems.end());
  // --update: the same run again, its trace into the golden file.
  const TraceRerun rerun = [&again](std::ostream& out, vm::StepObserver& stop) {
    runtime::Run run(*again);
    runtime::TraceWriter writer(out, runtime::TraceFormat::Text, run);
    run.observe(writer);
    run.observe(stop);
    run.runToEnd();
  };
  for (const GoldenTrace& t : traces) judgeTrace(t, again ? &rerun : nullptr, settingsFile, options, r);
  r.status = r.problems.empty() ? TestStatus::Passed : TestStatus::Failed;
}

std::shared_ptr<const diag::SourceFile> readSource(const std::string& path, TestResult& r) {
  diag::Result<std::string> read = diag::readInput(path, launch::kMaxInputBytes, "cannot read");
  if (!read) {
    r.status = TestStatus::Error;
    r.problems.push_back(read.failure());
    return nullptr;
  }
  return std::make_shared<const diag::SourceFile>(path, std::move(read).value());
}

bool isScenarioFile(const std::string& path) { return fs::path(path).extension() == ".rstest"; }

// What scenario `s` earned in `r`: all its points when it passed; with
// partial credit, those of each expectation that holds (no problem at its
// line and column in the scenario file, or at one of its motor terms) in a run that was made; else none.
void grade(const Scenario& s, const std::string& specPath, TestResult& r) {
  r.maxPoints = maxPointsOf(s);
  if (r.status == TestStatus::Passed) {
    r.points = r.maxPoints;
    return;
  }
  r.points = 0;
  if (r.status == TestStatus::Error || !r.ran || !partialCredit(s)) return;
  for (const Expectation& e : s.parsed.expectations) {
    if (!e.points) continue;
    const bool failed = std::any_of(r.problems.begin(), r.problems.end(), [&](const diag::Diagnostic& d) {
      // At the expectation, or at one of its motor terms (evaluate.cpp's failAtMotor).
      const bool atTerm = std::find(e.motorCols.begin(), e.motorCols.end(), d.pos.col) != e.motorCols.end();
      return d.file == specPath && d.pos.line == e.pos.line && (d.pos.col == e.pos.col || atTerm);
    });
    if (!failed) r.points += *e.points;
  }
}

}  // namespace

std::vector<TestResult> runScenarios(const std::string& specPath, const std::string& programOverride,
                                     const RunnerOptions& options) {
  TestResult base;
  base.file = programOverride.empty() ? specPath : programOverride;
  const std::shared_ptr<const diag::SourceFile> spec = readSource(specPath, base);
  if (!spec) return {base};
  base.sources.push_back(spec);
  const ScenarioFile parsed = parseScenarioFile(*spec);
  if (!parsed.errors.empty()) {
    base.status = TestStatus::Error;
    base.problems = parsed.errors;
    return {base};
  }
  std::string program = programOverride;
  if (program.empty()) {
    // No program: the cell's PROGRAMs and the `program LABEL FILE` lines are what runs.
    if (parsed.program.empty() && parsed.shared.cell.empty() && parsed.shared.programs.empty() &&
        std::all_of(parsed.scenarios.begin(), parsed.scenarios.end(), [](const Scenario& s) {
          return s.parsed.settings.cell.empty() && s.parsed.settings.programs.empty();
        })) {
      base.status = TestStatus::Error;
      base.problems.push_back({specPath, {}, diag::Severity::Error,
                               "the scenario file names no program: add 'program FILE', or give it with --spec"});
      return {base};
    }
    if (!parsed.program.empty()) program = besideProgram(specPath, parsed.program, false);
  }
  std::vector<TestResult> results;
  for (const Scenario& s : parsed.scenarios) {
    TestResult r = base;
    r.name = s.name;
    ParsedExpectations scenario = s.parsed;
    scenario.settings = settingsOf(parsed, s);  // with the settings every scenario shares
    check(program, scenario, specPath, options, !programOverride.empty(), r);
    grade(s, specPath, r);
    results.push_back(std::move(r));
  }
  return results;
}

std::vector<TestResult> runTestPath(const std::string& path, const RunnerOptions& options) {
  if (isScenarioFile(path)) return runScenarios(path, "", options);
  TestResult r;
  r.file = path;
  const std::shared_ptr<const diag::SourceFile> source = readSource(path, r);
  if (!source) return {r};
  ParsedExpectations parsed;
  if (!vm::looksLikeImage(source->text())) {
    parsed = parseExpectations(*source);
    r.sources.push_back(source);
    if (!parsed.errors.empty()) {
      r.status = TestStatus::Error;
      r.problems = parsed.errors;
      return {r};
    }
  }
  check(path, parsed, path, options, false, r);
  return {r};
}

}  // namespace rs::testrun
