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
#include "tools/testrun/evaluate.h"
#include "tools/testrun/run_watch.h"
#include "tools/testrun/test_steps.h"

namespace rs::testrun {

namespace {

// What a robot's own run answers (the rest is the cell's): a prefix names
// the robot, and without one they are the program under test's robot's.
bool robotsOwn(ExpectKind kind) {
  switch (kind) {
    case ExpectKind::Motors:
    case ExpectKind::MotorBound:
    case ExpectKind::Output:
    case ExpectKind::Input:
    case ExpectKind::Pulses:
    case ExpectKind::Order:
    case ExpectKind::Variable:
    case ExpectKind::Tcp: return true;
    default: return false;
  }
}

// The robots that run a program here, for a hint: "`feeder`, `packer`".
std::string runningLabels(const runtime::CellRun& cell) {
  std::string out;
  for (std::size_t p = 0; p < cell.size(); ++p)
    out += fmt::format("{}`{}`", out.empty() ? "" : ", ", base::safeText(cell.label(p)));
  return out;
}

// How robot `p` ended: its own outcome, or, stopped with the cell, the
// cell's reason at the instruction it was at.
RunEnd robotEnd(const runtime::CellRun& cell, std::size_t p, const vm::RunOutcome& cellOutcome) {
  const runtime::Run& run = cell.robot(p);
  RunEnd end;
  end.robot = cell.label(p);
  end.at = cell.endTime(p);
  if (cell.end(p) == runtime::RobotEnd::Stopped || !run.outcome()) {
    end.outcome.reason = cellOutcome.reason;
    end.outcome.message = cellOutcome.message;
    end.outcome.index = run.view().instruction;
    end.stopped = cell.failed().has_value();
    end.line = run.view().line;
    return end;
  }
  end.outcome = *run.outcome();
  end.line = run.spec().image->lines[end.outcome.index];
  return end;
}

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

// An order between two robots' lines: the expectation, each robot and
// the place of its event in its watch.
struct CrossOrder {
  std::size_t expectation, first, firstAt, second, secondAt;
};

// Checks the expectations against the finished cell run.
class CellChecker {
 public:
  CellChecker(const runtime::CellRun& cell, const vm::RunOutcome& outcome, const std::vector<Expectation>& all,
              std::optional<std::size_t> under, const std::string& file)
      : cell_(cell), outcome_(outcome), all_(all), under_(under), file_(file), own_(cell.size()), events_(cell.size()) {
    for (std::size_t i = 0; i < all.size(); ++i) route(i);
  }

  // Watches each robot's run for its own expectations (before the run).
  void watch(runtime::CellRun& cell) {
    watches_.resize(cell.size());
    eventWatches_.resize(cell.size());
    for (std::size_t p = 0; p < cell.size(); ++p) {
      if (RunWatch::needed(own_[p])) {
        watches_[p] = std::make_unique<RunWatch>(cell.robot(p), own_[p]);
        cell.observe(p, *watches_[p]);
      }
      if (!events_[p].empty()) {
        eventWatches_[p] = std::make_unique<RunWatch>(cell.robot(p), events_[p]);
        cell.observe(p, *eventWatches_[p]);
      }
    }
  }

  // After the run: every expectation, in the order written.
  std::vector<diag::Diagnostic> check(bool impliedFinished) {
    cellEnd_.outcome = outcome_;
    cellEnd_.at = cell_.clock();
    std::vector<diag::Diagnostic> out = problems_;
    for (std::size_t p = 0; p < cell_.size(); ++p) {
      const RunEnd end = robotEnd(cell_, p, outcome_);
      if (watches_.size() > p && watches_[p]) watches_[p]->finish(end.outcome);
      if (eventWatches_.size() > p && eventWatches_[p]) eventWatches_[p]->finish(end.outcome);
      const std::vector<diag::Diagnostic> said =
          evaluate(cell_.robot(p), end, own_[p], file_, false, watches_.size() > p ? watches_[p].get() : nullptr);
      out.insert(out.end(), said.begin(), said.end());
    }
    for (const Expectation& e : cellOwn_) cellExpectation(e, out);
    for (const CrossOrder& c : crosses_) crossOrder(c, out);
    std::stable_sort(out.begin(), out.end(),
                     [](const diag::Diagnostic& a, const diag::Diagnostic& b) {
                       return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.col < b.pos.col;
                     });
    if (impliedFinished && !outcome_.ok()) out.insert(out.begin(), impliedEnd());
    return out;
  }

