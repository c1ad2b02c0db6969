#include "tools/lsp/checked_run.h"

#include <fmt/format.h>

#include "launch/program.h"
#include "launch/run_diagnostics.h"
#include "launch/run_request.h"
#include "runtime/run/run.h"
#include "tools/lsp/program_analysis.h"
#include "tools/lsp/run_pieces.h"

namespace rs::lsp {

std::optional<std::uint32_t> CheckedRun::stoppedAt() const {
  if (!outcome || outcome->ok()) return std::nullopt;
  return outcome->index;
}

void RunControl::abandon() {
  abandoned_.store(true, std::memory_order_relaxed);
  const std::lock_guard<std::mutex> lock(mutex_);
  for (runtime::Run* run : runs_) run->requestPause();
}

void RunControl::attach(std::vector<runtime::Run*> runs) {
  const std::lock_guard<std::mutex> lock(mutex_);
  runs_ = std::move(runs);
}

CheckedRun checkRun(const ProgramAnalysis& analysis, const RunOptions& options, RunControl& control,
                    std::chrono::milliseconds budget) {
  CheckedRun out;
  const std::chrono::nanoseconds deadline = threadTime() + budget;
  if (!analysis.image() || control.abandoned()) {
    out.end = CheckedRun::End::Abandoned;
    return out;
  }
  if (std::vector<diag::Diagnostic> lines = lineErrors(analysis); !lines.empty()) {
    out.end = CheckedRun::End::NotRun;
    out.diagnostics = std::move(lines);
    out.summary = "not made (a straight line cannot be followed)";
    return out;
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
  if (std::optional<CheckedRun> notMade = stimuliBeside(analysis, options, spec->cell.get(), spec->stimuli))
    return std::move(*notMade);
  out.times.resize(spec->image->code.size());
  out.calls.resize(spec->image->code.size());
  RunTimer timer(out.times, out.calls, control, deadline);
  runtime::Run run(*spec);
  run.observe(timer);
  control.attach({&run});
  vm::RunOutcome outcome = run.runToEnd();
  control.attach({});
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
