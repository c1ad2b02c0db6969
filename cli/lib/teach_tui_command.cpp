#include "cli/lib/teach_tui_command.h"

#include <fmt/format.h>

#include "cli/lib/exit_codes.h"
#include "launch/cell_directive.h"
#include "teach/pendant.h"
#include "teach/program_file.h"
#include "teach/tui/tui_curses.h"

namespace rs::cli {

namespace {

// The pendant never waits for an input (no WAITFOR): run's default limit.
constexpr vm::Micros kWaitLimit = 3600LL * 1'000'000;

// The cell: --cell, else the program's "; cell: NAME" line. The program
// need not compile (its MOVEP may name a point not taught yet).
std::shared_ptr<const workcell::Workcell> cellFor(const TeachOptions& o, const teach::ProgramFile& file,
                                                  std::ostream& err) {
  launch::ProgramRequest request = o.program;
  if (request.cell.empty())
    if (const std::optional<launch::CellDirective> d = launch::findCellDirective(file.points().text()))
      request.cell = launch::resolveCellName(request.file, d->name);
  if (request.cell.empty()) {
    err << fmt::format("{}: error: teach needs a workcell\nhint: give --cell CELL, or a '; cell: NAME' line in the "
                       "program\n",
                       o.program.file);
    return nullptr;
  }
  launch::LoadedProgram loaded;
  std::shared_ptr<const workcell::Workcell> cell = launch::loadCell(request, loaded);
  launch::printDiagnostics(err, loaded.diagnostics, loaded);
  if (cell && cell->robots.empty()) {
    err << fmt::format("{}: error: the workcell has no robot to teach\n", request.cell);
    return nullptr;
  }
  return cell;
}

}  // namespace

int teachTuiCommand(const TeachOptions& o, std::ostream&, std::ostream& err) {
  std::string error;
  std::optional<teach::ProgramFile> file = teach::ProgramFile::load(o.program.file, error);
  if (!file) {
    err << fmt::format("{}: error: {}\n", o.program.file, error);
    return kExitBadInput;
  }
  const std::shared_ptr<const workcell::Workcell> cell = cellFor(o, *file, err);
  if (!cell) return kExitBadInput;
  std::vector<vm::MotorSpec> motors = launch::cellTarget(*cell).motors;
  std::unique_ptr<teach::Pendant> pendant;
  if (o.serial.active()) {
    std::vector<diag::Diagnostic> problems;
    std::unique_ptr<vm::Machine> rhino = launch::openRhino(o.serial, motors, kWaitLimit, problems);
    launch::printDiagnostics(err, problems, launch::LoadedProgram{});
    if (!rhino) return kExitBadInput;
    pendant = std::make_unique<teach::Pendant>(cell, motors, std::move(*file), std::move(rhino), o.serial.device);
  } else {
    pendant = std::make_unique<teach::Pendant>(cell, motors, std::move(*file));
  }
  const teach::tui::TuiEnd end = teach::tui::runTerminalPendant(*pendant);
  if (!end.error.empty()) {
    err << "robotsim: error: " << end.error << '\n';
    return kExitBadInput;
  }
  return end.signal == 0 ? kExitOk : 128 + end.signal;
}

}  // namespace rs::cli
