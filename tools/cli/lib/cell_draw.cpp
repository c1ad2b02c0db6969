#include "tools/cli/lib/cell_draw.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "base/text.h"
#include "launch/run_diagnostics.h"
#include "runtime/run/cell_log.h"
#include "tools/cli/lib/cell_run_command.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/plot_command.h"
#include "tools/cli/lib/run_warnings.h"

namespace rs::cli {

namespace {

CellDrawChoice failed() {
  CellDrawChoice c;
  c.exit = kExitBadInput;
  return c;
}

std::string baseName(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

}  // namespace

std::optional<CellDrawChoice> chooseCellDraw(const launch::ProgramRequest& given,
                                             std::vector<std::string> assignments, const launch::RunRequest& run,
                                             std::uint64_t defaultMaxSteps, runtime::LineThinning lines,
                                             std::ostream& err) {
  launch::ProgramRequest request = given;
  std::error_code ec;
  if (launch::isProgramAssignment(request.file) && !std::filesystem::exists(request.file, ec))
    assignments.insert(assignments.begin(), request.file), request.file.clear();
  if (request.cell.empty()) {
    if (assignments.empty()) return std::nullopt;
    err << "robotsim: error: LABEL=FILE gives a program to a robot of a cell\n  hint: name the cell with --cell CELL\n";
    return failed();
  }
  if (request.file.empty() && assignments.empty()) {
    // A cell that loads but has no PROGRAMs, and nothing given: the command
    // says what it needs, as always.
    launch::LoadedProgram probe;
    launch::ProgramRequest cellOnly = request;
    cellOnly.robot.clear();
    const std::shared_ptr<const workcell::Workcell> cell = launch::loadCell(cellOnly, probe);
    if (cell && !diag::hasErrors(probe.diagnostics) &&
        std::none_of(cell->robots.begin(), cell->robots.end(),
                     [](const workcell::PlacedRobot& r) { return !r.program.empty(); }))
      return std::nullopt;
  }
  auto draw = std::make_unique<CellDraw>();
  launch::CellPrograms& programs = draw->programs;
  const auto sourceOf = [&programs](const std::string& file) { return programs.sourceOf(file); };
  if (!launch::assignCellPrograms(request, assignments, programs)) {
    // A program alone on a cell that does not load: the run of one says why, as always.
    if (!request.file.empty() && assignments.empty()) return std::nullopt;
    std::vector<diag::Diagnostic> all = programs.allDiagnostics();
    launch::printDiagnostics(err, all, sourceOf, request.maxErrors, {});
    return failed();
  }
  if (programs.programs.empty()) return std::nullopt;
  if (programs.programs.size() == 1) {
    // One robot has a program: the run of one, as always.
    if (!request.file.empty()) return std::nullopt;
    CellDrawChoice c;
    c.one = request;
    c.one->file = programs.files[0], c.one->robot = programs.labels[0];
    return c;
  }
  launch::compileAssignedPrograms(request, programs);
  // Each program's load read the cell again: its warnings are said once.
  std::vector<diag::Diagnostic> diags = programs.diagnosticsOnce();
  std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, run, diags, defaultMaxSteps);
  launch::printDiagnostics(err, diags, sourceOf, request.maxErrors, {});
  if (!spec) return failed();
  draw->spec = std::move(*spec);
  draw->spec.log = true;
  draw->spec.lines = lines;
  CellDrawChoice c;
  c.several = std::move(draw);
  return c;
}

vm::RunOutcome runCellDraw(CellDraw& draw, std::ostream& err, std::optional<vm::Micros> until) {
  if (until) draw.spec.limits.maxTime = *until;
  draw.run = std::make_unique<runtime::CellRun>(draw.spec);
  const vm::RunOutcome outcome = draw.run->runToEnd();
  if (until && outcome.reason == vm::StopReason::TimeLimit) return outcome;  // the moment was reached
  const std::vector<diag::Diagnostic> said = cellRunDiagnostics(*draw.run, outcome, draw.spec.collisions);
  printRunWarnings(err, said, draw.programs.loaded.front());
  return outcome;
}

render::Chart cellChart(const CellDraw& draw, const vm::RunOutcome& outcome, vm::Micros every) {
  const runtime::CellRun& cell = *draw.run;
  std::vector<std::vector<std::uint32_t>> lineOf;  // per robot: what its chart's span looks at
  for (std::size_t p = 0; p < cell.size(); ++p) lineOf.push_back(cell.robot(p).spec().image->lines.toVector());
  // The devices' lanes come from the first robot's log: with every robot's device events.
  const runtime::RunLog first = runtime::cellLogOf(cell, 0);
  render::CellChartInput input;
  input.cell = &cell.cell();
  input.robotLogs.assign(cell.cell().robots.size(), nullptr);
  for (std::size_t p = 0; p < cell.size(); ++p) input.robotLogs[cell.robot(p).rig().robotIndex()] = cell.robot(p).log();
  input.every = every;
  input.title = cellDrawTitle(draw);
  for (std::size_t p = 0; p < cell.size(); ++p) {
    const runtime::Run& run = cell.robot(p);
    // The stop is marked on the robot that stopped the cell, or (a
    // deadlock, the time limit) on the first robot the cell stopped.
    std::string stop;
    if (!outcome.ok()) {
      if (cell.failed() == p) {
        const vm::Image& image = *run.spec().image;
        stop = launch::stopDiagnostic(image, *run.outcome(), image.sourceName).message;
      } else if (!cell.failed()) {
        bool earlier = false;
        for (std::size_t q = 0; q < p; ++q) earlier |= cell.end(q) == runtime::RobotEnd::Stopped;
        if (!earlier && cell.end(p) == runtime::RobotEnd::Stopped) stop = outcome.message;
      }
    }
    input.robots.push_back({cell.label(p), run.rig().robotIndex(), p == 0 ? &first : run.log(), lineOf[p], chartMarks(run, stop)});
  }
  return render::cellChartOf(input);
}

std::string cellDrawTitle(const CellDraw& draw) {
  std::string files;
  for (std::size_t p = 0; p < draw.run->size(); ++p)
    files += (p ? ", " : "") + base::safeText(baseName(draw.run->robot(p).spec().image->sourceName));
  return fmt::format("{} on {}", files, base::safeText(draw.run->cell().name));
}

}  // namespace rs::cli