 private:
  // Which robot's run answers expectation i, or the cell.
  void route(std::size_t i) {
    const Expectation& e = all_[i];
    if (e.kind == ExpectKind::CompileError || e.kind == ExpectKind::Trace) return;  // not the run's alone
    std::optional<std::size_t> robot;
    if (!e.robot.empty()) {
      robot = robotOf(e, e.robot, e.robotCol);
      if (!robot) return;
    } else if (robotsOwn(e.kind)) {
      if (!under_) {
        problems_.push_back({file_, e.pos, diag::Severity::Error,
                             fmt::format("a cell of several robots runs here: say whose {} this is, as in "
                                         "'LABEL.{}'",
                                         e.kind == ExpectKind::Variable ? "variable" : "line or motor", e.text),
                             {}, fmt::format("the robots with a program: {}", runningLabels(cell_))});
        return;
      }
      robot = under_;
    }
    if (!robot) return cellOwn_.push_back(e);
    Expectation mine = e;
    mine.robot.clear();
    if (!e.secondRobot.empty()) {
      const std::optional<std::size_t> second = robotOf(e, e.secondRobot, e.secondRobotCol);
      if (!second) return;
      mine.secondRobot.clear();
      if (*second != *robot) {
        // Each robot's watch gives when its own event first happened.
        Expectation first = mine, then = mine;
        first.second = first.first;
        then.first = then.second;
        crosses_.push_back({i, *robot, events_[*robot].size(), *second, events_[*second].size()});
        events_[*robot].push_back(std::move(first));
        events_[*second].push_back(std::move(then));
        return;
      }
    }
    own_[*robot].push_back(std::move(mine));
  }

  // The program of robot `label`, or a problem at its column.
  std::optional<std::size_t> robotOf(const Expectation& e, const std::string& label, std::uint32_t col) {
    for (std::size_t p = 0; p < cell_.size(); ++p)
      if (base::sameName(cell_.label(p), label)) return p;
    unknownRobot(e, label, col);
    return std::nullopt;
  }

  void unknownRobot(const Expectation& e, const std::string& label, std::uint32_t col) {
    const runtime::CellRun& c = cell_;
    const bool inCell = c.cell().robotLabeled(label) != workcell::kNoIndex;
    diag::Diagnostic d{file_, {e.pos.line, col}, diag::Severity::Error,
                       inCell ? fmt::format("robot {} runs no program in this scenario: it has no run to check",
                                            base::safeText(label))
                              : fmt::format("workcell {} has no robot labelled `{}`", base::safeText(c.cell().name),
                                            base::safeText(label)),
                       "unknown-robot",
                       inCell ? fmt::format("the robots with a program: {}", runningLabels(c))
                              : fmt::format("the cell's robots are {}", launch::robotLabelsOf(c.cell()))};
    problems_.push_back(std::move(d));
  }

  // One of the cell's expectations: its end and time, objects, devices, collisions.
  void cellExpectation(const Expectation& e, std::vector<diag::Diagnostic>& out) {
    const std::vector<Expectation> one{e};
    const auto on = [&](std::size_t p) { return evaluate(cell_.robot(p), cellEnd_, one, file_, false, nullptr); };
    // Held by any robot's gripper, not held by any; no collision of any
    // robot; a collision with NAME of one of them.
    const bool any = (e.kind == ExpectKind::ObjectHeld && e.on) || e.kind == ExpectKind::CollidesWith;
    const bool every = (e.kind == ExpectKind::ObjectHeld && !e.on) || e.kind == ExpectKind::NoCollision;
    if (!any && !every) {
      const std::vector<diag::Diagnostic> said = on(0);  // the world, the devices and the clock are the cell's
      out.insert(out.end(), said.begin(), said.end());
      return;
    }
    std::vector<diag::Diagnostic> first;
    for (std::size_t p = 0; p < cell_.size(); ++p) {
      std::vector<diag::Diagnostic> said = on(p);
      if (said.empty() && any) return;
      // Of a collision expected: the robot whose run had one says best what happened.
      const bool better = e.kind == ExpectKind::CollidesWith && !cell_.robot(p).rig().collisions().empty() &&
                          (first.empty() || cell_.robot(0).rig().collisions().empty());
      if (!said.empty() && (first.empty() || better)) first = std::move(said);
      if (!first.empty() && every) break;
    }
    out.insert(out.end(), first.begin(), first.end());
  }

