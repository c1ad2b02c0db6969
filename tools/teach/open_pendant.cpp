#include "tools/teach/open_pendant.h"

#include "base/file_io.h"
#include "launch/cell_directive.h"
#include "vm/image_file.h"

namespace rs::teach {

namespace {
diag::Diagnostic error(const std::string& file, std::string message, std::string hint = {}) {
  diag::Diagnostic d{file, {}, diag::Severity::Error, std::move(message)};
  d.hint = std::move(hint);
  return d;
}
}  // namespace

OpenedPendant openPendant(const TeachRequest& request) {
  OpenedPendant out;
  diag::Result<ProgramFile> file = ProgramFile::load(request.program.file);
  if (!file) {
    out.diagnostics.push_back(file.failure());
    return out;
  }
  const std::string text = file->points().text();
  if (vm::looksLikeImage(text)) {
    out.diagnostics.push_back(error(request.program.file, "teach edits a program's source: this is a compiled image",
                                    "teach the .rsp file it was compiled from"));
    return out;
  }
  launch::ProgramRequest cellRequest = request.program;
  if (cellRequest.cell.empty())
    if (const std::optional<launch::CellDirective> d = launch::findCellDirective(text))
      cellRequest.cell = launch::resolveCellName(request.program.file, d->name);
  if (cellRequest.cell.empty()) {
    out.diagnostics.push_back(error("--cell", "teach needs a workcell to move the robot in",
                                    "name one with --cell (robotsim teach PROG.rsp --cell scara-pick), or put a "
                                    "'; cell: NAME' line in the program"));
    return out;
  }
  std::shared_ptr<const workcell::Workcell> cell = launch::loadCell(cellRequest, out.loaded);
  for (const diag::Diagnostic& d : out.loaded.diagnostics) out.diagnostics.push_back(d);
  if (!cell) return out;
  if (cell->robots.empty()) {
    out.diagnostics.push_back(error(cellRequest.cell, "the workcell has no robot to teach"));
    return out;
  }
  std::vector<vm::MotorSpec> motors = launch::cellTarget(*cell).motors;
  if (request.serial.active()) {
    std::unique_ptr<rhino::RhinoMachine> device =
        launch::openRhino(request.serial, motors, vm::Micros{3600} * 1'000'000, out.diagnostics);
    if (!device) return out;
    out.pendant = std::make_unique<Pendant>(cell, std::move(motors), std::move(*file), std::move(device),
                                            request.serial.device);
  } else {
    out.pendant = std::make_unique<Pendant>(cell, std::move(motors), std::move(*file));
  }
  return out;
}

}  // namespace rs::teach
