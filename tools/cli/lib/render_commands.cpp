#include "tools/cli/lib/render_commands.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "base/file_io.h"
#include "base/seconds.h"
#include "base/text.h"
#include "tools/cli/lib/cell_draw_commands.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"
#include "tools/cli/lib/options.h"
#include "tools/cli/lib/plot_command.h"
#include "tools/cli/lib/report.h"
#include "tools/cli/lib/run_warnings.h"
#include "launch/cell_programs.h"
#include "launch/run_diagnostics.h"
#include "runtime/render/animation.h"
#include "runtime/render/collision_marks.h"
#include "runtime/run/empty_close.h"
#include "runtime/render/draw.h"
#include "runtime/render/moment.h"
#include "runtime/render/picture.h"
#include "runtime/run/run.h"
#include "vm/disasm.h"

namespace rs::cli {

namespace {

// ---- options ----------------------------------------------------------------

// "25,-35,0" -> (25, -35, 0), each number by `rule`.
bool parseTriple(const std::string& text, std::string_view option, const NumberRule& rule, Eigen::Vector3d& v,
                 std::ostream& err) {
  std::vector<double> list;
  if (!parseNumberList(text, option, rule, list, err)) return false;
  if (list.size() != 3) {
    err << fmt::format("{}: error: {} takes three numbers X,Y,Z separated by commas, found {}\n  hint: {}\n", option,
                       option, list.size(), rule.hint);
    return false;
  }
  v = Eigen::Vector3d(list[0], list[1], list[2]);
  return true;
}

// "1024x768" -> 1024, 768.
bool parseSize(const std::string& text, int& width, int& height, std::ostream& err) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) {
    err << numberError("--size", fmt::format("--size takes WIDTHxHEIGHT, not '{}'", base::safeText(text)),
                       rules::kPixels);
    return false;
  }
  const NumberRead w = readNumber(std::string_view(text).substr(0, x), rules::kPixels);
  const NumberRead h = readNumber(std::string_view(text).substr(x + 1), rules::kPixels);
  if (!w.problem.empty() || !h.problem.empty()) {
    err << numberError("--size", !w.problem.empty() ? w.problem : h.problem, rules::kPixels);
    return false;
  }
  width = static_cast<int>(w.value), height = static_cast<int>(h.value);
  return true;
}

// The starting camera from --view, --window, --zoom (read by its rule as
// the command line was parsed), --axes, --size.
bool cameraFrom(const RenderOptions& o, render::Camera& camera, std::ostream& err) {
  if (!o.view.empty() && !parseTriple(o.view, "--view", rules::kAngle, camera.view, err)) return false;
  if (!o.window.empty() && !parseTriple(o.window, "--window", rules::kCoordinate, camera.window, err)) return false;
  if (!o.size.empty() && !parseSize(o.size, camera.width, camera.height, err)) return false;
  camera.zoom = o.zoom;
  camera.axes = o.axes;
  return true;
}

// ---- inputs -----------------------------------------------------------------

bool write(const std::string& path, std::string_view bytes, std::ostream& err) {
  std::string error;
  if (base::writeFileAtomically(path, bytes, error)) return true;
  err << fmt::format("{}: error: cannot write: {}\n", base::safeText(path), error);
  return false;
}

bool write(const std::string& path, const std::vector<std::uint8_t>& bytes, std::ostream& err) {
  return write(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), err);
}

std::string baseName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The page's listing: the source's lines, or the disassembly of an image.
render::Listing listing(const launch::LoadedProgram& program) {
  const vm::Image& image = *program.image;
  render::Listing l;
  l.name = baseName(program.source ? program.source->name() : image.sourceName);
  if (program.source) {
    for (std::uint32_t n = 1; n <= program.source->lineCount(); ++n) l.lines.emplace_back(program.source->line(n));
    l.lineOf = image.lines.toVector();
  } else {
    for (std::uint32_t i = 0; i < image.code.size(); ++i) {
      l.lines.push_back(fmt::format("{:04}  {}", i + 1, vm::instructionText(image, i)));
      l.lineOf.push_back(i + 1);
    }
  }
  return l;
}

