#include "launch/program.h"

#include "base/ascii.h"

#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "diag/read_input.h"
#include "launch/cell_directive.h"
#include "launch/robot_choice.h"
#include "model/workcell/cell_file.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"
#include "vm/io_lines.h"

namespace rs::launch {

namespace {

diag::Diagnostic wholeFileError(const std::string& file, std::string message) {
  return {file, {}, diag::Severity::Error, std::move(message)};
}

// The workcell an image carries, checked against the image itself (its
// robot must have exactly the image's motors); an error message, or empty.
std::string decodeImageCell(const vm::Image& image, std::shared_ptr<const workcell::Workcell>& cell) {
  diag::Result<workcell::Workcell> decoded = workcell::decodeCell(image.cell);
  if (!decoded) return decoded.failure().message;
  if (!decoded->drivenRobot()) return "its cell has no robot";
  // The cell section bounds a line's number loosely; the machine's are 1..kIoCount.
  const auto badLine = [](const workcell::Signal& s) {
    return (s.kind == workcell::Signal::Kind::Output || s.kind == workcell::Signal::Kind::Input) &&
           !vm::isIoLine(s.number);
  };
  const workcell::Devices& devices = decoded->devices;
  for (const workcell::Wire& w : devices.wires)
    if (!vm::isIoLine(w.input) || badLine(w.source)) return "cell section: a wire to or from a line the machine lacks";
  for (const workcell::Conveyor& c : devices.conveyors)
    if (badLine(c.run)) return "cell section: a conveyor run by a line the machine lacks";
  for (const workcell::Feeder& f : devices.feeders)
    if (f.when && badLine(*f.when)) return "cell section: a feeder fed by a line the machine lacks";
  // The cell's bytes hold the geometry; how motors accelerate is in the
  // image's motor table alone (an image's 1.1 motion section), so that a
  // cell of constant-speed motors keeps the bytes it always had. The
  // robot takes the image's accelerations and actuation time, then the
  // rest must match exactly.
  workcell::Robot& robot = decoded->drivenRobot()->robot;
  if (robot.joints.size() + (robot.hasGripper ? 1 : 0) == image.motors.size()) {
    for (std::size_t i = 0; i < robot.joints.size(); ++i) robot.joints[i].acceleration = image.motors[i].acceleration;
    if (robot.hasGripper) {
      robot.gripper.acceleration = image.motors.back().acceleration;
      robot.gripper.actuation = image.motors.back().actuation;
    }
  }
  if (compiler::motorTable(robot) != image.motors) return "its cell's robot does not match its motor table";
  cell = std::make_shared<const workcell::Workcell>(std::move(decoded).value());
  return {};
}

// "prog.rsb", "PROG.RSB": what a compiled image is usually called.
bool endsWithImageSuffix(std::string_view path) {
  constexpr std::string_view kSuffix = ".rsb";
  return path.size() >= kSuffix.size() && base::sameName(path.substr(path.size() - kSuffix.size()), kSuffix);
}

// FILE's bytes, or nothing with the reason in `into`.
std::optional<std::string> readBytes(const std::string& path, LoadedProgram& into) {
  diag::Result<std::string> read = diag::readInput(path, kMaxInputBytes, "cannot read file");
  if (!read) {
    into.diagnostics.push_back(read.failure());
    return std::nullopt;
  }
  return std::move(read).value();
}

// The request with its cell: --cell when given, else the program source's
// "; cell:" directive (cell_directive.h), confined for a submission; or
// nothing, with the refusal in `into`.
std::optional<ProgramRequest> withDirective(const ProgramRequest& request, const std::string& bytes,
                                            LoadedProgram& into) {
  ProgramRequest r = request;
  if (!r.cell.empty() || vm::looksLikeImage(bytes)) return r;
  const std::optional<CellDirective> d = findCellDirective(diag::withoutByteOrderMark(bytes));
  if (!d) return r;
  if (!request.submission) {
    r.cell = resolveCellName(request.file, d->name);
    return r;
  }
  diag::Result<SubmissionCell> cell = resolveSubmissionCell(request.file, *d);
  if (!cell) {
    into.source.emplace(request.file, bytes);  // for the caret under the directive
    into.diagnostics.push_back(cell.failure());
    return std::nullopt;
  }
  r.cell = cell->name;
  r.cellFromLibraryOnly = cell->libraryName;
  return r;
}

// Compiles FILE's bytes for `target`, or loads and verifies them when they
// are an image.
void readProgram(const std::string& path, std::string bytes, const compiler::Target& target, LoadedProgram& into) {
  if (vm::looksLikeImage(bytes)) {
    diag::Result<vm::Image> loaded = vm::loadImage(bytes, path);
    if (!loaded)
      into.diagnostics.push_back(loaded.failure());
    else
      into.image = std::make_shared<const vm::Image>(std::move(loaded).value());
    return;
  }
  if (endsWithImageSuffix(path))
    into.diagnostics.push_back({path, {}, diag::Severity::Note,
                                "this is not a compiled image (it does not start with the image magic number); "
                                "compiling it as source"});
  into.source.emplace(path, std::move(bytes));
  compiler::CompileResult compiled = compiler::compile(*into.source, target, into.maxErrors);
  for (diag::Diagnostic& d : compiled.diagnostics) into.diagnostics.push_back(std::move(d));
  into.omitted += compiled.omitted;
  if (compiled.image) into.image = std::make_shared<const vm::Image>(std::move(*compiled.image));
}

bool sameMotors(const vm::Image& image, const workcell::Workcell& cell) {
  const workcell::PlacedRobot* driven = cell.drivenRobot();
  return driven && image.motors == compiler::motorTable(driven->robot);
}

}  // namespace

compiler::Target defaultTarget() {
  compiler::Target target{std::string(stdlib::rhinoScaraName()), stdlib::rhinoScaraMotors(), vm::kDefaultCallDepth};
  target.cellHint = std::string(stdlib::rhinoScaraCellName());
  return target;
}

compiler::Target cellTarget(const workcell::Workcell& cell) {
  const workcell::PlacedRobot& driven = *cell.drivenRobot();
  const workcell::Robot& robot = driven.robot;
  compiler::Target target{robot.name, compiler::motorTable(robot), vm::kDefaultCallDepth, nullptr};
  if (robot.chain) {
    target.robot = std::make_shared<const workcell::PlacedRobot>(driven);
    target.linePlans = std::make_shared<workcell::LinePlanCache>();
  }
  return target;
}

const diag::SourceFile* LoadedProgram::sourceOf(const std::string& file) const {
  if (source && source->name() == file) return &*source;
  return descriptions ? descriptions->source(file) : nullptr;
}

void printDiagnostics(std::ostream& err, const std::vector<diag::Diagnostic>& diags, const LoadedProgram& program) {
  printDiagnostics(
      err, diags, [&program](const std::string& file) { return program.sourceOf(file); }, program.maxErrors,
      program.omitted);
}

void printDiagnostics(std::ostream& err, std::span<const diag::Diagnostic> diags,
                      const std::function<const diag::SourceFile*(const std::string&)>& sourceOf, std::size_t max,
                      diag::Omitted omitted) {
  const std::size_t shown = max == 0 ? diags.size() : std::min(max, diags.size());
  for (const diag::Diagnostic& d : diags.first(shown)) err << diag::render(d, sourceOf(d.file));
  for (const diag::Diagnostic& d : diags.subspan(shown)) omitted.count(d.severity);
  err << omittedNote(omitted);
}

std::string omittedNote(const diag::Omitted& omitted) {
  if (!omitted.any()) return {};
  const auto count = [](std::size_t n, std::string_view what) {
    return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s");
  };
  const std::string what = omitted.errors == 0     ? count(omitted.warnings, "more warning")
                           : omitted.warnings == 0 ? count(omitted.errors, "more error")
                                                   : fmt::format("{} and {}", count(omitted.errors, "more error"),
                                                                 count(omitted.warnings, "warning"));
  return fmt::format("robotsim: note: {} not shown; --max-errors 0 shows all\n", what);
}

std::shared_ptr<const workcell::Workcell> loadCell(const ProgramRequest& request, LoadedProgram& into) {
  if (const LoadedCell* read = request.loadedCell.get()) {
    into.descriptions = read->descriptions;
    into.diagnostics.insert(into.diagnostics.end(), read->diagnostics.begin(), read->diagnostics.end());
    return read->cell;
  }
  auto library = std::make_shared<compiler::Library>(compiler::librarySearchPath(request.libDirs));
  if (request.cellFromLibraryOnly) library->lookUpNamesOnly();
  into.descriptions = library;
  std::optional<workcell::Workcell> cell = library->workcell(request.cell);
  for (const diag::Diagnostic& d : library->diagnostics()) into.diagnostics.push_back(d);
  if (!cell) return nullptr;
  return std::make_shared<const workcell::Workcell>(std::move(*cell));
}

namespace {

// run, check, compile, disasm: a source compiled for --cell carries that
// cell; an image runs on the cell it carries, and refuses --cell.
void fitToRun(const ProgramRequest& request, LoadedProgram& program) {
  if (!request.cell.empty()) {
    if (program.image && !program.source) {
      program.image.reset();
      program.diagnostics.push_back(
          wholeFileError(request.file, "--cell applies to program sources: a compiled image carries its own cell"));
    }
    if (program.image) {
      auto withCell = std::make_shared<vm::Image>(*program.image);
      withCell->cell = workcell::encodeCell(*program.cell);
      program.image = std::move(withCell);
    }
    return;
  }
  if (program.image && !program.image->cell.empty()) {
    if (const std::string error = decodeImageCell(*program.image, program.cell); !error.empty()) {
      program.diagnostics.push_back(wholeFileError(request.file, "image rejected: " + error));
      program.image.reset();
    }
  }
}

// render, animate: a source needs --cell; an image is drawn on the cell it
// carries, or on --cell's when its robot has the image's motors.
void fitToDraw(const ProgramRequest& request, LoadedProgram& program) {
  if (!program.ok()) return;
  const vm::Image& image = *program.image;
  if (program.source) {
    if (!program.cell) program.diagnostics.push_back(wholeFileError("robotsim", "which workcell? give it with --cell CELL"));
  } else {
    if (!program.cell && !image.cell.empty()) {
      if (const std::string error = decodeImageCell(image, program.cell); !error.empty())
        program.diagnostics.push_back(wholeFileError(request.file, "image rejected: " + error));
    } else if (!program.cell) {
      program.diagnostics.push_back(
          wholeFileError(request.file, "the image carries no workcell; give one with --cell"));
    } else if (!sameMotors(image, *program.cell)) {
      program.diagnostics.push_back(wholeFileError(
          request.file, fmt::format("the image was compiled for robot '{}', whose motors differ from those of '{}'",
                                    image.robotName, program.cell->drivenRobot()->robot.name)));
    }
  }
  if (!program.ok()) program.image.reset();
}

}  // namespace

// The file read, its cell found (--cell or its directive) and loaded, the
// program compiled for that cell's robot or the default one: the same for
// every use; then what the use asks of the program and its cell.
LoadedProgram loadProgram(const ProgramRequest& given, ProgramUse use) {
  LoadedProgram program;
  program.maxErrors = given.maxErrors;
  std::optional<std::string> bytes = readBytes(given.file, program);
  if (!bytes) return program;
  const std::optional<ProgramRequest> directed = withDirective(given, *bytes, program);
  if (!directed) return program;
  const ProgramRequest& request = *directed;
  if (!request.cell.empty()) {
    program.cell = loadCell(request, program);
    if (!program.cell) return program;
    const std::optional<CellDirective> robot =
        vm::looksLikeImage(*bytes) ? std::nullopt : findRobotDirective(diag::withoutByteOrderMark(*bytes));
    program.cell = driveProgramsRobot(program.cell, request, robot, program);
    if (!program.cell) {
      program.source.emplace(request.file, std::move(*bytes));  // for the caret under the directive
      return program;
    }
    if (!program.cell->drivenRobot()) {
      program.diagnostics.push_back(wholeFileError(request.cell, "the workcell has no robot to run the program"));
      return program;
    }
  }
  if (request.cell.empty() && !request.robot.empty()) {
    program.diagnostics.push_back(wholeFileError("--robot", "--robot names a robot of a cell, but the program runs on no cell"));
    program.diagnostics.back().hint = "name the cell with --cell CELL or a '; cell:' line";
    return program;
  }
  readProgram(request.file, std::move(*bytes), program.cell ? cellTarget(*program.cell) : defaultTarget(), program);
  switch (use) {
    case ProgramUse::Run: fitToRun(request, program); break;
    case ProgramUse::Draw: fitToDraw(request, program); break;
  }
  return program;
}

}  // namespace rs::launch
