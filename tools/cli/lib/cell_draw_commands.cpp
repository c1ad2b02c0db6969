#include "tools/cli/lib/cell_draw_commands.h"

#include <fmt/format.h>

#include "base/file_io.h"
#include "base/seconds.h"
#include "base/text.h"
#include "launch/run_diagnostics.h"
#include "runtime/render/animation.h"
#include "runtime/render/cell_moment.h"
#include "runtime/render/collision_marks.h"
#include "runtime/render/picture.h"
#include "runtime/render/tool_path.h"
#include "runtime/run/cell_log.h"
#include "runtime/run/device_history.h"
#include "tools/cli/lib/cell_draw.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"

namespace rs::cli {

namespace {

// The page's listing: the first robot's program (its source's lines).
render::Listing listingOf(const launch::LoadedProgram& program) {
  const vm::Image& image = *program.image;
  render::Listing l;
  const std::string name = program.source ? program.source->name() : image.sourceName;
  l.name = name.substr(name.find_last_of('/') + 1);
  if (program.source) {
    for (std::uint32_t n = 1; n <= program.source->lineCount(); ++n) l.lines.emplace_back(program.source->line(n));
    l.lineOf = image.lines.toVector();
  }
  return l;
}

// How the cell stopped, for people ("" when it ended well): the robot
// that stopped it at its line, or the cell's own words (a deadlock).
std::string stopText(const runtime::CellRun& cell, const vm::RunOutcome& outcome) {
  if (outcome.ok()) return "";
  if (!cell.failed()) return outcome.message;
  const runtime::Run& run = cell.robot(*cell.failed());
  const vm::Image& image = *run.spec().image;
  const diag::Diagnostic d = launch::stopDiagnostic(image, *run.outcome(), image.sourceName);
  return fmt::format("{}: {}{}", cell.label(*cell.failed()), d.pos.line ? fmt::format("line {}: ", d.pos.line) : "",
                     d.message);
}

}  // namespace

std::optional<int> renderCellIfSeveral(const RenderOptions& o, const render::Camera& start,
                                       std::optional<render::ImageFormat> format,
                                       std::optional<Eigen::Vector3d> center, std::ostream& out, std::ostream& err) {
  vm::Micros at = 0;
  if (!o.at.empty() && !parseSecondsArg(o.at, "--at", at, err)) return kExitBadInput;
  std::optional<CellDrawChoice> choice =
      chooseCellDraw(o.program, o.programs, o.run, vm::RunLimits{}.maxSteps, {}, err);
  if (!choice) return std::nullopt;
  if (choice->exit) return *choice->exit;
  if (choice->one) {
    RenderOptions one = o;
    one.program = *choice->one, one.programs.clear();
    return renderCommand(one, out, err);
  }
  CellDraw& draw = *choice->several;
  const vm::RunOutcome outcome = runCellDraw(draw, err, o.at.empty() ? std::nullopt : std::optional(at));
  const runtime::CellRun& run = *draw.run;
  const bool reached = outcome.ok() || (!o.at.empty() && outcome.reason == vm::StopReason::TimeLimit);
  // A collision that stopped the cell is drawn as it happened; any other
  // failure is said (above) and drawn not at all, as for one robot.
  const runtime::CollisionEvent* hit = nullptr;
  if (!reached && run.failed() && outcome.reason == vm::StopReason::RuntimeError) {
    const auto hits = run.robot(*run.failed()).rig().collisions();
    if (!hits.empty()) hit = &hits.back();
  }
  if (!reached && !hit) return kExitRunFailed;
  const vm::Micros moment = hit ? hit->at : o.at.empty() ? run.clock() : at;
  render::CellMoment m = render::cellMomentOf(run, moment);
  if (hit) m.encoders[run.robot(*run.failed()).rig().robotIndex()] = hit->encoders;

  const workcell::Workcell& cell = run.cell();
  render::Camera camera = start;
  render::CellPoser poser(cell);
  render::Fit fit = render::fitView(poser.homePoints(), camera);
  if (!center) center = zoomPivot(cell);
  if (center) fit = render::zoomAbout(fit, camera, *center);
  for (std::size_t r = 0; r < cell.robots.size(); ++r)
    if (!m.encoders[r].empty()) poser.setEncoders(r, m.encoders[r]);
  for (std::size_t i = 0; i < m.objects.size(); ++i) poser.setObjectPose(i, m.objects[i]);
  // The sensors that are ON then, whichever robot's step their edges came in.
  if (!cell.devices.sensors.empty() && run.size()) {
    const runtime::RunLog devices = runtime::cellLogOf(run, 0);
    const runtime::DeviceHistory history(devices, cell);
    for (std::size_t s = 0; s < cell.devices.sensors.size(); ++s) poser.setSensorOn(s, history.sensorOn(s, moment));
  }
  // The first program's VIEW and WINDOW turn the picture, as for one robot.
  if (const runtime::RunLog* log = run.robot(0).log()) {
    const runtime::RunState state = runtime::stateAt(*log, moment);
    camera.view += Eigen::Vector3d(state.view.x, state.view.y, state.view.z);
    camera.window += Eigen::Vector3d(state.window.x, state.window.y, state.window.z);
  }
  const std::string what = cellDrawTitle(draw);
  render::Picture picture = render::makePicture(poser, camera, fit, {what, static_cast<double>(moment) / 1e6});
  if (o.path)
    for (std::size_t p = 0; p < run.size(); ++p) {
      const std::size_t r = run.robot(p).rig().robotIndex();
      const std::vector<render::PathPoint> path = render::toolPathOf(
          *run.robot(p).log(), cell.robots[r], fit.radius * render::kPathTolerance / camera.zoom);
      render::addPath(picture, render::pathUntil(path, moment, poser.tool(r)));
    }
  // Every robot's overlaps with the objects, as the still of one robot checks them.
  for (std::size_t r = 0; r < cell.robots.size(); ++r) {
    const std::span<const std::int32_t> motors = m.encoders[r].empty() ? poser.encoders(r) : std::span(m.encoders[r]);
    if (o.collisionShapes) render::addLines(picture, render::collisionShapeLines(cell, motors, m.objects, r));
    render::markColliding(picture, render::contactsAt(cell, motors, m.objects, m.held[r], r), r);
  }
  if (!writeStill(o, picture, cell, format, camera, what, moment, out, err)) return kExitBadInput;
  return hit ? kExitRunFailed : kExitOk;
}

std::optional<int> animateCellIfSeveral(const RenderOptions& o, const render::Camera& camera, std::ostream& out,
                                        std::ostream& err) {
  std::optional<CellDrawChoice> choice =
      chooseCellDraw(o.program, o.programs, o.run, kAnimateMaxSteps, runtime::LineThinning{.on = true}, err);
  if (!choice) return std::nullopt;
  if (choice->exit) return *choice->exit;
  if (choice->one) {
    RenderOptions one = o;
    one.program = *choice->one, one.programs.clear();
    return animateCommand(one, out, err);
  }
  CellDraw& draw = *choice->several;
  const vm::RunOutcome outcome = runCellDraw(draw, err);
  const runtime::CellRun& cell = *draw.run;
  // The page plays the first program as its own run (its listing, lamps
  // and steps), and every other robot's moves and grasps by time.
  const runtime::Run& first = cell.robot(0);
  // Its log with every robot's device events and part motions: the page's belts and beams.
  const runtime::RunLog recording = runtime::cellLogOf(cell, 0);
  render::AnimationInput input;
  input.cell = &cell.cell();
  input.robot = first.rig().robotIndex();
  input.run = &recording;
  input.listing = listingOf(draw.programs.loaded.front());
  input.camera = camera;
  input.outcome = stopText(cell, outcome);
  addCollisionMarks(first, input);  // the first robot's, whose parts the page marks
  for (std::size_t p = 1; p < cell.size(); ++p)
    input.others.push_back({cell.robot(p).rig().robotIndex(), cell.robot(p).log()});
  const render::Chart chart = cellChart(draw, outcome, 0);
  input.chart = &chart;
  const render::Frames frames = render::framesOf(recording, input.eventSteps, input.frameRule);
  const std::string html = render::animationHtml(input, frames);
  std::string error;
  if (!base::writeFileAtomically(o.output, html, error)) {
    err << fmt::format("{}: error: cannot write: {}\n", base::safeText(o.output), error);
    return kExitBadInput;
  }
  std::uint64_t steps = 0;
  for (std::size_t p = 0; p < cell.size(); ++p) steps += cell.robot(p).log()->steps.size();
  out << fmt::format("{} -> {} ({} instructions executed, {} s simulated{})\n", cellDrawTitle(draw),
                     base::safeText(o.output), steps, base::formatSeconds(cell.clock()),
                     frames.decimated() ? fmt::format("; the page shows {} frames of {}: every event, and the "
                                                      "first instruction to start in each {} s",
                                                      frames.log.steps.size(), base::safeText(cell.label(0)),
                                                      base::formatSeconds(frames.slot))
                                        : "");
  return outcome.ok() ? kExitOk : kExitRunFailed;
}

std::optional<int> plotCellIfSeveral(const PlotOptions& o, const std::string& format, vm::Micros every,
                                     std::ostream& out, std::ostream& err) {
  // The logs exact at every sample: the slot divides the interval (run_log.h).
  std::optional<CellDrawChoice> choice = chooseCellDraw(o.program, o.programs, o.run, kAnimateMaxSteps,
                                                        runtime::LineThinning{.on = true, .slot = every}, err);
  if (!choice) return std::nullopt;
  if (choice->exit) return *choice->exit;
  if (choice->one) {
    PlotOptions one = o;
    one.program = *choice->one, one.programs.clear();
    return plotCommand(one, out, err);
  }
  CellDraw& draw = *choice->several;
  const vm::RunOutcome outcome = runCellDraw(draw, err);
  const vm::Micros end = draw.run->clock();
  if (every > 0 && static_cast<std::uint64_t>(end / every) + 2 > render::kMaxChartSamples) {
    err << fmt::format("--every: error: {} s over a run of {} s makes more than {} samples\n  hint: take a longer "
                       "interval, e.g. --every {}\n",
                       base::formatSeconds(every), base::formatSeconds(end), render::kMaxChartSamples,
                       base::formatSeconds(render::chartInterval(end, 1000)));
    return kExitBadInput;
  }
  const render::Chart chart = cellChart(draw, outcome, every);
  if (!writeChart(o, format, chart, cellDrawTitle(draw), out, err)) return kExitBadInput;
  return outcome.ok() ? kExitOk : kExitRunFailed;
}

}  // namespace rs::cli
