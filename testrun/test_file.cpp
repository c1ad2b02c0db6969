#include "testrun/test_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <sstream>

#include "base/file_io.h"
#include "launch/program.h"
#include "launch/run_request.h"
#include "runtime/run/empty_close.h"
#include "runtime/run/run.h"
#include "testrun/evaluate.h"
#include "testrun/expectation.h"
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

namespace {

// A file named by a `; test:` line is relative to the program's folder; a
// cell that is no file there is a library name.
std::string besideProgram(const std::string& program, const std::string& name, bool mayBeLibraryName) {
  if (name.empty()) return name;
  const fs::path path = fs::path(name).is_absolute() ? fs::path(name) : fs::path(program).parent_path() / name;
  std::error_code ec;
  if (mayBeLibraryName && !fs::is_regular_file(path, ec)) return name;
  return path.lexically_normal().string();
}

// The compile errors against the expect-error lines: each expectation
// needs an error on its line whose message contains its text, each error
// an expectation.
void matchCompileErrors(const std::vector<Expectation>& expectations, const std::vector<diag::Diagnostic>& diags,
                        const std::string& file, TestResult& r) {
  std::vector<bool> matched(diags.size(), false);
  for (const Expectation& e : expectations) {
    if (e.kind != ExpectKind::CompileError) continue;
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
    d.message = "unexpected compile error: " + d.message;
    d.hint = "mark an error a negative example must have with '; expect-error: TEXT' on its line";
    r.problems.push_back(std::move(d));
  }
}

}  // namespace

namespace {

void compareTrace(const Expectation& e, const std::string& golden, const std::string& trace,
                  const std::string& settingsFile, const RunnerOptions& options, TestResult& r);

// The program at `program` checked against `parsed`, whose file names are
// relative to the folder of `settingsFile`. `r` has its file, name and the
// sources read so far.
void check(const std::string& program, const ParsedExpectations& parsed, const std::string& settingsFile,
           const RunnerOptions& options, TestResult& r) {
  launch::ProgramRequest request{program, besideProgram(settingsFile, parsed.settings.cell, true), options.libDirs};
  const launch::LoadedProgram loaded = launch::loadProgram(request);
  if (loaded.source && !r.sourceOf(loaded.source->name()))
    r.sources.push_back(std::make_shared<const diag::SourceFile>(*loaded.source));
  if (loaded.descriptions)
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
    matchCompileErrors(parsed.expectations, loaded.diagnostics, program, r);
    if (parsed.expectsCompileErrors() && loaded.ok())
      r.problems.insert(r.problems.begin(), {program, {}, diag::Severity::Error,
                                             "the program compiled, but its expect-error lines ask for errors"});
    r.status = r.problems.empty() ? TestStatus::Passed : TestStatus::Failed;
    return;
  }

  launch::RunRequest run;
  run.stimuliFile = besideProgram(settingsFile, parsed.settings.stimuliFile, false);
  run.inputs = parsed.settings.inputs;
  run.maxSteps = parsed.settings.maxSteps;
  run.maxTime = parsed.settings.maxTime;
  run.collisions = options.collisions;
  // A test that expects a collision lets the run go on past it.
  if (parsed.expectsCollision() && run.collisions.empty()) run.collisions = "warn";
  std::vector<diag::Diagnostic> runProblems;
  std::optional<runtime::RunSpec> spec = launch::prepareRun(loaded, run, runProblems);
  if (!spec) {
    r.status = TestStatus::Error;
    r.problems = std::move(runProblems);
    return;
  }
  spec->log = true;
  std::optional<CoverageCounter> counter;
  if (options.coverage) counter.emplace(spec->image);
  runtime::Run running(std::move(*spec));
  if (counter) running.observe(*counter);
  std::ostringstream trace;
  std::unique_ptr<vm::StepObserver> tracer;
  if (parsed.wantsTrace() && options.traceMaker) {
    tracer = options.traceMaker(trace, running);
    running.observe(*tracer);
  }
  const vm::RunOutcome outcome = running.runToEnd();
  if (counter) r.coverage = counter->coverage();
  r.simulated = running.clock();
  r.steps = outcome.steps;
  r.expectations = parsed.expectations.size() + (parsed.statesStatus() ? 0 : 1);
  // An expectation of a scenario file points into it.
  r.problems = evaluate(running, parsed.expectations, settingsFile, !parsed.statesStatus());
  if (std::optional<diag::Diagnostic> w = runtime::gripperWarning(running, program)) r.warnings.push_back(std::move(*w));
  if (!parsed.statesStatus() && !r.problems.empty() && !outcome.ok()) r.problems.front().file = program;
  for (const Expectation& e : parsed.expectations)
    if (e.kind == ExpectKind::Trace) compareTrace(e, besideProgram(settingsFile, e.name, false), trace.str(),
                                                  settingsFile, options, r);
  r.status = r.problems.empty() ? TestStatus::Passed : TestStatus::Failed;
}

}  // namespace

