#include "tools/lsp/run_pieces.h"

#include <fmt/format.h>

#include <algorithm>
#include <time.h>

#include "compiler/program/line_check.h"
#include "launch/stimuli_robots.h"
#include "runtime/run/run.h"
#include "tools/lsp/program_analysis.h"

namespace rs::lsp {

std::chrono::nanoseconds threadTime() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return std::chrono::seconds(t.tv_sec) + std::chrono::nanoseconds(t.tv_nsec);
}

bool RunTimer::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
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

std::vector<diag::Diagnostic> lineErrors(const ProgramAnalysis& analysis) {
  const compiler::Target& target = analysis.cell().target;
  if (target.checkLines || !target.robot || !target.robot->robot.chain) return {};
  diag::Diagnostics lines(analysis.source().name(), kMaxDiagnostics);
  compiler::checkLinePaths(*analysis.image(), *target.robot, lines, target.linePlans.get());
  if (!lines.hasErrors()) return {};
  return lines.sorted();
}

std::optional<CheckedRun> stimuliBeside(const ProgramAnalysis& analysis, const RunOptions& options,
                                        const workcell::Workcell* cell, stimuli::Stimuli& into,
                                        const std::vector<bool>* running) {
  if (!options.stimuliText && options.stimuliPath.empty()) return std::nullopt;
  diag::Result<stimuli::Stimuli> parsed = options.stimuliText
                                              ? stimuli::parseStimuli(*options.stimuliText, options.stimuliFile)
                                              : stimuli::loadStimuliFile(options.stimuliPath);
  CheckedRun out;
  out.end = CheckedRun::End::NotRun;
  if (!parsed) {
    out.diagnostics.push_back({analysis.source().name(), {}, diag::Severity::Note,
                               fmt::format("not run in the editor: the stimuli file beside it, {}, has errors",
                                           options.stimuliFile),
                               "run-not-made", "its diagnostics are in that file"});
    out.summary = "not made (its stimuli file has errors)";
    return out;
  }
  into = std::move(parsed).value();
  std::vector<diag::Diagnostic> placing;  // an unknown robot's label is the stimuli file's error
  if (launch::placeStimuliOnRobots(cell, options.stimuliFile, into, placing, running)) return std::nullopt;
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

}  // namespace rs::lsp
