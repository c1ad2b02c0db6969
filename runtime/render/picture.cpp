#include "runtime/render/picture.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "base/text.h"
#include "runtime/render/palette.h"

namespace rs::render {

namespace {

using Json = nlohmann::ordered_json;

const std::string& ownerName(const Part& part, const workcell::Workcell& cell) {
  const auto i = static_cast<std::size_t>(part.owner);
  if (part.kind == PartKind::Sensor) return cell.devices.sensors[i].name;
  return part.kind == PartKind::Object ? cell.objects[i].shape.name : cell.robots[i].robot.name;
}

const char* ownerWord(const Part& part) {
  return part.kind == PartKind::Object ? "object" : part.kind == PartKind::Sensor ? "sensor" : "robot";
}

// Nine decimals, and never "-0.000000000".
std::string number(double v) {
  std::string s = fmt::format("{:.9f}", v);
  if (s.find_first_not_of("-0.") == std::string::npos) return fmt::format("{:.9f}", 0.0);
  return s;
}

}  // namespace

std::string partName(const Part& part) {
  switch (part.kind) {
    case PartKind::Link: return fmt::format("link{}", part.index);
    case PartKind::GripperBase: return "gripper";
    case PartKind::Finger2: return "finger2";
    case PartKind::Finger3: return "finger3";
    case PartKind::Object: return "object";
    case PartKind::Axis: return fmt::format("axis{}-{}", part.index, "xyz"[part.axis & 3]);
    case PartKind::Sensor: return "sensor";
  }
  return "?";
}

std::string robotLegend(const workcell::Robot& robot, std::span<const std::int32_t> encoders) {
  std::string text = base::safeText(robot.name) + " ";
  for (std::size_t i = 0; i < encoders.size(); ++i) {
    const char letter = i < robot.joints.size() ? robot.joints[i].letter : robot.gripper.letter;
    text += fmt::format(" {}={}", letter, encoders[i]);
  }
  return text;
}

Picture makePicture(const CellPoser& poser, const Camera& camera, const Fit& fit, const Caption& caption) {
  const Projection project(camera, fit);
  Picture picture;
  picture.width = camera.width;
  picture.height = camera.height;
  picture.camera = camera;
  picture.fit = fit;
  std::vector<Line3> lines;
  poser.lines(lines, camera.axes ? kAxisLength * fit.radius : 0.0);
  picture.lines.reserve(lines.size());
  for (const Line3& l : lines) picture.lines.push_back({project(l.a), project(l.b), l.color, l.part});
  const workcell::Workcell& cell = poser.cell();
  // A robot alone is its own workcell: its name needs saying only once.
  const bool robotAlone = cell.robots.size() == 1 && cell.drivenRobot()->robot.name == caption.title;
  std::string title = robotAlone ? "" : base::safeText(caption.title);
  if (caption.seconds) title += fmt::format("{}t = {:.3f} s", title.empty() ? "" : "   ", *caption.seconds);
  if (!title.empty()) picture.legend.push_back(title);
  for (std::size_t r = 0; r < cell.robots.size(); ++r) {
    const workcell::Robot& robot = cell.robots[r].robot;
    if (poser.hasToolMark(r)) picture.tools.push_back({static_cast<int>(r), project(poser.tool(r))});
    picture.legend.push_back(robotLegend(robot, poser.encoders(r)));
  }
  return picture;
}

void addPath(Picture& picture, const std::vector<PathPoint>& path) {
  const Projection project(picture.camera, picture.fit);
  for (const PathPoint& p : path) {
    if (picture.path.empty() || p.jump) picture.path.emplace_back();
    picture.path.back().push_back(project(p.p));
  }
}

void dumpText(std::ostream& out, const Picture& picture, const workcell::Workcell& cell) {
  const Camera& c = picture.camera;
  out << fmt::format("# robotsim lines: cell {} lines {} size {}x{}\n", base::safeText(cell.name), picture.lines.size(),
                     picture.width, picture.height);
  out << fmt::format("# camera: view {} {} {} window {} {} {} zoom {} axes {} fit {} {} {} radius {}\n", c.view.x(),
                     c.view.y(), c.view.z(), c.window.x(), c.window.y(), c.window.z(), c.zoom, c.axes ? "on" : "off",
                     picture.fit.center.x(), picture.fit.center.y(), picture.fit.center.z(), picture.fit.radius);
  for (const Line2& l : picture.lines)
    out << fmt::format("{} {} {} {} {} {} {} {} {}\n", ownerWord(l.part),
                       l.part.owner, base::safeText(ownerName(l.part, cell)), partName(l.part), colorName(l.color),
                       number(l.a.x()), number(l.a.y()), number(l.b.x()), number(l.b.y()));
  for (const ToolMark& t : picture.tools)
    out << fmt::format("tool {} {} {} {}\n", t.robot,
                       base::safeText(cell.robots[static_cast<std::size_t>(t.robot)].robot.name), number(t.at.x()),
                       number(t.at.y()));
  for (std::size_t k = 0; k < picture.path.size(); ++k)
    for (const Eigen::Vector2d& v : picture.path[k]) out << fmt::format("path {} {} {}\n", k, number(v.x()), number(v.y()));
}

void dumpJson(std::ostream& out, const Picture& picture, const workcell::Workcell& cell) {
  Json lines = Json::array(), tools = Json::array();
  for (const Line2& l : picture.lines)
    lines.push_back({{"owner", ownerWord(l.part)},
                     {"index", l.part.owner},
                     {"name", ownerName(l.part, cell)},
                     {"part", partName(l.part)},
                     {"color", colorName(l.color)},
                     {"a", {l.a.x(), l.a.y()}},
                     {"b", {l.b.x(), l.b.y()}}});
  for (const ToolMark& t : picture.tools)
    tools.push_back({{"robot", t.robot},
                     {"name", cell.robots[static_cast<std::size_t>(t.robot)].robot.name},
                     {"at", {t.at.x(), t.at.y()}}});
  const Camera& c = picture.camera;
  Json doc = {{"cell", cell.name},
                    {"width", picture.width},
                    {"height", picture.height},
                    {"camera",
                     {{"view", {c.view.x(), c.view.y(), c.view.z()}},
                      {"window", {c.window.x(), c.window.y(), c.window.z()}},
                      {"zoom", c.zoom},
                      {"axes", c.axes}}},
                    {"fit",
                     {{"center", {picture.fit.center.x(), picture.fit.center.y(), picture.fit.center.z()}},
                      {"radius", picture.fit.radius}}},
                    {"lines", lines},
                    {"tools", tools},
                    {"legend", picture.legend}};
  if (!picture.path.empty()) {
    Json path = Json::array();
    for (const std::vector<Eigen::Vector2d>& stretch : picture.path) {
      Json vertices = Json::array();
      for (const Eigen::Vector2d& v : stretch) vertices.push_back({v.x(), v.y()});
      path.push_back(std::move(vertices));
    }
    doc["path"] = std::move(path);
  }
  out << doc.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
}

}  // namespace rs::render
