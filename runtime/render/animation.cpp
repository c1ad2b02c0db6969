#include "runtime/render/animation.h"

#include <fmt/format.h>

#include <cmath>

#include "runtime/render/chart_draw.h"
#include "runtime/render/draw.h"
#include "runtime/render/page.h"
#include "runtime/render/palette.h"
#include "runtime/render/scene.h"
#include "runtime/render/tool_path.h"
#include "runtime/cell/input_cause.h"
#include "runtime/run/device_history.h"
#include "vm/io_lines.h"

namespace rs::render {

namespace {

using Json = nlohmann::ordered_json;

Json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// A shape's lines in the coordinates of the frame it moves with.
Json part(std::string_view kind, int index, std::size_t frame, const workcell::Shape& shape,
          const Eigen::Isometry3d& M) {
  Json pts = Json::array(), colors = Json::array();
  for (const workcell::Segment& s : shape.segments) {
    const Eigen::Vector3d a = M * s.a, b = M * s.b;
    for (double v : {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}) pts.push_back(v);
    colors.push_back(static_cast<int>(s.color));
  }
  return {{"kind", kind}, {"index", index}, {"frame", frame}, {"pts", pts}, {"colors", colors}};
}

// A finger's axis in frame n's coordinates: [point, direction].
Json axis(const kinematics::Line& line, const Eigen::Isometry3d& M) {
  const Eigen::Vector3d p = M * line.point, d = M.linear() * line.direction;
  return {p.x(), p.y(), p.z(), d.x(), d.y(), d.z()};
}

Json robotModel(const CellPoser& poser, std::size_t r, bool runsProgram) {
  const workcell::Robot& robot = poser.cell().robots[r].robot;
  const std::size_t last = poser.frameCount(r) - 1;
  Json joints = Json::array();
  if (robot.chain)
    for (const kinematics::Joint& j : robot.chain->joints())
      joints.push_back({{"revolute", j.type() == kinematics::JointType::Revolute},
                        {"theta", j.dh.theta},
                        {"d", j.dh.d},
                        {"a", j.dh.a},
                        {"alpha", j.dh.alpha},
                        {"home", j.home},
                        {"precision", j.precision},
                        {"encoder", j.encoder},
                        {"coupling", j.coupling}});
  Json parts = Json::array();
  for (std::size_t i = 0; i < robot.links.size(); ++i) {
    const std::size_t f = std::min(i, last);
    parts.push_back(part("link", static_cast<int>(i), f, robot.links[i], poser.designInFrame(r, f)));
  }
  Json gripper = nullptr;
  if (robot.hasGripper) {
    const Eigen::Isometry3d& M = poser.designInFrame(r, last);
    parts.push_back(part("gripper", static_cast<int>(last), last, robot.gripper.base, M));
    parts.push_back(part("finger2", static_cast<int>(last), last, robot.gripper.finger2, M));
    parts.push_back(part("finger3", static_cast<int>(last), last, robot.gripper.finger3, M));
    gripper = {{"motor", last},
               {"precision", robot.gripper.model.precision},
               {"axis2", axis(robot.gripper.model.r2, M)},
               {"axis3", axis(robot.gripper.model.r3, M)}};
  }
  std::string letters;
  for (const workcell::JointSpec& j : robot.joints) letters += j.letter;
  if (robot.hasGripper) letters += robot.gripper.letter;
  return {{"name", robot.name},
          {"letters", letters},
          {"program", runsProgram},
          {"tool", poser.hasToolMark(r)},
          {"base", frameJson(poser.frame(r, 0))},
          {"joints", joints},
          {"parts", parts},
          {"gripper", gripper}};
}

// The grasp events as parallel arrays. Each pose is given as the page
// applies it to the object's pts (world coordinates at its placement P):
// a take's F_E_object · P⁻¹ (into the end-effector frame), a let-go's
// F_world_object · P⁻¹ (identity when the object is back at P).
Json graspModel(const runtime::RunLog& rec, const workcell::Workcell& cell) {
  Json step = Json::array(), at = Json::array(), object = Json::array(), held = Json::array(), pose = Json::array();
  for (const runtime::GraspRecord& record : rec.grasps) {
    const runtime::GraspEvent& g = record.event;
    if (g.object >= cell.objects.size()) continue;  // never expected: the log saw this cell
    if (!g.held && g.other) continue;  // a hand-over: the robot that took it over carries it
    step.push_back(record.step), at.push_back(g.at), object.push_back(g.object), held.push_back(g.held);
    const Eigen::Isometry3d P_inv = cell.objects[g.object].F_world_design.inverse(Eigen::Isometry);
    for (const auto& v : frameJson(g.pose * P_inv)) pose.push_back(v);
  }
  return {{"step", step}, {"at", at}, {"object", object}, {"held", held}, {"pose", pose}};
}

// How the cell's belts, feeders and sinks moved the parts (run_log.h's
// motions) as parallel arrays: "step", "at" (µs), "object", "pose" (12
// numbers each, as a let-go's: F_world_object · P⁻¹ at "at"), "velocity"
// (3 each, units per second), "travel" (how far it goes; -1: without end),
// "present" (0: a part a sink took, a feeder's empty slot). And each
// sensor's edges: "at", "sensor", "on".
Json motionModel(const runtime::RunLog& rec, const workcell::Workcell& cell) {
  Json step = Json::array(), at = Json::array(), object = Json::array(), pose = Json::array(), velocity = Json::array();
  Json travel = Json::array(), present = Json::array();
  for (const runtime::MotionRecord& record : rec.motions) {
    const runtime::PartMotion& m = record.motion;
    if (m.object >= cell.objects.size()) continue;  // never expected: the log saw this cell
    step.push_back(record.step), at.push_back(m.at), object.push_back(m.object);
    const Eigen::Isometry3d P_inv = cell.objects[m.object].F_world_design.inverse(Eigen::Isometry);
    for (const auto& v : frameJson(m.pose * P_inv)) pose.push_back(v);
    for (const double v : {m.velocity.x(), m.velocity.y(), m.velocity.z()}) velocity.push_back(v);
    travel.push_back(std::isfinite(m.travel) ? m.travel : -1.0);
    present.push_back(runtime::isParked(m.pose) ? 0 : 1);
  }
  return {{"step", step}, {"at", at},         {"object", object}, {"pose", pose},
          {"velocity", velocity}, {"travel", travel}, {"present", present}};
}

// Every change of an input and what made it (a stimulus, a rule, a wire),
// in the words the debugger prints beside an input ("since 1.100 s: wire
// from sensor eye"): the page's lamps say it in their titles.
Json inputCauseModel(const runtime::RunLog& rec) {
  Json at = Json::array(), input = Json::array(), on = Json::array(), since = Json::array();
  for (const runtime::InputRecord& r : rec.inputChanges) {
    at.push_back(r.at), input.push_back(r.cause.input), on.push_back(r.cause.on);
    since.push_back(runtime::inputSinceText(fmt::format("{:.3f}", static_cast<double>(r.at) / 1e6), r.cause));
  }
  return {{"at", at}, {"input", input}, {"on", on}, {"since", since}};
}

Json sensorEdgeModel(const runtime::RunLog& rec) {
  Json at = Json::array(), sensor = Json::array(), on = Json::array();
  for (const runtime::DeviceRecord& r : rec.devices) {
    const runtime::DeviceEvent& e = r.event;
    if (e.kind != runtime::DeviceEvent::Kind::SensorOn && e.kind != runtime::DeviceEvent::Kind::SensorOff) continue;
    at.push_back(e.at), sensor.push_back(e.device), on.push_back(e.kind == runtime::DeviceEvent::Kind::SensorOn);
  }
  return {{"at", at}, {"sensor", sensor}, {"on", on}};
}

Json motorsModel(const runtime::RunLog& rec) {
  Json motors = Json::array();
  for (const vm::MotorSpec& m : rec.motors) {
    Json motor = {{"letter", std::string(1, m.letter)},
                  {"kind", m.kind == vm::JointKind::Gripper     ? "gripper"
                           : m.kind == vm::JointKind::Prismatic ? "prismatic"
                                                                : "revolute"},
                  {"min", m.min},
                  {"max", m.max},
                  {"speed", m.speed}};
    // Only when set: a constant-speed motor's entry is what it always was.
    if (m.acceleration != 0) motor["acceleration"] = m.acceleration;
    if (m.actuation != 0) motor["actuation"] = m.actuation;
    motors.push_back(std::move(motor));
  }
  return motors;
}

// Each motor's moves as parallel arrays; `steps`: with each one's step.
Json movesModel(const runtime::RunLog& rec, bool steps) {
  Json moves = Json::array();
  for (const std::vector<runtime::MotorMove>& list : rec.moves) {
    Json step = Json::array(), from = Json::array(), to = Json::array(), t0 = Json::array(), t1 = Json::array();
    Json lock = Json::array();
    bool anyLock = false;
    for (const runtime::MotorMove& m : list) {
      if (steps) step.push_back(m.step);
      from.push_back(m.from), to.push_back(m.to), t0.push_back(m.start), t1.push_back(m.end);
      lock.push_back(m.lockStep ? (m.lead ? 2 : 1) : 0), anyLock |= m.lockStep;
    }
    // Moved in, not copied (a braced list copies): a page of many frames is mostly these.
    Json entry = Json::object();
    if (steps) entry["step"] = std::move(step);
    entry["from"] = std::move(from), entry["to"] = std::move(to);
    entry["start"] = std::move(t0), entry["end"] = std::move(t1);
    if (anyLock) entry["lock"] = std::move(lock);  // 1 lock-step, 2 leading: only with straight lines, so other pages keep their bytes
    moves.push_back(std::move(entry));
  }
  return moves;
}

// Another robot of the cell, moved by time ("run"."others").
Json otherModel(const OtherRobotRun& other, const workcell::Workcell& cell) {
  Json grasps = graspModel(*other.run, cell);
  grasps.erase("step");
  return {{"robot", other.robot},
          {"end", other.run->end},
          {"motors", motorsModel(*other.run)},
          {"moves", movesModel(*other.run, false)},
          {"grasps", std::move(grasps)}};
}

Json runModel(const runtime::RunLog& rec, const workcell::Workcell& cell, const std::string& outcome,
              std::size_t driven) {
  Json motors = motorsModel(rec);
  Json index = Json::array(), start = Json::array(), stop = Json::array();
  for (const runtime::StepRecord& s : rec.steps) index.push_back(s.index), start.push_back(s.start), stop.push_back(s.end);
  Json moves = movesModel(rec, true);
  Json outStep = Json::array(), outMask = Json::array();
  for (const runtime::OutputChange& o : rec.outputs) outStep.push_back(o.step), outMask.push_back(o.outputs);
  Json camStep = Json::array(), camView = Json::array(), camWindow = Json::array();
  for (const runtime::CameraChange& c : rec.cameras) {
    camStep.push_back(c.step);
    for (std::int64_t v : {c.view.x, c.view.y, c.view.z}) camView.push_back(v);
    for (std::int64_t v : {c.window.x, c.window.y, c.window.z}) camWindow.push_back(v);
  }
  Json inAt = Json::array(), inMask = Json::array();
  for (const runtime::InputLevel& l : rec.inputs) inAt.push_back(l.at), inMask.push_back(l.inputs);
  Json run = Json::object();
  run["end"] = rec.end;
  run["outcome"] = outcome;
  run["motors"] = std::move(motors);
  run["index"] = std::move(index), run["start"] = std::move(start), run["stop"] = std::move(stop);
  run["moves"] = std::move(moves);
  run["driven"] = driven;  // the robot a collision's robotParts are parts of
  run["lines"] = vm::kIoCount;  // inputs and outputs each: the lamps the page draws
  run["outputs"] = {{"step", outStep}, {"mask", outMask}};
  run["cameras"] = {{"step", camStep}, {"view", camView}, {"window", camWindow}};
  run["inputs"] = {{"at", inAt}, {"mask", inMask}};
  if (!rec.inputChanges.empty()) run["inputCauses"] = inputCauseModel(rec);  // only with changes: other pages keep their bytes
  run["grasps"] = graspModel(rec, cell);
  if (!cell.devices.empty()) {  // only with devices: other pages keep their bytes
    run["motions"] = motionModel(rec, cell);
    run["sensors"] = sensorEdgeModel(rec);
  }
  return run;
}

Json withCollisions(Json run, const std::vector<CollisionMark>& marks) {
  Json at = Json::array(), end = Json::array(), robotParts = Json::array(), objects = Json::array();
  for (const CollisionMark& m : marks)
    at.push_back(m.at), end.push_back(m.end), robotParts.push_back(m.robotParts), objects.push_back(m.objects);
  run["collisions"] = {{"at", at}, {"end", end}, {"robotParts", robotParts}, {"objects", objects}};
  return run;
}

std::string cssColor(Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

// What the stills draw with (palette.h, scene.h, draw.h), so that the page
// draws the same.
Json styleModel() {
  Json palette = Json::array(), axisColors = Json::array();
  for (const Rgb& c : kEga) palette.push_back(cssColor(c));
  for (const workcell::Color c : kAxisColors) axisColors.push_back(static_cast<int>(c));
  return {{"palette", palette},
          {"background", cssColor(kBackground)},
          {"axisColors", axisColors},
          {"axisLength", kAxisLength},
          {"toolRadius", kToolRadius},
          {"toolLineWidth", kToolLineWidth},
          {"toolColor", static_cast<int>(kToolColor)},
          {"pathColor", static_cast<int>(kPathColor)},
          {"pathLineWidth", kPathLineWidth}};
}

// The tool centre point's path over the whole run (tool_path.h), thinned
// to a thousandth of the fit's radius: "at" (µs), "pts" (x, y, z each),
// "jump" (the points that start a new stretch).
Json pathModel(const runtime::RunLog& log, const workcell::Workcell& cell, std::size_t driven, double radius) {
  Json at = Json::array(), pts = Json::array(), jump = Json::array();
  if (const workcell::PlacedRobot* robot = driven < cell.robots.size() ? &cell.robots[driven] : nullptr) {
    const std::vector<PathPoint> path = toolPathOf(log, *robot, radius * kPathTolerance);
    for (std::size_t i = 0; i < path.size(); ++i) {
      at.push_back(path[i].at);
      for (const double v : {path[i].p.x(), path[i].p.y(), path[i].p.z()}) pts.push_back(v);
      if (path[i].jump) jump.push_back(i);
    }
  }
  return {{"at", at}, {"pts", pts}, {"jump", jump}};
}

// Each sensor's lines as a still draws them while it is ON (scene.h), in
// world coordinates: {"kind": "sensor", "index", "name", "pts", "colors"}.
Json sensorModel(const workcell::Workcell& cell) {
  CellPoser poser(cell);
  for (std::size_t s = 0; s < cell.devices.sensors.size(); ++s) poser.setSensorOn(s, true);
  std::vector<Line3> lines;
  poser.lines(lines);
  Json sensors = Json::array();
  for (std::size_t s = 0; s < cell.devices.sensors.size(); ++s)
    sensors.push_back({{"kind", "sensor"},
                       {"index", s},
                       {"name", cell.devices.sensors[s].name},
                       {"pts", Json::array()},
                       {"colors", Json::array()}});
  for (const Line3& l : lines) {
    if (l.part.kind != PartKind::Sensor) continue;
    Json& sensor = sensors[static_cast<std::size_t>(l.part.owner)];
    for (const double v : {l.a.x(), l.a.y(), l.a.z(), l.b.x(), l.b.y(), l.b.z()}) sensor["pts"].push_back(v);
    sensor["colors"].push_back(static_cast<int>(l.color));
  }
  return sensors;
}

}  // namespace

nlohmann::ordered_json frameJson(const Eigen::Isometry3d& F) {
  Json m = Json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m.push_back(F.matrix()(r, c));
  return m;
}

Json cellDrawing(const workcell::Workcell& cell, const Camera& camera) {
  return cellDrawing(cell, camera, cell.drivenRobotIndex());
}

Json cellDrawing(const workcell::Workcell& cell, const Camera& camera, std::size_t robot) {
  const CellPoser poser(cell);
  const Fit fit = fitView(poser.homePoints(), camera);
  Json robots = Json::array();
  for (std::size_t r = 0; r < cell.robots.size(); ++r) robots.push_back(robotModel(poser, r, r == robot));
  Json objects = Json::array();
  for (std::size_t o = 0; o < cell.objects.size(); ++o)
    objects.push_back(part("object", static_cast<int>(o), 0, cell.objects[o].shape, cell.objects[o].F_world_design));
  for (std::size_t o = 0; o < cell.objects.size(); ++o) {
    objects[o]["name"] = cell.objects[o].shape.name;
    if (cell.objects[o].F_world_design.translation().y() < kNotInCellBelow) objects[o]["parked"] = true;  // a feeder's slot
  }
  Json drawing = {{"fit", {{"center", vec(fit.center)}, {"radius", fit.radius}}},
                  {"camera",
                   {{"view", vec(camera.view)}, {"window", vec(camera.window)}, {"zoom", camera.zoom}, {"axes", camera.axes}}},
                  {"style", styleModel()},
                  {"robots", robots},
                  {"objects", objects}};
  if (!cell.devices.sensors.empty()) drawing["sensors"] = sensorModel(cell);
  return drawing;
}

Json animationModel(const AnimationInput& input) {
  return animationModel(input, framesOf(*input.run, input.eventSteps, input.frameRule));
}

Json animationModel(const AnimationInput& input, const Frames& frames) {
  const workcell::Workcell& cell = *input.cell;
  Json model = {{"title", fmt::format("{} on {}", input.listing.name, cell.name)}, {"cell", cell.name}};
  const Json drawing = cellDrawing(cell, input.camera, input.robot);
  for (const auto& [key, value] : drawing.items()) model[key] = value;
  model["program"] = {{"name", input.listing.name}, {"lines", input.listing.lines}, {"lineOf", input.listing.lineOf}};
  model["run"] = withCollisions(runModel(frames.log, cell, input.outcome, input.robot), input.collisions);
  if (!input.others.empty()) {  // only in a cell of several: other pages keep their bytes
    Json others = Json::array();
    vm::Micros end = frames.log.end;
    for (const OtherRobotRun& other : input.others) others.push_back(otherModel(other, cell)), end = std::max(end, other.run->end);
    model["run"]["others"] = std::move(others);
    model["run"]["end"] = end;
  }
  if (frames.decimated()) model["run"]["frames"] = {{"steps", frames.runSteps}, {"slot", frames.slot}};
  if (!input.warning.empty()) model["run"]["warning"] = input.warning;  // only when there is one
  model["path"] = pathModel(*input.run, cell, input.robot, model["fit"]["radius"].get<double>());
  if (input.chart) {
    const ChartLayout layout = chartLayout(*input.chart);
    const diag::Result<std::vector<std::uint8_t>> svg = encodeChart(*input.chart, layout, ImageFormat::Svg);
    if (svg)
      model["chart"] = {{"svg", std::string(svg->begin(), svg->end())},
                        {"width", layout.width},
                        {"height", layout.height},
                        {"left", layout.left},
                        {"right", layout.right},
                        {"end", layout.end}};
  }
  return model;
}

std::string scriptSafeJson(const Json& model) {
  std::string json = model.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (json.find('<') == std::string::npos) return json;  // the usual case: no second copy of a large model
  std::string safe;
  safe.reserve(json.size());
  for (char c : json) {
    if (c == '<')
      safe += "\\u003c";
    else
      safe += c;
  }
  return safe;
}

std::string animationHtml(const AnimationInput& input) {
  return animationHtml(input, framesOf(*input.run, input.eventSteps, input.frameRule));
}

std::string animationHtml(const AnimationInput& input, const Frames& frames) {
  // The model as text, and the model gone before the page is put
  // together: a page of many frames is mostly its model, held once at a time.
  std::string title, safe;
  {
    const Json model = animationModel(input, frames);
    title = model["title"].get<std::string>();
    safe = scriptSafeJson(model);
  }
  std::string html;
  html.reserve(safe.size() + pageScript().size() + pageStyle().size() + 4096);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html +=
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data:\">\n";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  html += "<title>robotsim: " + escapeHtml(title) + "</title>\n";
  html += "<style>\n";
  html += pageStyle();
  html += "</style>\n</head>\n<body>\n";
  html += page::kBody;
  html += "<script type=\"application/json\" id=\"robotsim-model\">";
  html += safe;
  html += "</script>\n<script>\n";
  html += drawScript();
  html += "</script>\n<script>\n";
  html += pageScript();
  html += "</script>\n</body>\n</html>\n";
  return html;
}

std::string escapeHtml(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string_view pageScript() { return page::kScript; }
std::string_view drawScript() { return page::kDrawScript; }
std::string_view pageStyle() { return page::kStyle; }

}  // namespace rs::render