// The first option given to `render` that only a run uses, when there is
// no --program to run ("" when none).
std::string_view withoutProgram(const RenderOptions& o) {
  if (!o.program.file.empty()) return "";
  if (!o.at.empty()) return "--at";
  if (o.path) return "--path";
  return o.run.firstGiven();
}

// The program's run on the workcell, every problem of the program and of
// the run's options printed (all of them, so that one call reports every
// mistake), with its --collisions; the run is null when anything is wrong.
// `maxTime`, when set, overrides --max-time.
struct Prepared {
  std::unique_ptr<runtime::Run> run;
  runtime::CollisionMode collisions = runtime::CollisionMode::Error;  // the run's --collisions
};
Prepared prepare(const launch::LoadedProgram& program, const RenderOptions& o, std::uint64_t defaultMaxSteps,
                 std::optional<vm::Micros> maxTime, std::ostream& err, bool log = false) {
  std::vector<diag::Diagnostic> diags = program.diagnostics;
  std::optional<runtime::RunSpec> spec = launch::prepareRun(program, o.run, diags, defaultMaxSteps);
  launch::printDiagnostics(err, diags, program);
  if (!spec || !program.ok()) return {};
  if (maxTime) spec->limits.maxTime = *maxTime;
  spec->log = log;
  spec->lines.on = log;  // a page shows lines at most slot by slot: their knots are thinned as they are logged
  const runtime::CollisionMode mode = spec->collisions;
  return {std::make_unique<runtime::Run>(std::move(*spec)), mode};
}

// The step of the move that collided: the one of its instruction whose
// time holds the collision's (binary search: a run in warn mode may
// collide often in a long log).
std::optional<std::uint32_t> stepOfCollision(const runtime::RunLog& log, const runtime::CollisionEvent& e) {
  const auto after = std::upper_bound(log.steps.begin(), log.steps.end(), e.at,
                                      [](vm::Micros t, const runtime::StepRecord& s) { return t < s.start; });
  for (auto it = after; it != log.steps.begin();) {
    --it;
    if (it->end < e.at) break;
    if (it->index == e.instruction) return static_cast<std::uint32_t>(it - log.steps.begin());
  }
  return std::nullopt;
}

