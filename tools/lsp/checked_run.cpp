#include "tools/lsp/checked_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <time.h>

#include "compiler/program/line_check.h"
#include "launch/stimuli_robots.h"
#include "launch/program.h"
#include "launch/run_diagnostics.h"
#include "launch/run_request.h"
#include "tools/lsp/program_analysis.h"
#include "runtime/run/run.h"
#include "compiler/stimuli/stimuli.h"

namespace rs::lsp {

namespace {

// The CPU time of the calling thread: the run's budget is the work the
// worker's thread does, whatever else the machine is doing meanwhile (a
// wall-clock budget ran out on a loaded machine before the work did).
std::chrono::nanoseconds threadTime() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return std::chrono::seconds(t.tv_sec) + std::chrono::nanoseconds(t.tv_nsec);
}

// Notes when each instruction first starts and ends, how often it runs and
// for how long, and how long each call of a subroutine takes (a stack of
// the calls under way, as the interpreter's); pauses the run when it is
// abandoned or out of time (the thread's clock read every kClockEvery
// steps: a step costs nanoseconds, a read hundreds; and every
// kClockEveryKnots knots, since one straight line is a step of thousands
// of moves).
class Timer final : public vm::StepObserver {
 public:
  static constexpr std::uint64_t kClockEvery = 1024;
  static constexpr std::uint64_t kClockEveryKnots = 4096;

  Timer(std::vector<InstructionTimes>& times, std::vector<CallTimes>& calls, const RunControl& control,
        std::chrono::nanoseconds deadline)
      : times_(times), calls_(calls), control_(control), deadline_(deadline) {}
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override {
    const vm::Micros now = vm.machine().now();
    if (index < times_.size()) {
      InstructionTimes& t = times_[index];
      if (t.runs++ == 0) t.start = before_, t.end = now;
      t.total += now - before_;
      const vm::Op op = vm.image().code[index].op;
      if (vm::has(op, vm::kCalls) && vm.callDepth() > underWay_.size()) underWay_.push_back({vm.pc(), before_});
      if (vm::has(op, vm::kReturns) && !underWay_.empty() && vm.callDepth() < underWay_.size()) {
        const Call c = underWay_.back();
        underWay_.pop_back();
        if (c.entry < calls_.size()) {
          CallTimes& ct = calls_[c.entry];
          const vm::Micros took = now - c.start;
          ct.shortest = ct.calls == 0 ? took : std::min(ct.shortest, took);
          ct.longest = std::max(ct.longest, took);
          ++ct.calls;
          ct.total += took;
        }
      }
    }
    before_ = now;
    if (control_.abandoned()) return true;
    const std::uint64_t knots = vm.machine().knots();
    if (++steps_ % kClockEvery == 0 || knots >= knotsRead_ + kClockEveryKnots) {
      knotsRead_ = knots;
      if (threadTime() >= deadline_) outOfTime_ = true;
    }
    return outOfTime_;
  }
  bool outOfTime() const { return outOfTime_; }

 private:
  struct Call {
    std::uint32_t entry = 0;  // the subroutine's first instruction
    vm::Micros start = 0;
  };
  std::vector<InstructionTimes>& times_;
  std::vector<CallTimes>& calls_;
  std::vector<Call> underWay_;
  const RunControl& control_;
  std::chrono::nanoseconds deadline_;
  vm::Micros before_ = 0;
  std::uint64_t steps_ = 0;
  std::uint64_t knotsRead_ = 0;
  bool outOfTime_ = false;
};

std::string summaryOf(const runtime::Run& run, const vm::RunOutcome& outcome) {
  const std::string at = formatSeconds(run.rig().clock());
  const std::uint32_t line = run.spec().image->lines[outcome.index];
  switch (outcome.reason) {
    case vm::StopReason::End: return fmt::format("finished at {}", at);
    case vm::StopReason::RuntimeError:
      return fmt::format("stopped by an error at {} (line {}: {})", at, line, outcome.message);
    case vm::StopReason::Deadlock: return fmt::format("waits forever for an input at {} (line {})", at, line);
    case vm::StopReason::StepLimit:
    case vm::StopReason::TimeLimit:
    case vm::StopReason::InstantLimit:
    case vm::StopReason::KnotLimit:
      return fmt::format("stopped by the {} at {} (line {})", vm::stopReasonName(outcome.reason), at, line);
    default: break;  // paused
  }
  return {};
}

// The run stopped by the editor's budget: a note where it stopped, so
// that no line is left looking checked when it was not.
diag::Diagnostic budgetNote(const runtime::Run& run, const std::string& file, std::chrono::milliseconds budget) {
  const auto last = static_cast<std::uint32_t>(run.spec().image->code.size() - 1);
  const std::uint32_t index = std::min(run.interpreter().pc(), last);
  return {file,
          {run.spec().image->lines[index], run.spec().image->columns[index]},
          diag::Severity::Note,
          fmt::format("the editor's run stopped here after {} s of checking ({} instructions, {} simulated), before "
                      "the program ended: what comes after is not checked in the editor",
                      static_cast<double>(budget.count()) / 1000.0, run.interpreter().steps(), formatSeconds(run.rig().clock())),
          "run-not-finished",
          "robotsim check runs it to its end"};
}

}  // namespace

