#include "tools/cli/lib/describe_command.h"

#include <optional>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "base/number_text.h"
#include "base/text.h"
#include "compiler/description/library.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/workcell/reach.h"
#include "model/workcell/support.h"
#include "tools/cli/lib/describe_devices.h"
#include "tools/cli/lib/exit_codes.h"
#include "vm/io_lines.h"

namespace rs::cli {

using base::formatNumber;

namespace {

using Json = nlohmann::ordered_json;

// The controller's input and output lines (vm/io_lines.h: the paper's
// eight of each); descriptions do not name them.
constexpr int kInputs = vm::kIoCount, kOutputs = vm::kIoCount;

struct MotorRow {
  char letter;
  std::string type;
  double precision;
  std::int32_t min, max, speed;
  bool coupling;
};

std::vector<MotorRow> motorsOf(const workcell::Robot& robot) {
  std::vector<MotorRow> rows;
  for (const workcell::JointSpec& j : robot.joints)
    rows.push_back({j.letter, std::string(kinematics::jointTypeName(j.type)), j.precision, j.min, j.max, j.speed,
                    j.coupling});
  if (robot.hasGripper) {
    const workcell::Gripper& g = robot.gripper;
    rows.push_back({g.letter, "gripper", g.model.precision, g.min, g.max, g.speed, false});
  }
  return rows;
}

Json vec(const Eigen::Vector3d& v) { return Json::array({v.x() + 0.0, v.y() + 0.0, v.z() + 0.0}); }

std::string point(const Eigen::Vector3d& v) {
  return fmt::format("({}, {}, {})", formatNumber(v.x()), formatNumber(v.y()), formatNumber(v.z()));
}

std::string boxText(const Eigen::AlignedBox3d& b) {
  return fmt::format("x {}..{}  y {}..{}  z {}..{}", formatNumber(b.min().x()), formatNumber(b.max().x()),
                     formatNumber(b.min().y()), formatNumber(b.max().y()), formatNumber(b.min().z()),
                     formatNumber(b.max().z()));
}

// Objects are numbered from 1 in the workcell's order, as run traces do.
std::string supportText(const workcell::Support& s, const workcell::Workcell& cell) {
  switch (s.kind) {
    case workcell::Support::Kind::Object:
      return fmt::format("{} (object {})", base::safeText(cell.objects[s.object].shape.name), s.object + 1);
    case workcell::Support::Kind::Floor: return "the floor (y = 0)";
    case workcell::Support::Kind::Nothing: break;
  }
  return "nothing (there is no gravity: it stays where it is placed)";
}

Json supportJson(const workcell::Support& s, const workcell::Workcell& cell) {
  switch (s.kind) {
    case workcell::Support::Kind::Object:
      return {{"kind", "object"}, {"object", s.object + 1}, {"name", cell.objects[s.object].shape.name}};
    case workcell::Support::Kind::Floor: return {{"kind", "floor"}};
    case workcell::Support::Kind::Nothing: break;
  }
  return {{"kind", "nothing"}};
}

// Everything describe says about one robot, computed once for both formats.
struct RobotFacts {
  const workcell::PlacedRobot* placed = nullptr;
  Eigen::Isometry3d F_world_0 = Eigen::Isometry3d::Identity();
  Eigen::Vector3d homeTcp = Eigen::Vector3d::Zero();
  workcell::Reach reach;
  Eigen::AlignedBox3d base;
  workcell::Support on;
  // The gripper's fingers as drawn (open), from the tool centre point at
  // home: how far their lines reach ahead of it along the approach vector
  // a (below it, for a gripper pointing down), and the gap between them
  // across it (along n or o, whichever the fingers lie apart on).
  std::optional<double> fingerReach, fingerOpening;
};

void fingerFacts(const workcell::PlacedRobot& placed, const Eigen::Isometry3d& tool, RobotFacts& f) {
  const workcell::Robot& robot = placed.robot;
  if (!robot.hasGripper || robot.gripper.finger2.segments.empty() || robot.gripper.finger3.segments.empty()) return;
  const Eigen::Vector3d tcp = tool.translation(), a = tool.linear().col(2);
  double reach = -1e300;
  const auto points = [&](const workcell::Shape& s, const Eigen::Vector3d& axis, double& lo, double& hi) {
    lo = 1e300, hi = -1e300;
    for (const workcell::Segment& seg : s.segments)
      for (const Eigen::Vector3d& d : {seg.a, seg.b}) {
        const Eigen::Vector3d w = placed.F_world_design * d;
        reach = std::max(reach, (w - tcp).dot(a));
        lo = std::min(lo, (w - tcp).dot(axis)), hi = std::max(hi, (w - tcp).dot(axis));
      }
  };
  double gap = -1e300;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d axis = tool.linear().col(k);
    double lo2, hi2, lo3, hi3;
    points(robot.gripper.finger2, axis, lo2, hi2);
    points(robot.gripper.finger3, axis, lo3, hi3);
    gap = std::max({gap, lo3 - hi2, lo2 - hi3});
  }
  f.fingerReach = reach;
  f.fingerOpening = gap;
}

RobotFacts factsOf(const workcell::PlacedRobot& placed, std::span<const workcell::PlacedObject> objects) {
  RobotFacts f;
  f.placed = &placed;
  const kinematics::ChainModel chain =
      placed.robot.chain->placedAt(placed.F_world_design * placed.robot.frames.front());
  f.F_world_0 = chain.F_world_0();
  kinematics::ChainData data(chain);
  std::vector<double> home;
  for (const kinematics::Joint& j : chain.joints()) home.push_back(j.home);
  kinematics::forwardKinematics(chain, data, home);
  f.homeTcp = kinematics::toolPose(chain, data).translation();
  fingerFacts(placed, kinematics::toolPose(chain, data), f);
  f.reach = workcell::reachOf(placed);
  f.base = placed.robot.links.empty() ? Eigen::AlignedBox3d()
                                      : workcell::worldBoxOf(placed.robot.links.front(), placed.F_world_design);
  f.on = workcell::supportOf(f.base, objects);
  return f;
}

void robotText(const RobotFacts& f, bool first, const workcell::Workcell& cell, std::ostream& out) {
  const workcell::Robot& robot = f.placed->robot;
  out << fmt::format("robot {}{}\n", base::safeText(robot.name), first ? " (runs the program)" : "");
  if (robot.urdf)
    out << fmt::format("  from URDF file {}: the chain from root link {} to tip link {}\n", base::safeText(robot.urdf->file),
                       base::safeText(robot.urdf->rootLink), base::safeText(robot.urdf->tipLink));
  const Eigen::Matrix3d r = f.F_world_0.linear();
  out << fmt::format("  frame 0  origin {}, x0 {}, z0 {} (z0 is joint 1's axis)\n", point(f.F_world_0.translation()),
                     point(r.col(0)), point(r.col(2)));
  out << fmt::format("  {:<6} {:<10} {:>14} {:>14} {:>10}  {}\n", "motor", "type", "per count", "range", "speed/s",
                     "coupling");
  for (const MotorRow& m : motorsOf(robot)) {
    const std::string unit = m.type == "prismatic" ? "" : " deg";
    out << fmt::format("  {:<6} {:<10} {:>14} {:>14} {:>10}  {}\n", m.letter, m.type,
                       formatNumber(m.precision) + unit, fmt::format("{}..{}", m.min, m.max), m.speed,
                       m.type == "gripper" ? fmt::format("({} open, {} closed)", m.min, m.max)
                                           : (m.coupling ? "on" : "off"));
  }
  out << fmt::format("  tool centre point at home (every motor at 0): {}\n", point(f.homeTcp));
  if (f.fingerReach)
    out << fmt::format("  fingers  reach {} below the tool centre point (along a), open {} wide (as drawn)\n",
                       formatNumber(*f.fingerReach), formatNumber(*f.fingerOpening));
  if (f.reach.radius)
    out << fmt::format("  reach    {} from joint {}'s axis (tool centre point)\n", formatNumber(*f.reach.radius),
                       robot.joints.front().letter);
  out << fmt::format("  span     {} (tool centre point)\n", boxText(Eigen::AlignedBox3d(f.reach.min, f.reach.max)));
  if (!f.base.isEmpty())
    out << fmt::format("  base     {}, on {}\n", boxText(f.base), supportText(f.on, cell));
}

Json robotJson(const RobotFacts& f, const workcell::Workcell& cell) {
  const workcell::Robot& robot = f.placed->robot;
  Json motors = Json::array();
  for (const MotorRow& m : motorsOf(robot))
    motors.push_back({{"letter", std::string(1, m.letter)},
                      {"type", m.type},
                      {"precision", m.precision},
                      {"unit", m.type == "prismatic" ? "length" : "deg"},
                      {"min", m.min},
                      {"max", m.max},
                      {"speed", m.speed},
                      {"coupling", m.coupling}});
  const Eigen::Matrix3d r = f.F_world_0.linear();
  Json j;
  j["name"] = robot.name;
  if (robot.urdf)
    j["source"] = {{"urdf", robot.urdf->file}, {"root", robot.urdf->rootLink}, {"tip", robot.urdf->tipLink}};
  j["frame0"] = {{"origin", vec(f.F_world_0.translation())}, {"x", vec(r.col(0))}, {"z", vec(r.col(2))}};
  j["motors"] = motors;
  j["home_tcp"] = vec(f.homeTcp);
  if (f.fingerReach) j["fingers"] = {{"reach", *f.fingerReach}, {"opening", *f.fingerOpening}};
  j["reach"] = {{"radius", f.reach.radius ? Json(*f.reach.radius) : Json(nullptr)},
                {"min", vec(f.reach.min)},
                {"max", vec(f.reach.max)}};
  if (!f.base.isEmpty())
    j["base"] = {{"min", vec(f.base.min())}, {"max", vec(f.base.max())}, {"on", supportJson(f.on, cell)}};
  return j;
}

}  // namespace

