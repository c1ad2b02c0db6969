#include "tools/testrun/cell_test.h"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "launch/cell_programs.h"
#include "launch/robot_choice.h"
#include "launch/run_request.h"
#include "runtime/run/cell_run.h"
#include "runtime/run/empty_close.h"
#include "runtime/run/labelled_trace.h"
#include "tools/testrun/golden_check.h"
#include "tools/testrun/cell_checker.h"
#include "tools/testrun/test_steps.h"

namespace rs::testrun {

namespace {

// The diagnostics of `program LABEL FILE` lines' programs that name no
// place in a file (the assignment refused, the file unreadable), put at
// the scenario file's line.
void placeAtLines(std::vector<diag::Diagnostic>& diags, const std::vector<RobotProgram>& lines,
                  const std::vector<std::string>& assignments, const std::vector<std::string>& files,
                  const std::string& settingsFile) {
  for (diag::Diagnostic& d : diags) {
    if (d.pos.line != 0) continue;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const bool refused = d.file == base::safeText(assignments[k]);
      if (!refused && d.file != files[k]) continue;
      d.file = settingsFile;
      d.pos = {lines[k].pos.line, refused ? lines[k].labelCol : lines[k].fileCol};
      if (!refused) {
        d.message = fmt::format("robot {}'s program '{}': {}", base::safeText(lines[k].label),
                                base::safeText(lines[k].file), d.message);
        if (d.hint.empty()) d.hint = "a 'program LABEL FILE' line names a file relative to the scenario file";
      }
      break;
    }
  }
}

// Every text a problem may point into: the programs, and (outside
// grading, which quotes no line of a description) the cell's files.
void keepSources(const launch::CellPrograms& programs, bool grading, TestResult& r) {
  const auto keep = [&](const diag::SourceFile& s) {
    if (!r.sourceOf(s.name())) r.sources.push_back(std::make_shared<const diag::SourceFile>(s));
  };
  for (const launch::LoadedProgram& l : programs.loaded)
    if (l.source) keep(*l.source);
  if (grading) return;
  for (const diag::Diagnostic& d : programs.allDiagnostics())
    if (const diag::SourceFile* s = programs.sourceOf(d.file)) keep(*s);
}

// Every robot's trace into `out`, each line begun with its label, as
// `run --cell --trace` prints them.
void labelTraces(runtime::CellRun& cell, std::ostream& out, std::vector<std::unique_ptr<vm::StepObserver>>& kept,
                 std::vector<runtime::LabelledTrace*>& writers) {
  for (std::size_t p = 0; p < cell.size(); ++p) {
    auto w = std::make_unique<runtime::LabelledTrace>(out, runtime::TraceFormat::Text, cell.robot(p), cell.label(p));
    writers.push_back(w.get());
    cell.observe(p, *w);
    kept.push_back(std::move(w));
  }
}

CellCheck made() {
  CellCheck c;
  c.done = true;
  return c;
}

}  // namespace

ParsedExpectations ownRobotOnly(const ParsedExpectations& parsed, const workcell::Workcell* cell,
                                const std::string& file, std::vector<diag::Diagnostic>& problems) {
  ParsedExpectations out = parsed;
  out.expectations.clear();
  const workcell::PlacedRobot* driven = cell ? cell->drivenRobot() : nullptr;
  const auto ours = [&](const std::string& label) {
    return label.empty() || (driven && base::sameName(driven->labelOf(), label));
  };
  for (const Expectation& e : parsed.expectations) {
    if (ours(e.robot) && ours(e.secondRobot)) {
      out.expectations.push_back(e);
      continue;
    }
    const bool second = ours(e.robot);
    const std::string& label = second ? e.secondRobot : e.robot;
    const diag::Pos at{e.pos.line, second ? e.secondRobotCol : e.robotCol};
    if (!cell)
      problems.push_back({file, at, diag::Severity::Error,
                          fmt::format("the run has no workcell: '{}.' names a robot of one", base::safeText(label)),
                          "unknown-robot", "name the cell with 'test: cell CELL'"});
    else if (cell->robotLabeled(label) != workcell::kNoIndex)
      problems.push_back({file, at, diag::Severity::Error,
                          fmt::format("robot {} runs no program in this test: it has no run to check",
                                      base::safeText(label)),
                          "unknown-robot",
                          fmt::format("the robot with a program: `{}`", base::safeText(driven ? driven->labelOf() : ""))});
    else
      problems.push_back({file, at, diag::Severity::Error,
                          fmt::format("workcell {} has no robot labelled `{}`", base::safeText(cell->name),
                                      base::safeText(label)),
                          "unknown-robot", fmt::format("the cell's robots are {}", launch::robotLabelsOf(*cell))});
  }
  return out;
}