std::optional<std::uint32_t> CheckedRun::stoppedAt() const {
  if (!outcome || outcome->ok()) return std::nullopt;
  return outcome->index;
}

void RunControl::abandon() {
  abandoned_.store(true, std::memory_order_relaxed);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (run_) run_->requestPause();
}

void RunControl::attach(runtime::Run* run) {
  const std::lock_guard<std::mutex> lock(mutex_);
  run_ = run;
}

CheckedRun checkRun(const ProgramAnalysis& analysis, const RunOptions& options, RunControl& control,
                    std::chrono::milliseconds budget) {
  CheckedRun out;
  const std::chrono::nanoseconds deadline = threadTime() + budget;
  if (!analysis.image() || control.abandoned()) {
    out.end = CheckedRun::End::Abandoned;
    return out;
  }
  const compiler::Target& target = analysis.cell().target;
  if (!target.checkLines && target.robot && target.robot->robot.chain) {
    diag::Diagnostics lines(analysis.source().name(), kMaxDiagnostics);
    compiler::checkLinePaths(*analysis.image(), *target.robot, lines, target.linePlans.get());
    if (lines.hasErrors()) {
      out.end = CheckedRun::End::NotRun;
      out.diagnostics = lines.sorted();
      out.summary = "not made (a straight line cannot be followed)";
      return out;
    }
  }
  // The spec as `check` makes it, from the same function.
  launch::LoadedProgram program;
  program.image = analysis.image();
  program.cell = analysis.cell().cell;
  launch::RunRequest request;
  request.collisions = runtime::collisionModeName(options.collisions);
  std::vector<diag::Diagnostic> problems;
  std::optional<runtime::RunSpec> spec = launch::prepareRun(program, request, problems);
  if (!spec) {
    out.end = CheckedRun::End::Abandoned;
    return out;
  }
  // The stimuli file beside the program, from the editor's text when it
  // holds one (check would read the saved file).
  if (options.stimuliText || !options.stimuliPath.empty()) {
    diag::Result<stimuli::Stimuli> parsed = options.stimuliText
                                                ? stimuli::parseStimuli(*options.stimuliText, options.stimuliFile)
                                                : stimuli::loadStimuliFile(options.stimuliPath);
    if (!parsed) {
      out.end = CheckedRun::End::NotRun;
      out.diagnostics.push_back({analysis.source().name(), {}, diag::Severity::Note,
                                 fmt::format("not run in the editor: the stimuli file beside it, {}, has errors",
                                             options.stimuliFile),
                                 "run-not-made", "its diagnostics are in that file"});
      out.summary = "not made (its stimuli file has errors)";
      return out;
    }
    spec->stimuli = std::move(parsed).value();
    std::vector<diag::Diagnostic> placing;  // an unknown robot's label is the stimuli file's error
    if (!launch::placeStimuliOnRobots(spec->cell.get(), options.stimuliFile, spec->stimuli, placing)) {
      out.end = CheckedRun::End::NotRun;
      const diag::Diagnostic& first = *std::find_if(placing.begin(), placing.end(), [](const diag::Diagnostic& d) {
        return d.severity == diag::Severity::Error;
      });
      out.diagnostics.push_back({analysis.source().name(), {}, diag::Severity::Note,
                                 fmt::format("not run in the editor: the stimuli file beside it, {}, at line {}: {}",
                                             options.stimuliFile, first.pos.line, first.message),
                                 "run-not-made", first.hint});
      out.summary = "not made (its stimuli file names an unknown robot)";
      return out;
    }
  }
  out.times.resize(spec->image->code.size());
  out.calls.resize(spec->image->code.size());
  Timer timer(out.times, out.calls, control, deadline);
  runtime::Run run(*spec);
  run.observe(timer);
  control.attach(&run);
  vm::RunOutcome outcome = run.runToEnd();
  control.attach(nullptr);
  out.clock = run.rig().clock();
  out.steps = run.interpreter().steps();
  if (run.finished()) {
    out.outcome = outcome;
    out.diagnostics = launch::runDiagnostics(run, spec->collisions, analysis.source().name());
    out.summary = summaryOf(run, outcome);
  } else if (control.abandoned() || !timer.outOfTime()) {
    out.end = CheckedRun::End::Abandoned;
  } else {
    out.end = CheckedRun::End::OutOfBudget;
    out.diagnostics.push_back(budgetNote(run, analysis.source().name(), budget));
    out.summary = fmt::format("still running at {} after {} instructions, when the editor's run stopped",
                              formatSeconds(out.clock), out.steps);
  }
  return out;
}

}  // namespace rs::lsp