int describeCommand(const RobotQuery& q, std::ostream& out, std::ostream& err) {
  compiler::Library library = queryLibrary(q);
  const std::optional<workcell::Workcell> cell = library.workcell(q.robot);
  const bool world = cell && library.holdsWorkcell(q.robot);
  for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
  if (!cell) return kExitBadInput;

  std::vector<Eigen::AlignedBox3d> boxes;
  for (const workcell::PlacedObject& o : cell->objects) boxes.push_back(workcell::worldBoxOf(o.shape, o.F_world_design));
  std::vector<RobotFacts> robots;
  for (const workcell::PlacedRobot& r : cell->robots) robots.push_back(factsOf(r, cell->objects));

  if (q.json) {
    Json j;
    j["cell"] = world ? Json(cell->name) : Json(nullptr);
    j["frame"] = world ? "world" : "design";
    Json list = Json::array();
    for (const RobotFacts& f : robots) list.push_back(robotJson(f, *cell));
    j["robots"] = list;
    Json objects = Json::array();
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      Json o;
      o["object"] = i + 1;
      o["name"] = cell->objects[i].shape.name;
      if (!boxes[i].isEmpty()) {
        o["min"] = vec(boxes[i].min());
        o["max"] = vec(boxes[i].max());
        o["centre"] = vec(boxes[i].center());
      }
      o["on"] = supportJson(workcell::supportOf(boxes[i], cell->objects, i), *cell);
      objects.push_back(o);
    }
    j["objects"] = objects;
    j["devices"] = describeDevicesJson(*cell);
    j["wires"] = describeWiresJson(*cell);
    j["inputs"] = kInputs;
    j["outputs"] = kOutputs;
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return kExitOk;
  }

  if (world)
    out << fmt::format("workcell {}: world coordinates, y up, lengths in the cell's unit\n", base::safeText(cell->name));
  else
    out << fmt::format("robot {} alone: its design coordinates (those its description is drawn in), y up\n",
                       base::safeText(cell->drivenRobot()->robot.name));
  for (std::size_t i = 0; i < robots.size(); ++i) {
    out << '\n';
    robotText(robots[i], i == 0, *cell, out);
  }
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    out << fmt::format("\nobject {}  {}\n", i + 1, base::safeText(cell->objects[i].shape.name));
    if (boxes[i].isEmpty()) {
      out << "  (no lines: nothing to grip)\n";
      continue;
    }
    out << fmt::format("  box     {}\n", boxText(boxes[i]));
    out << fmt::format("  centre  {}\n", point(boxes[i].center()));
    out << fmt::format("  on      {}\n", supportText(workcell::supportOf(boxes[i], cell->objects, i), *cell));
  }
  describeDevicesText(*cell, out);
  out << fmt::format("\ninputs 1..{} and outputs 1..{}: the controller's lines (descriptions do not name them)\n",
                     kInputs, kOutputs);
  out << "(values rounded to 4 decimals; --json gives full precision. Reach and span: found by search over whole "
         "encoder counts)\n";
  return kExitOk;
}

void addDescribeOptions(CLI::App* cmd, RobotQuery& q) {
  addRobotArguments(cmd, q,
                    "Workcell or robot: description file (.rsd), URDF file (.urdf) or library name, e.g. scara-pick");
}

}  // namespace rs::cli