// "run.html", "RUN.HTML": what animate writes.
bool endsWithHtml(std::string_view path) {
  constexpr std::string_view kSuffix = ".html";
  if (path.size() < kSuffix.size()) return false;
  const std::string_view end = path.substr(path.size() - kSuffix.size());
  return std::equal(end.begin(), end.end(), kSuffix.begin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

}  // namespace

std::optional<Eigen::Vector3d> zoomPivot(const workcell::Workcell& cell) {
  if (!cell.drivenRobot()) return std::nullopt;
  const workcell::PlacedRobot& r = *cell.drivenRobot();
  Eigen::AlignedBox3d box;
  const auto add = [&](const workcell::Shape& shape) {
    for (const workcell::Segment& s : shape.segments) box.extend(r.F_world_design * s.a), box.extend(r.F_world_design * s.b);
  };
  for (const workcell::Shape& link : r.robot.links) add(link);
  if (r.robot.hasGripper) add(r.robot.gripper.base), add(r.robot.gripper.finger2), add(r.robot.gripper.finger3);
  if (box.isEmpty()) return std::nullopt;
  return box.center();
}

// ---- render -------------------------------------------------------------------

int renderCommand(const RenderOptions& given, std::ostream& out, std::ostream& err) {
  RenderOptions o = given;
  if (!o.cellArgument.empty()) {
    if (o.program.cell.empty()) {
      o.program.cell = o.cellArgument;
    } else if (launch::isProgramAssignment(o.cellArgument)) {
      o.programs.insert(o.programs.begin(), o.cellArgument);
    } else {
      err << fmt::format("robotsim: error: two cells: {} and --cell {}\n  hint: name the cell once: as the first "
                         "argument, or with --cell\n",
                         base::safeText(o.cellArgument), base::safeText(o.program.cell));
      return kExitBadInput;
    }
    o.cellArgument.clear();
  }
  if (o.program.cell.empty()) {
    err << "robotsim: error: which workcell? give CELL (a description file or a library name), or --cell CELL\n";
    return kExitBadInput;
  }
  render::Camera camera;
  if (!cameraFrom(o, camera, err)) return kExitBadInput;
  std::optional<render::ImageFormat> format;
  if (!o.output.empty() && !(format = render::formatFromPath(o.output))) {
    err << fmt::format("robotsim: error: -o {}: the file name must end in .png or .svg\n", base::safeText(o.output));
    return kExitBadInput;
  }
  if (o.output.empty() && o.dump.empty()) {
    err << "robotsim: error: give -o FILE.png|FILE.svg, or --dump-lines\n";
    return kExitBadInput;
  }
  if (!o.dump.empty() && o.dump != "text" && o.dump != "json") {
    err << fmt::format("robotsim: error: --dump-lines takes text or json, not '{}'\n", o.dump);
    return kExitBadInput;
  }
  vm::Micros at = 0;
  if (!o.at.empty() && !parseSecondsArg(o.at, "--at", at, err)) return kExitBadInput;
  std::optional<Eigen::Vector3d> center;
  if (!o.center.empty() && !parseTriple(o.center, "--center", rules::kCoordinate, center.emplace(), err))
    return kExitBadInput;
  // A cell whose robots run programs together: each drawn where its motors are.
  const bool runs = !o.program.file.empty() || !o.programs.empty() || !withoutProgram(o).empty();
  if (runs)
    if (const std::optional<int> code = renderCellIfSeveral(o, camera, format, center, out, err)) return *code;
  if (const std::string_view runOption = withoutProgram(o); !runOption.empty()) {
    err << fmt::format("robotsim: error: {} needs --program\n", runOption);
    return kExitBadInput;
  }
  launch::LoadedProgram loaded;
  if (o.program.file.empty()) {
    loaded.cell = launch::loadCell(o.program, loaded);
    launch::printDiagnostics(err, loaded.diagnostics, loaded);
    if (!loaded.cell || diag::hasErrors(loaded.diagnostics)) return kExitBadInput;
  } else {
    loaded = launch::loadProgramToDraw(o.program);
  }

  // With --at the run needs to go on only until then.
  Prepared prepared;
  if (!o.program.file.empty()) {
    // A cell's devices move parts during a move: the log says where they were at --at.
    prepared = prepare(loaded, o, vm::RunLimits{}.maxSteps, o.at.empty() ? std::nullopt : std::optional(at), err,
                       /*log=*/o.path || (loaded.cell && !loaded.cell->devices.empty()));
    if (!prepared.run) return kExitBadInput;
  }
  const std::unique_ptr<runtime::Run>& run = prepared.run;

  // The run's cell: its feeders' slots are objects too (not drawn while empty).
  const workcell::Workcell& cell = run && run->rig().cell() ? *run->rig().cell() : *loaded.cell;
  render::CellPoser poser(cell);
  render::Fit fit = render::fitView(poser.homePoints(), camera);  // for the starting view
  // --zoom about --center, or the robot's base; at zoom 1 nothing changes.
  if (!center) center = zoomPivot(cell);
  if (center) fit = render::zoomAbout(fit, camera, *center);
  render::Caption caption{cell.name, std::nullopt};
  std::optional<vm::Micros> moment;  // with --program: the moment drawn
  // What the collision marks are drawn for: the motors and the objects.
  std::vector<std::int32_t> encoders(cell.robots.empty() ? 0 : poser.encoders(0).size(), 0);
  std::vector<Eigen::Isometry3d> objectPoses;
  for (const workcell::PlacedObject& p : cell.objects) objectPoses.push_back(p.F_world_design);
  std::optional<std::size_t> held;  // the object the gripper carries then
  bool stoppedByCollision = false;  // drawn at the collision, exit 1
  if (run) {
    render::Moment m = render::momentOf(*run, o.at.empty() ? INT64_MAX : at);
    if (o.at.empty() && run->finished())  // at a moment --at picks, the run has not ended
      printRunWarnings(err, launch::runWarnings(*run, prepared.collisions, run->spec().image->sourceName), loaded);
    if (!m.reached || (o.at.empty() && !m.outcome.ok())) {
      const vm::Image& image = *run->spec().image;
      launch::printDiagnostics(err, {launch::stopDiagnostic(image, m.outcome, image.sourceName)}, loaded);
      // A collision stopped the run: draw it as it happened.
      const auto hits = run->rig().collisions();
      stoppedByCollision = run->finished() && !hits.empty() && hits.back().instruction == m.outcome.index &&
                           m.outcome.reason == vm::StopReason::RuntimeError;
      if (!stoppedByCollision) {
        if (m.reached) err << "robotsim: note: the program did not end within --max-time; pick a moment with --at\n";
        return kExitRunFailed;
      }
      m.encoders = hits.back().encoders;
      m.clock = hits.back().at;
      m.objects.clear();
      m.held.reset();
      for (const runtime::ObjectView& v : run->rig().objects(hits.back().at)) {
        if (v.held) m.held = m.objects.size();
        m.objects.push_back(v.pose);
      }
    }
    poser.setEncoders(0, m.encoders);
    for (std::size_t i = 0; i < m.objects.size(); ++i) poser.setObjectPose(i, m.objects[i]);
    for (std::size_t s = 0; s < m.sensorsOn.size(); ++s) poser.setSensorOn(s, m.sensorsOn[s]);
    encoders = m.encoders;
    objectPoses = m.objects;
    held = m.held;
    camera.view += Eigen::Vector3d(m.view.x, m.view.y, m.view.z);
    camera.window += Eigen::Vector3d(m.window.x, m.window.y, m.window.z);
    caption.title = fmt::format("{} on {}", baseName(o.program.file), cell.name);
    moment = o.at.empty() || stoppedByCollision ? m.clock : at;
    caption.seconds = static_cast<double>(*moment) / 1e6;
  }
  render::Picture picture = render::makePicture(poser, camera, fit, caption);
  // The tool's path up to the moment drawn, thinned to a fraction of a
  // pixel at any zoom.
  if (o.path && run && run->log() && cell.drivenRobot()) {
    const std::vector<render::PathPoint> path =
        render::toolPathOf(*run->log(), *cell.drivenRobot(), fit.radius * render::kPathTolerance / camera.zoom);
    render::addPath(picture, render::pathUntil(path, *moment, poser.tool(cell.drivenRobotIndex())));
  }
  if (!cell.robots.empty()) {
    if (o.collisionShapes) render::addLines(picture, render::collisionShapeLines(cell, encoders, objectPoses));
    render::markColliding(picture, render::contactsAt(cell, encoders, objectPoses, held));
  }
  const std::string what = run ? fmt::format("{} on {}", base::safeText(o.program.file), base::safeText(cell.name))
                               : base::safeText(cell.name);
  if (!writeStill(o, picture, cell, format, camera, what, moment, out, err)) return kExitBadInput;
  return stoppedByCollision ? kExitRunFailed : kExitOk;
}

bool writeStill(const RenderOptions& o, const render::Picture& picture, const workcell::Workcell& cell,
                std::optional<render::ImageFormat> format, const render::Camera& camera, const std::string& what,
                std::optional<vm::Micros> moment, std::ostream& out, std::ostream& err) {
  if (o.dump == "json")
    render::dumpJson(out, picture, cell);
  else if (!o.dump.empty())
    render::dumpText(out, picture, cell);
  if (format) {
    diag::Result<std::vector<std::uint8_t>> encoded = render::encodePicture(picture, *format);
    if (!encoded) {
      err << fmt::format("{}: error: {}\n", base::safeText(o.output), encoded.failure().message);
      return false;
    }
    const std::size_t bytes = encoded->size();
    if (!write(o.output, *encoded, err)) return false;
    // What was written, as animate says it; on stderr when stdout carries
    // the --dump-lines listing.
    (o.dump.empty() ? out : err) << fmt::format(
        "{} -> {} ({}x{} pixels, {}, {} bytes{})\n", what, base::safeText(o.output), camera.width, camera.height,
        *format == render::ImageFormat::Png ? "PNG" : "SVG", bytes,
        moment ? fmt::format(", at {} s", base::formatSeconds(*moment)) : "");
  }
  return true;
}

// ---- animate ------------------------------------------------------------------

void addCollisionMarks(const runtime::Run& run, render::AnimationInput& input) {
  const runtime::CollisionWatch* watch = run.rig().collisionWatch();
  if (!watch || !run.log()) return;
  const runtime::RunLog& recording = *run.log();
  const auto robotBodies = watch->model().robotBodies();
  for (const runtime::CollisionEvent& e : run.rig().collisions()) {
    render::CollisionMark mark{e.at, e.at, {}, {}};
    if (const std::optional<std::uint32_t> step = stepOfCollision(recording, e)) {  // its move: an event
      mark.end = recording.steps[*step].end;
      input.eventSteps.push_back(*step);
    }
    for (const workcell::BodyRef& b : {e.contact.a, e.contact.b}) {
      if (b.kind == workcell::BodyKind::Object) mark.objects.push_back(b.index);
      for (std::size_t k = 0; k < robotBodies.size(); ++k)
        if (robotBodies[k].ref == b) mark.robotParts.push_back(static_cast<int>(k));
    }
    input.collisions.push_back(std::move(mark));
  }
}

int animateCommand(const RenderOptions& o, std::ostream& out, std::ostream& err) {
  if (!endsWithHtml(o.output)) {
    err << fmt::format("robotsim: error: -o {}: the page's file name must end in .html\n", base::safeText(o.output));
    return kExitBadInput;
  }
  render::Camera camera;
  if (!cameraFrom(o, camera, err)) return kExitBadInput;
  if (const std::optional<int> code = animateCellIfSeveral(o, camera, out, err)) return *code;
  if (o.program.file.empty()) {
    err << "robotsim: error: which program? give a program file, or --cell CELL to animate every PROGRAM its "
           "ROBOT lines name (LABEL=FILE gives or overrides one)\n";
    return kExitBadInput;
  }
  const launch::LoadedProgram loaded = launch::loadProgramToDraw(o.program);
  const Prepared prepared = prepare(loaded, o, kAnimateMaxSteps, std::nullopt, err, /*log=*/true);
  const std::unique_ptr<runtime::Run>& run = prepared.run;
  if (!run) return kExitBadInput;
  const vm::RunOutcome outcome = run->runToEnd();
  const runtime::RunLog& recording = *run->log();

  render::AnimationInput input;
  input.cell = run->rig().cell() ? run->rig().cell() : loaded.cell.get();  // with its feeders' slots
  input.run = &recording;
  input.listing = listing(loaded);
  input.camera = camera;
  addCollisionMarks(*run, input);
  if (!outcome.ok()) {
    const vm::Image& image = *run->spec().image;
    const diag::Diagnostic d = launch::stopDiagnostic(image, outcome, image.sourceName);
    launch::printDiagnostics(err, {d}, loaded);
    input.outcome = d.pos.line ? fmt::format("line {}: {}", d.pos.line, d.message) : d.message;
  }
  printRunWarnings(err, launch::runWarnings(*run, prepared.collisions, run->spec().image->sourceName), loaded);
  if (const auto w = runtime::gripperWarning(*run, run->spec().image->sourceName))  // shown under END
    input.warning = fmt::format("line {}: {}", w->pos.line, w->message);
  // The chart under the scrub bar: from the whole log, whatever the frames keep.
  render::ChartInput chartInput;
  chartInput.cell = input.cell;
  chartInput.run = &recording;
  const std::vector<std::uint32_t> lineOf = run->spec().image->lines.toVector();
  chartInput.lineOf = lineOf;
  chartInput.marks = chartMarks(*run, input.outcome);
  chartInput.title = fmt::format("{} on {}", base::safeText(input.listing.name), base::safeText(loaded.cell->name));
  const render::Chart chart = render::chartOf(chartInput);
  input.chart = &chart;
  const render::Frames frames = render::framesOf(recording, input.eventSteps, input.frameRule);
  const std::string html = render::animationHtml(input, frames);
  if (!write(o.output, std::string_view(html), err)) return kExitBadInput;
  out << fmt::format("{} -> {} ({} instructions executed, {} s simulated{})\n", base::safeText(o.program.file),
                     base::safeText(o.output), recording.steps.size(), base::formatSeconds(recording.end),
                     frames.decimated() ? fmt::format("; the page shows {} frames: every event, and the first "
                                                      "instruction to start in each {} s",
                                                      frames.log.steps.size(), base::formatSeconds(frames.slot))
                                        : "");
  return outcome.ok() ? kExitOk : kExitRunFailed;
}

// ---- registration ---------------------------------------------------------------

namespace {

void addCommon(CLI::App* cmd, RenderOptions& o, const std::string& maxStepsDefault) {
  cmd->add_option("--view", o.view, "Turn the image about x, y, z by RX,RY,RZ degrees (default 25,-35,0)")
      ->transform(numberListArg(rules::kAngle));
  cmd->add_option("--window", o.window, "Shift the workcell by X,Y,Z (its own length units)")
      ->transform(numberListArg(rules::kCoordinate));
  cmd->add_option("--zoom", o.zoom, "Magnify (1 = the workcell fits the picture)")->transform(numberArg(rules::kZoom));
  cmd->add_flag("--axes", o.axes, "Draw each link's coordinate frame (the paper's AXES ON)");
  addRunOptions(cmd, o.run, maxStepsDefault);
}

}  // namespace

void addRenderOptions(CLI::App* cmd, RenderOptions& o) {
  cmd->add_option("cell", o.cellArgument, "Workcell (or robot) description file or library name (or give --cell)");
  cmd->add_option("--cell", o.program.cell, "The workcell, as the first argument names it");
  cmd->add_option("programs", o.programs,
                  "LABEL=FILE gives or overrides the program of the cell's robot LABEL; with it (or --at, "
                  "--path) every robot with a program runs it on the cell's one clock, each drawn where its motors "
                  "are");
  cmd->add_option("--program", o.program.file, "Run this program on the workcell's first robot");
  cmd->add_option("--at", o.at,
                  "The moment of the run to draw, in seconds (default: its end, or the collision that stopped it)")
      ->transform(secondsArg());
  cmd->add_flag("--collision-shapes", o.collisionShapes,
                "Also draw the collision geometry (each BOX, the hull of the LINEs, COLLIDE boxes) in light "
                "magenta; parts that overlap are drawn red either way");
  cmd->add_flag("--path", o.path,
                "Also draw the path of the tool centre point up to the moment drawn (in cyan): a straight line for "
                "MOVES, APPRO and DEPART, a curve for MOVEP (needs --program, or a cell whose robots have PROGRAMs)");
  cmd->add_option("-o,--output", o.output, "Picture to write: FILE.png or FILE.svg");
  cmd->add_option("--size", o.size, "Picture size WIDTHxHEIGHT in pixels (default 1024x768)");
  cmd->add_option("--center", o.center,
                  "Zoom about the world point X,Y,Z (default: the base of the workcell's first robot)")
      ->transform(numberListArg(rules::kCoordinate));
  cmd->add_flag("--dump-lines{text}", o.dump, "Print the projected 2-D lines: --dump-lines (text) or =json");
  addLibOption(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
  addCommon(cmd, o, std::to_string(vm::RunLimits{}.maxSteps));
}

void addAnimateOptions(CLI::App* cmd, RenderOptions& o) {
  cmd->add_option("program", o.program.file,
                  "Program source (.rsp) or compiled image (.rsb); without it, every PROGRAM of --cell");
  cmd->add_option("programs", o.programs,
                  "With --cell: LABEL=FILE gives or overrides the program of the cell's robot LABEL; every robot "
                  "with a program runs it on the cell's one clock");
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
  cmd->add_option("-o,--output", o.output, "HTML file to write")->required();
  addCommon(cmd, o, std::to_string(kAnimateMaxSteps));
}

}  // namespace rs::cli
