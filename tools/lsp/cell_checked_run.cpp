#include "tools/lsp/cell_checked_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>

#include "launch/cell_programs.h"
#include "launch/run_diagnostics.h"
#include "launch/run_request.h"
#include "runtime/run/cell_run.h"
#include "tools/lsp/program_analysis.h"
#include "tools/lsp/run_pieces.h"

namespace rs::lsp {

namespace {

std::string_view codeOfCellStop(vm::StopReason reason) {
  switch (reason) {
    case vm::StopReason::Deadlock: return "deadlock";
    case vm::StopReason::TimeLimit: return "time-limit";
    default: return "runtime-error";  // a device's fault
  }
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// One program of the run: the program's own (0) or a partner's (1...).
struct Member {
  std::size_t robot = 0;
  std::string label;
  std::string file;
  std::shared_ptr<const vm::Image> image;
  const ProgramAnalysis* analysis = nullptr;  // null: an image
  bool shownElsewhere = false;  // its own document shows what the run finds in it
};

std::vector<CheckedRun> allEnd(std::size_t n, CheckedRun::End end, std::string summary = {}) {
  std::vector<CheckedRun> out(n);
  for (CheckedRun& r : out) r.end = end, r.summary = summary;
  return out;
}

// The run is not made: a note on the program's first line says why.
std::vector<CheckedRun> notMade(std::size_t n, const std::string& file, const std::string& why, std::string hint) {
  std::vector<CheckedRun> out = allEnd(n, CheckedRun::End::NotRun, "not made (" + why + ")");
  out[0].diagnostics.push_back({file, {}, diag::Severity::Note,
                                fmt::format("not run in the editor: {} (the cell runs every robot's program together)",
                                            why),
                                "run-not-made", std::move(hint)});
  return out;
}

diag::Pos posOf(const vm::Image& image, std::uint32_t index) {
  index = std::min<std::uint32_t>(index, static_cast<std::uint32_t>(image.code.size() - 1));
  return {image.lines[index], image.columns[index]};
}

}  // namespace

std::vector<CheckedRun> checkCellRun(const ProgramAnalysis& analysis, const CellRunPlan& plan,
                                     const RunOptions& options, RunControl& control,
                                     std::chrono::milliseconds budget) {
  const std::size_t n = plan.partners.size() + 1;
  const std::chrono::nanoseconds deadline = threadTime() + budget;
  if (!analysis.image() || control.abandoned() || !plan.cell) return allEnd(n, CheckedRun::End::Abandoned);
  const std::string& self = analysis.source().name();
  if (!plan.problem.empty()) return notMade(n, self, plan.problem, "its diagnostics are in that file");
  std::vector<Member> members;
  members.push_back({plan.robot, plan.cell->robots[plan.robot].labelOf(), self, analysis.image(), &analysis, false});
  for (const CellPartner& p : plan.partners)
    members.push_back({p.robot, p.label, p.analysis ? p.analysis->source().name() : p.file, p.image,
                       p.analysis.get(), !p.uri.empty()});
  // The straight lines of every program, which the editor's compile leaves out.
  if (std::vector<diag::Diagnostic> lines = lineErrors(analysis); !lines.empty()) {
    std::vector<CheckedRun> out = allEnd(n, CheckedRun::End::NotRun, "not made (a straight line cannot be followed)");
    out[0].diagnostics = std::move(lines);
    return out;
  }
  for (std::size_t m = 1; m < n; ++m)
    if (members[m].analysis)
      if (std::vector<diag::Diagnostic> lines = lineErrors(*members[m].analysis); !lines.empty()) {
        std::vector<CheckedRun> out =
            notMade(n, self,
                    fmt::format("robot {}'s program {} has a straight line its arm cannot follow (line {})",
                                members[m].label, fileName(members[m].file), lines.front().pos.line),
                    "its diagnostics are in that file");
        out[m].diagnostics = std::move(lines);
        return out;
      }

  // The spec as `check --cell` makes it, the programs in the cell's robot order.
  std::vector<std::size_t> order(n);  // spec's program k is member order[k]
  for (std::size_t m = 0; m < n; ++m) order[m] = m;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return members[a].robot < members[b].robot; });
  launch::CellPrograms programs;
  programs.cell = plan.cell;
  for (const std::size_t m : order) {
    programs.labels.push_back(members[m].label);
    programs.files.push_back(members[m].file);
    programs.loaded.emplace_back().image = members[m].image;
    programs.programs.push_back({members[m].robot, members[m].image});
  }
  launch::RunRequest request;
  request.collisions = runtime::collisionModeName(options.collisions);
  std::vector<diag::Diagnostic> problems;
  std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, request, problems);
  if (!spec)
    return notMade(n, self, problems.empty() ? std::string("the cell's programs cannot run together") : problems.front().message,
                   problems.empty() ? std::string() : problems.front().hint);
  std::vector<bool> running(plan.cell->robots.size(), false);
  for (const Member& m : members) running[m.robot] = true;
  if (std::optional<CheckedRun> stimuliProblem =
          stimuliBeside(analysis, options, spec->cell.get(), spec->stimuli, &running)) {
    std::vector<CheckedRun> out = allEnd(n, CheckedRun::End::NotRun, stimuliProblem->summary);
    out[0] = std::move(*stimuliProblem);
    return out;
  }

  std::vector<CheckedRun> out(n);
  std::vector<std::unique_ptr<RunTimer>> timers;
  runtime::CellRun cell(*spec);
  std::vector<runtime::Run*> runs;
  for (std::size_t k = 0; k < n; ++k) {
    CheckedRun& r = out[order[k]];
    r.times.resize(members[order[k]].image->code.size());
    r.calls.resize(members[order[k]].image->code.size());
    timers.push_back(std::make_unique<RunTimer>(r.times, r.calls, control, deadline));
    cell.observe(k, *timers.back());
    runs.push_back(&cell.robot(k));
  }
  control.attach(runs);
  const vm::RunOutcome outcome = cell.runToEnd();
  control.attach({});
  const bool outOfTime = std::any_of(timers.begin(), timers.end(), [](const auto& t) { return t->outOfTime(); });
  if (control.abandoned() || (outcome.reason == vm::StopReason::Paused && !outOfTime))
    return allEnd(n, CheckedRun::End::Abandoned);

  std::optional<diag::Diagnostic> ownDeadlock;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t m = order[k];
    const runtime::Run& run = cell.robot(k);
    const vm::Image& image = *members[m].image;
    CheckedRun& r = out[m];
    r.clock = cell.endTime(k);
    r.steps = run.interpreter().steps();
    if (outOfTime) {
      r.end = CheckedRun::End::OutOfBudget;
      r.diagnostics.push_back(budgetNote(run, members[m].file, budget));
      r.summary = fmt::format("still running at {} after {} instructions, when the editor's run of the cell stopped",
                              formatSeconds(r.clock), r.steps);
      continue;
    }
    r.diagnostics = launch::runDiagnostics(run, spec->collisions, members[m].file);
    if (cell.end(k) == runtime::RobotEnd::Finished && run.outcome()) {
      r.outcome = run.outcome();
      r.summary = summaryOf(run, *r.outcome);
      if (cell.failed() == k)
        for (diag::Diagnostic& d : r.diagnostics)
          if (d.severity == diag::Severity::Error)
            d.hint += fmt::format("{}robot {} stopped the cell", d.hint.empty() ? "" : "; ", members[m].label);
      continue;
    }
    // Stopped with the cell, where it was: by another robot's failure, or
    // the cell's own stop (the deadlock names this robot's line too).
    const std::uint32_t at = run.view().instruction;
    vm::RunOutcome stopped = outcome;
    stopped.index = std::min<std::uint32_t>(at, static_cast<std::uint32_t>(image.code.size() - 1));
    r.outcome = stopped;
    r.summary = fmt::format("stopped with the cell at {} (line {}): {}", formatSeconds(r.clock),
                            posOf(image, at).line, outcome.message);
    if (cell.failed()) continue;  // the failing robot's program says why
    diag::Diagnostic d{members[m].file, posOf(image, at), diag::Severity::Error, outcome.message,
                       codeOfCellStop(outcome.reason),
                       outcome.reason == vm::StopReason::Deadlock ? launch::kCellDeadlockHint : ""};
    if (m == 0 && outcome.reason == vm::StopReason::Deadlock) ownDeadlock = d;
    r.diagnostics.insert(r.diagnostics.begin(), std::move(d));
  }

  // What no other document shows is said here, at this robot's line when
  // the cell stopped it there, else on the first line.
  const diag::Pos here = out[0].stoppedAt() ? posOf(*members[0].image, *out[0].stoppedAt()) : diag::Pos{};
  for (std::size_t m = 1; m < n; ++m) {
    if (members[m].shownElsewhere) continue;
    for (const diag::Diagnostic& d : out[m].diagnostics) {
      if (ownDeadlock && d.code == "deadlock") continue;  // its message names every waiting robot already
      diag::Diagnostic moved = d;
      moved.file = self;
      moved.pos = here;
      moved.message = fmt::format("robot {} ({}:{}): {}", members[m].label, fileName(members[m].file), d.pos.line,
                                  d.message);
      moved.related.push_back({members[m].file, d.pos, fmt::format("in robot {}'s program", members[m].label)});
      out[0].diagnostics.push_back(std::move(moved));
    }
  }
  return out;
}

}  // namespace rs::lsp