CellCheck checkCell(const launch::ProgramRequest& request, const ParsedExpectations& parsed,
                    const std::string& settingsFile, const RunnerOptions& options, bool grading, TestResult& r) {
  const std::vector<RobotProgram>& lines = parsed.settings.programs;
  std::vector<std::string> assignments, files;
  for (const RobotProgram& p : lines) {
    files.push_back(besideProgram(settingsFile, p.file, false));
    assignments.push_back(p.label + "=" + files.back());
  }
  // The program under test runs on its robot: no line gives that robot another.
  if (!request.file.empty() && !request.robot.empty())
    for (const RobotProgram& p : lines)
      if (base::sameName(p.label, request.robot)) {
        r.status = TestStatus::Error;
        r.problems.push_back({settingsFile, {p.pos.line, p.labelCol}, diag::Severity::Error,
                              fmt::format("robot {} runs the program under test ('test: robot {}'): a 'program {} "
                                          "FILE' line would replace it",
                                          p.label, request.robot, p.label),
                              {}, "give each robot one program"});
        return made();
      }
  launch::CellPrograms programs;
  if (!launch::assignCellPrograms(request, assignments, programs)) {
    if (!request.file.empty() && assignments.empty()) return {};  // the run of one says why, as always
    r.status = TestStatus::Error;
    std::vector<diag::Diagnostic> all = programs.allDiagnostics();
    placeAtLines(all, lines, assignments, files, settingsFile);
    for (diag::Diagnostic& d : all)
      if (d.severity == diag::Severity::Error) {
        if (request.file.empty() && assignments.empty() && d.message.starts_with("no ROBOT line"))
          d.hint = "name the programs with 'program FILE' ('test: robot LABEL' says whose), 'program LABEL FILE', or "
                   "PROGRAM on the cell's ROBOT lines";
        r.problems.push_back(d);
      }
    keepSources(programs, grading, r);
    return made();
  }
  if (programs.programs.empty()) return {};
  if (programs.programs.size() == 1) {
    if (!request.file.empty()) return {};
    CellCheck one;
    one.program = programs.files[0], one.robot = programs.labels[0];
    return one;
  }
  launch::compileAssignedPrograms(request, programs);
  // Which program is the one under test (with --spec, the submission).
  std::optional<std::size_t> under;
  for (std::size_t p = 0; p < programs.files.size() && !request.file.empty(); ++p)
    if (programs.files[p] == request.file) under = p;
  if (grading && request.robot.empty()) {
    r.status = TestStatus::Error;
    r.problems.push_back({settingsFile, {}, diag::Severity::Error,
                          fmt::format("the cell runs several robots ({}): the scenario file must say which one a "
                                      "submission is",
                                      launch::robotLabelsOf(*programs.cell)),
                          {}, "add 'test: robot LABEL' before the first scenario"});
    return made();
  }
  keepSources(programs, grading, r);
  std::vector<diag::Diagnostic> cellProblems = programs.cellLoad.diagnostics;
  for (std::size_t p = 0; p < programs.loaded.size(); ++p) {
    std::vector<diag::Diagnostic> diags = programs.loaded[p].diagnostics;
    placeAtLines(diags, lines, assignments, files, settingsFile);
    if (under && p == *under) continue;
    cellProblems.insert(cellProblems.end(), diags.begin(), diags.end());
  }
  // A problem outside the program under test (its cell, another robot's
  // program, an unreadable file) means the test cannot start; without a
  // program under test, a program that does not compile fails it.
  for (const diag::Diagnostic& d : cellProblems)
    if (d.severity == diag::Severity::Error) {
      r.status = under.has_value() || d.pos.line == 0 || d.file == settingsFile ? TestStatus::Error : TestStatus::Failed;
      r.problems.push_back(d);
    }
  if (under) {
    const launch::LoadedProgram& mine = programs.loaded[*under];
    for (const diag::Diagnostic& d : mine.diagnostics)
      if (d.severity == diag::Severity::Error && (d.file != request.file || d.pos.line == 0))
        r.status = TestStatus::Error, r.problems.push_back(d);
    if (r.status == TestStatus::Error) return made();
    if (parsed.expectsCompileErrors() || !mine.ok()) {
      matchCompileErrors(parsed.expectations, mine.diagnostics, request.file, grading, r);
      if (parsed.expectsCompileErrors() && mine.ok())
        r.problems.insert(r.problems.begin(), {request.file, {}, diag::Severity::Error,
                                               "the program compiled, but its expect-error lines ask for errors"});
      if (r.status != TestStatus::Error) r.status = r.problems.empty() ? TestStatus::Passed : TestStatus::Failed;
      return made();
    }
  }
  if (!r.problems.empty()) return made();

  const launch::RunRequest request2 =
      runRequestOf(parsed.settings, settingsFile, parsed.expectsCollision(), options, grading);
  std::vector<diag::Diagnostic> runProblems;
  std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, request2, runProblems);
  if (!spec) {
    r.status = TestStatus::Error;
    r.problems = std::move(runProblems);
    return made();
  }
  if (grading) spec->limits.maxStepsPerInstant = kGradingMaxStepsAtOneInstant;
  std::vector<GoldenTrace> traces;
  if (!openGoldenTraces(parsed, settingsFile, traces, r)) return made();
  // --update may make the run again, for its trace.
  std::optional<runtime::CellRunSpec> again;
  if (options.update && !traces.empty()) again = *spec;
  runtime::CellRun cell(std::move(*spec));
  vm::RunOutcome outcome;
  CellChecker checker(cell, outcome, parsed.expectations, under, settingsFile);
  std::vector<runtime::LabelledTrace*> writers;
  for (GoldenTrace& t : traces) labelTraces(cell, *t.stream, t.writers, writers);
  std::vector<std::unique_ptr<CoverageCounter>> counters;  // per program, with --coverage
  if (options.coverage)
    for (std::size_t p = 0; p < cell.size(); ++p) {
      counters.push_back(std::make_unique<CoverageCounter>(cell.robot(p).spec().image));
      cell.observe(p, *counters.back());
    }
  outcome = cell.runToEnd();
  for (std::size_t p = 0; p < counters.size(); ++p) {
    const launch::LoadedProgram& l = programs.loaded[p];
    r.coverage.push_back({programs.files[p], l.source ? std::make_shared<const diag::SourceFile>(*l.source) : nullptr,
                          counters[p]->coverage()});
  }
  for (runtime::LabelledTrace* w : writers) w->finish();
  r.ran = true;
  r.simulated = cell.clock();
  r.steps = 0;
  for (std::size_t p = 0; p < cell.size(); ++p) r.steps += cell.robot(p).interpreter().steps();
  r.expectations = parsed.expectations.size() + (parsed.statesStatus() ? 0 : 1);
  r.problems = checker.check(!parsed.statesStatus());
  for (std::size_t p = 0; p < cell.size(); ++p)
    if (std::optional<diag::Diagnostic> w = runtime::gripperWarning(cell.robot(p), programs.files[p]))
      r.warnings.push_back(std::move(*w));
  hintLimit(outcome, parsed.settings, grading, r);
  const TraceRerun rerun = [&again](std::ostream& out, vm::StepObserver& stop) {
    runtime::CellRun run(*again);
    std::vector<std::unique_ptr<vm::StepObserver>> kept;
    std::vector<runtime::LabelledTrace*> labelled;
    labelTraces(run, out, kept, labelled);
    for (std::size_t p = 0; p < run.size(); ++p) run.observe(p, stop);
    run.runToEnd();
    for (runtime::LabelledTrace* w : labelled) w->finish();
  };
  for (const GoldenTrace& t : traces) judgeTrace(t, again ? &rerun : nullptr, settingsFile, options, r);
  r.status = r.problems.empty() ? TestStatus::Passed : TestStatus::Failed;
  return made();
}

}  // namespace rs::testrun