  // `left.output 1 on before right.input 1 on`: each robot's event when it first happened.
  void crossOrder(const CrossOrder& c, std::vector<diag::Diagnostic>& out) const {
    const Expectation& e = all_[c.expectation];
    const std::optional<vm::Micros> a = eventWatches_[c.first]->answer(c.firstAt).first;
    const std::optional<vm::Micros> b = eventWatches_[c.second]->answer(c.secondAt).first;
    const auto text = [&](std::size_t p, const LineEvent& ev) {
      return fmt::format("{}.{} {} {}", base::safeText(cell_.label(p)), ev.output ? "output" : "input", ev.number,
                         ev.on ? "ON" : "OFF");
    };
    const std::string first = text(c.first, e.first), second = text(c.second, e.second);
    const std::string want = fmt::format("expected {} before {}", first, second);
    if (!a)
      out.push_back({file_, e.pos, diag::Severity::Error,
                     fmt::format("{}; {} never happened (the run ended at {} s)", want, first,
                                 base::formatSeconds(cell_.clock()))});
    else if (b && *b <= *a)
      out.push_back({file_, e.pos, diag::Severity::Error,
                     fmt::format("{}; {} came {}, at {} s ({} at {} s)", want, second, *b == *a ? "at the same time" : "first",
                                 base::formatSeconds(*b), first, base::formatSeconds(*a))});
  }

  // A scenario that states no end must finish: else a failure at the line
  // of the robot that stopped the cell (or of the first still running).
  diag::Diagnostic impliedEnd() const {
    std::size_t p = 0;
    if (cell_.failed()) p = *cell_.failed();
    else
      while (p + 1 < cell_.size() && cell_.end(p) != runtime::RobotEnd::Stopped) ++p;
    const RunEnd end = robotEnd(cell_, p, outcome_);
    std::vector<diag::Diagnostic> said = evaluate(cell_.robot(p), end, {}, file_, true, nullptr);
    diag::Diagnostic d = said.empty() ? diag::Diagnostic{file_, {}, diag::Severity::Error, outcome_.message}
                                      : said.front();
    d.file = cell_.robot(p).spec().image->sourceName;
    return d;
  }

  const runtime::CellRun& cell_;
  const vm::RunOutcome& outcome_;
  const std::vector<Expectation>& all_;
  std::optional<std::size_t> under_;
  const std::string& file_;
  RunEnd cellEnd_;
  std::vector<std::vector<Expectation>> own_;  // per program: its robot's expectations, prefix taken off
  std::vector<Expectation> cellOwn_;
  std::vector<diag::Diagnostic> problems_;  // found before the run: a robot that is not there
  std::vector<std::unique_ptr<RunWatch>> watches_;
  std::vector<CrossOrder> crosses_;
  std::vector<std::vector<Expectation>> events_;  // per program: the events of crosses_ it watches
  std::vector<std::unique_ptr<RunWatch>> eventWatches_;
};

// Every text a problem may point into: the programs, and (outside
// grading, which quotes no line of a description) the cell's files.
void keepSources(const launch::CellPrograms& programs, bool grading, TestResult& r) {
  const auto keep = [&](const diag::SourceFile& s) {
    if (!r.sourceOf(s.name())) r.sources.push_back(std::make_shared<const diag::SourceFile>(s));
  };
  for (const launch::LoadedProgram& l : programs.loaded)
    if (l.source) keep(*l.source);
  if (grading) return;
  std::vector<diag::Diagnostic> all = programs.cellLoad.diagnostics;
  for (const launch::LoadedProgram& l : programs.loaded) all.insert(all.end(), l.diagnostics.begin(), l.diagnostics.end());
  for (const diag::Diagnostic& d : all)
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
    std::vector<diag::Diagnostic> all = programs.cellLoad.diagnostics;
    for (const launch::LoadedProgram& l : programs.loaded) all.insert(all.end(), l.diagnostics.begin(), l.diagnostics.end());
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
  checker.watch(cell);
  std::vector<runtime::LabelledTrace*> writers;
  for (GoldenTrace& t : traces) labelTraces(cell, *t.stream, t.writers, writers);
  outcome = cell.runToEnd();
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