// The first line where two texts differ (1-based), 0 when equal.
std::size_t firstDifference(std::string_view a, std::string_view b, std::string& lineA, std::string& lineB) {
  std::size_t line = 1;
  while (true) {
    const std::size_t ea = a.find('\n'), eb = b.find('\n');
    const std::string_view la = a.substr(0, ea), lb = b.substr(0, eb);
    if (la != lb || (ea == std::string_view::npos) != (eb == std::string_view::npos)) {
      lineA = la, lineB = lb;
      return line;
    }
    if (ea == std::string_view::npos) return 0;
    a.remove_prefix(ea + 1), b.remove_prefix(eb + 1), ++line;
  }
}

namespace {

// `expect: trace FILE`: the run's text trace must be the file's bytes;
// --update writes the file instead when it differs or is missing.
void compareTrace(const Expectation& e, const std::string& golden, const std::string& trace,
                  const std::string& settingsFile, const RunnerOptions& options, TestResult& r) {
  if (!options.traceMaker) {
    r.problems.push_back({settingsFile, e.pos, diag::Severity::Error, "no trace writer: cannot check the trace"});
    return;
  }
  const base::FileRead read = base::readFile(golden, launch::kMaxInputBytes);
  if (read.bytes && *read.bytes == trace) return;
  if (options.update) {
    std::string error;
    if (base::writeFileAtomically(golden, trace, error)) {
      r.updated.push_back(golden);
      return;
    }
    r.problems.push_back({settingsFile, e.pos, diag::Severity::Error, fmt::format("cannot write {}: {}", golden, error)});
    return;
  }
  if (!read.bytes) {
    r.problems.push_back({settingsFile, e.pos, diag::Severity::Error,
                          fmt::format("cannot read the golden trace {}: {}", golden, read.error), {},
                          "robotsim test --update writes it from the run"});
    return;
  }
  std::string want, got;
  const std::size_t line = firstDifference(*read.bytes, trace, want, got);
  r.problems.push_back({settingsFile, e.pos, diag::Severity::Error,
                        fmt::format("the trace differs from {} at its line {}: expected '{}', got '{}'", golden, line,
                                    want, got),
                        {}, "if the new run is right, robotsim test --update rewrites the golden trace"});
}

std::shared_ptr<const diag::SourceFile> readSource(const std::string& path, TestResult& r) {
  const base::FileRead read = base::readFile(path, launch::kMaxInputBytes);
  if (!read.bytes) {
    r.status = TestStatus::Error;
    r.problems.push_back({path, {}, diag::Severity::Error, "cannot read: " + read.error});
    return nullptr;
  }
  return std::make_shared<const diag::SourceFile>(path, *read.bytes);
}

bool isScenarioFile(const std::string& path) { return fs::path(path).extension() == ".rstest"; }

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
    if (parsed.program.empty()) {
      base.status = TestStatus::Error;
      base.problems.push_back({specPath, {}, diag::Severity::Error,
                               "the scenario file names no program: add 'program FILE', or give it with --spec"});
      return {base};
    }
    program = besideProgram(specPath, parsed.program, false);
  }
  std::vector<TestResult> results;
  for (const Scenario& s : parsed.scenarios) {
    TestResult r = base;
    r.name = s.name;
    check(program, s.parsed, specPath, options, r);
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
  check(path, parsed, path, options, r);
  return {r};
}

}  // namespace rs::testrun
