#include "tools/cli/lib/robot_commands.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/number_text.h"
#include "base/text.h"
#include "compiler/description/library.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"

namespace rs::cli {

using base::formatNumber;

namespace {

using Json = nlohmann::ordered_json;

std::optional<workcell::Robot> loadRobot(const RobotQuery& q, std::ostream& err) {
  compiler::Library library = queryLibrary(q);
  std::optional<workcell::Robot> robot = library.robot(q.robot);
  for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
  return robot;
}

// Joint values q from --theta, --encoders, or home when neither is given.
bool jointValues(const RobotQuery& q, const workcell::Robot& robot, std::vector<double>& values, std::ostream& err) {
  const kinematics::ChainModel& chain = *robot.chain;
  const auto n = static_cast<std::size_t>(chain.size());
  values.assign(n, 0.0);
  if (!q.theta.empty() && !q.encoders.empty()) {
    err << "robotsim: error: give --theta or --encoders, not both\n";
    return false;
  }
  std::vector<double> list;
  if (!q.theta.empty()) {
    if (!parseNumberList(q.theta, "--theta", rules::kJointValue, list, err)) return false;
    if (list.size() != n) {
      err << numberError("--theta", fmt::format("{} values needed (one per joint), found {}", n, list.size()),
                         rules::kJointValue);
      return false;
    }
    values = list;
    return true;
  }
  if (!q.encoders.empty()) {
    if (!parseNumberList(q.encoders, "--encoders", rules::kEncoderCount, list, err)) return false;
    const std::size_t motors = n + (robot.hasGripper ? 1 : 0);
    if (list.size() != n && list.size() != motors) {
      err << numberError("--encoders",
                         fmt::format("{} values needed (one per joint{}), found {}", n,
                                     robot.hasGripper ? ", the gripper's optional" : "", list.size()),
                         rules::kEncoderCount);
      return false;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const workcell::JointSpec& j = robot.joints[i];
      if (list[i] < j.min || list[i] > j.max) {
        err << numberError("--encoders",
                           fmt::format("value {} ({}, joint {}) {} is outside the motor's range {}..{}", i + 1,
                                       j.letter, i + 1, formatNumber(list[i]), j.min, j.max),
                           rules::kEncoderCount);
        return false;
      }
    }
    list.resize(n);
    return kinematics::jointValuesFromEncoders(chain, std::span<const double>(list), values);
  }
  for (std::size_t i = 0; i < n; ++i) values[i] = chain.joint(static_cast<int>(i + 1)).home;
  return true;
}

Json matrixJson(const Eigen::Isometry3d& m) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 4; ++c) {
      const double v = m.matrix()(r, c);
      row.push_back(std::abs(v) < 5e-13 ? 0.0 : v);
    }
    rows.push_back(row);
  }
  return rows;
}

std::string matrixText(const Eigen::Isometry3d& m) {
  std::string out;
  for (int r = 0; r < 4; ++r) {
    out += "  ";
    for (int c = 0; c < 4; ++c) out += fmt::format("{:>12}", fmt::format("{:.4f}", m.matrix()(r, c) + 0.0));
    out += '\n';
  }
  // "-0.0000" would read as a sign where there is none.
  for (std::size_t p = out.find("-0.0000"); p != std::string::npos; p = out.find("-0.0000", p))
    out.replace(p, 7, " 0.0000");
  return out;
}

// Which D-H case a row is (model/urdf/urdf_dh.h), from its values.
std::string_view rowCase(const kinematics::DhRow& r) {
  const double alpha = std::abs(normalizeDegrees(r.alpha));
  const bool parallel = alpha < 1e-9 || std::abs(alpha - 180.0) < 1e-9;
  if (parallel) return std::abs(r.a) < 1e-9 ? "collinear" : "parallel";
  return std::abs(r.a) < 1e-9 ? "intersecting" : "skew";
}

// What a URDF robot's table says besides its rows: where the robot came
// from, and the base and tool transforms the rows do not hold.
void urdfTableText(const workcell::Robot& robot, std::ostream& out) {
  const workcell::UrdfSource& u = *robot.urdf;
  out << fmt::format("from URDF file {}, chain from link {} to link {} (design coordinates: mm, y up)\n",
                     base::safeText(u.file), base::safeText(u.rootLink), base::safeText(u.tipLink));
  out << "BASE: frame 0 in the root link's frame (turned to y up):\n" << matrixText(robot.frames.front());
  out << fmt::format("TOOL: the tip link's frame in frame {}{}:\n", robot.chain->size(),
                     robot.chain->hasTool() ? "" : " (the tip is frame n itself)");
  out << matrixText(robot.chain->F_n_tool());
  out << "D-H choices: frame 0 on joint 1's axis at the foot of the root's origin; parallel axes take the common "
         "normal through the frame before (d = 0); intersecting axes x = z(i-1) x z(i); skew and parallel axes "
         "a > 0; collinear axes keep x (docs/models.md, \"Reading URDF\")\n";
}

}  // namespace

compiler::Library queryLibrary(const RobotQuery& q) {
  compiler::Library library(compiler::librarySearchPath(q.libDirs));
  library.setUrdfOptions({q.tip, q.precision});
  return library;
}

double normalizeDegrees(double degrees) {
  double d = std::remainder(degrees, 360.0);  // exact, in [-180, 180]
  if (d <= -180.0) d += 360.0;
  return d + 0.0;  // never -0
}

std::string formatAngle(double degrees) {
  const std::string s = formatNumber(normalizeDegrees(degrees));
  return s == "-180" ? "180" : s;
}

int tableCommand(const RobotQuery& q, std::ostream& out, std::ostream& err) {
  const std::optional<workcell::Robot> robot = loadRobot(q, err);
  if (!robot) return kExitBadInput;
  const std::vector<kinematics::DhRow> rows = robot->chain->table();
  if (q.json) {
    Json j;
    j["robot"] = robot->name;
    Json list = Json::array();
    // Full double precision (the shortest text that reads back as the
    // same double); angles brought into (-180, 180].
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const kinematics::DhRow& r = rows[i];
      const bool revolute = r.type == kinematics::JointType::Revolute;
      list.push_back({{"axis", i + 1},
                      {"type", kinematics::jointTypeName(r.type)},
                      {"theta", normalizeDegrees(r.theta)},
                      {"alpha", normalizeDegrees(r.alpha)},
                      {"a", r.a + 0.0},
                      {"d", r.d + 0.0},
                      {"home", revolute ? normalizeDegrees(r.home()) : r.home() + 0.0}});
    }
    j["rows"] = list;
    if (robot->urdf) {
      j["urdf"] = {{"file", robot->urdf->file}, {"root", robot->urdf->rootLink}, {"tip", robot->urdf->tipLink}};
      for (std::size_t i = 0; i < rows.size(); ++i) j["rows"][i]["case"] = std::string(rowCase(rows[i]));
    }
    if (robot->urdf || robot->chain->hasTool()) {
      j["base"] = matrixJson(robot->frames.front());
      j["tool"] = matrixJson(robot->chain->F_n_tool());
    }
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return kExitOk;
  }
  out << fmt::format("KINEMATIC PARAMETERS: {} (standard D-H; degrees and length units)\n",
                     base::safeText(robot->name));
  out << fmt::format("{:<6}{:<11}{:>10}{:>10}{:>10}{:>10}{:>10}\n", "AXIS", "TYPE", "theta", "alpha", "a", "d", "home");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const kinematics::DhRow& r = rows[i];
    const bool revolute = r.type == kinematics::JointType::Revolute;
    out << fmt::format("{:<6}{:<11}{:>10}{:>10}{:>10}{:>10}{:>10}\n", i + 1, kinematics::jointTypeName(r.type),
                       revolute ? fmt::format("theta{}", i + 1) : formatAngle(r.theta), formatAngle(r.alpha),
                       formatNumber(r.a), revolute ? formatNumber(r.d) : fmt::format("d{}", i + 1),
                       revolute ? formatAngle(r.home()) : formatNumber(r.home()));
  }
  if (robot->urdf) urdfTableText(*robot, out);
  else if (robot->chain->hasTool()) out << "TOOL: the tool frame in frame n:\n" << matrixText(robot->chain->F_n_tool());
  out << "(values rounded to 4 decimals, angles in (-180, 180]; --json gives full precision)\n";
  return kExitOk;
}

int matrixCommand(const RobotQuery& q, std::ostream& out, std::ostream& err) {
  const std::optional<workcell::Robot> robot = loadRobot(q, err);
  if (!robot) return kExitBadInput;
  const kinematics::ChainModel& chain = *robot->chain;
  const int n = chain.size();
  if (q.from < 0 || q.from > n || q.to < 0 || q.to > n) {
    err << fmt::format("robotsim: error: frames are numbered 0..{} for {}, got {} and {}\n", n,
                       base::safeText(robot->name), q.from, q.to);
    return kExitBadInput;
  }
  std::vector<double> values;
  if (!jointValues(q, *robot, values, err)) return kExitBadInput;
  kinematics::ChainData data(chain);
  kinematics::forwardKinematics(chain, data, values);
  const Eigen::Isometry3d m = *kinematics::transform(chain, data, q.from, q.to);
  if (q.json) {
    Json j;
    j["from"] = q.from;
    j["to"] = q.to;
    j["matrix"] = matrixJson(m);
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return kExitOk;
  }
  out << fmt::format("TRANSFORMATION MATRIX T_{}^{} of {} (coordinates in frame {} to frame {}):\n", q.to, q.from,
                     base::safeText(robot->name), q.to, q.from);
  out << matrixText(m);
  std::string joints;
  for (int i = 1; i <= n; ++i)
    joints += fmt::format("{}{}{} = {}", i > 1 ? "  " : "",
                          chain.joint(i).type() == kinematics::JointType::Revolute ? "theta" : "d", i,
                          formatNumber(values[static_cast<std::size_t>(i - 1)]));
  out << joints << '\n';
  return kExitOk;
}

// `where ROBOT` answers in the robot's design coordinates, `where CELL` in
// the workcell's world: the same chain, placed where the cell puts the
// robot's link 0 (a lone robot stands where it was drawn, so both agree).
int whereCommand(const RobotQuery& q, std::ostream& out, std::ostream& err) {
  compiler::Library library = queryLibrary(q);
  std::optional<workcell::Workcell> cell = library.workcell(q.robot);
  const bool world = cell && library.holdsWorkcell(q.robot);
  for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
  if (!cell) return kExitBadInput;
  if (cell->robots.empty()) {
    err << fmt::format("robotsim: error: workcell {} places no robot\n", base::safeText(cell->name));
    return kExitBadInput;
  }
  const workcell::PlacedRobot& placed = *cell->drivenRobot();
  const workcell::Robot& robot = placed.robot;
  const kinematics::ChainModel chain = robot.chain->placedAt(placed.F_world_design * robot.frames.front());
  std::vector<double> values;
  if (!jointValues(q, robot, values, err)) return kExitBadInput;
  kinematics::ChainData data(chain);
  kinematics::forwardKinematics(chain, data, values);
  const Eigen::Isometry3d tool = kinematics::toolPose(chain, data);
  const Eigen::Vector3d p = tool.translation();
  // Roll, pitch, yaw: rotations about x, y, z applied in that order (R = Rz Ry Rx).
  const Eigen::Matrix3d r = tool.linear();
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  double roll = std::atan2(r(2, 1), r(2, 2)), yaw = std::atan2(r(1, 0), r(0, 0));
  // At pitch ±90 degrees roll and yaw turn about the same axis (gimbal
  // lock): only their sum or difference is defined, so yaw is taken as 0.
  if (std::abs(r(2, 0)) > 1.0 - 1e-9) {
    yaw = 0.0;
    roll = std::atan2(-r(1, 2), r(1, 1));
  }
  const double deg = 180.0 / M_PI;
  // atan2 gives -180 or 180 by the sign of a zero: report (-180, 180].
  const auto angle = [&](double radians) { return normalizeDegrees(radians * deg); };
  if (q.json) {
    // Full precision, as matrix --json; a workcell's world coordinates
    // ("cell" and "frame" say so), else the robot's design coordinates.
    Json j;
    if (world) j["cell"] = cell->name;
    j["robot"] = robot.name;
    if (world) j["frame"] = "world";
    j["position"] = {p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    j["rpy"] = {angle(roll), angle(pitch), angle(yaw)};
    j["matrix"] = matrixJson(tool);
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return kExitOk;
  }
  const std::string who = world ? fmt::format("{} ({})", base::safeText(cell->name), base::safeText(robot.name))
                                : base::safeText(robot.name);
  out << fmt::format("{}: tool centre point at ({}, {}, {})\n", who, formatNumber(p.x()), formatNumber(p.y()),
                     formatNumber(p.z()));
  out << fmt::format("  normal n   ({}, {}, {})\n", formatNumber(r(0, 0)), formatNumber(r(1, 0)), formatNumber(r(2, 0)));
  out << fmt::format("  approach a ({}, {}, {})\n", formatNumber(r(0, 2)), formatNumber(r(1, 2)), formatNumber(r(2, 2)));
  out << fmt::format("  roll {}  pitch {}  yaw {} (degrees, R = Rz(yaw) Ry(pitch) Rx(roll))\n", formatAngle(roll * deg),
                     formatAngle(pitch * deg), formatAngle(yaw * deg));
  if (world) {
    const Eigen::Vector3d base = chain.F_world_0().translation();
    out << fmt::format("(world coordinates of workcell {}, whose {} has link 0's origin at ({}, {}, {}); values "
                       "rounded to 4 decimals, angles in (-180, 180]; --json gives full precision)\n",
                       base::safeText(cell->name), base::safeText(robot.name), formatNumber(base.x()),
                       formatNumber(base.y()), formatNumber(base.z()));
  } else {
    out << "(the robot's design coordinates, those its description is drawn in; values rounded to 4 decimals, "
           "angles in (-180, 180]; --json gives full precision)\n";
  }
  return kExitOk;
}

void addRobotArguments(CLI::App* cmd, RobotQuery& q, const char* what) {
  cmd->add_option("robot", q.robot, what)->required();
  cmd->add_option("--lib", q.libDirs, "Also look up names in this directory (repeatable)")->allow_extra_args(false);
  cmd->add_flag("--json", q.json, "Print one JSON object");
  addUrdfOptions(cmd, q);
}

void addUrdfOptions(CLI::App* cmd, RobotQuery& q) {
  cmd->add_option("--tip", q.tip, "A URDF robot's chain ends at this link (where its tree has several leaves)");
  cmd->add_option("--precision", q.precision,
                  "A URDF robot's motors: degrees (or mm) per encoder count (default 0.01)")
      ->check(CLI::PositiveNumber);
}

namespace {

void addJointOptions(CLI::App* cmd, RobotQuery& q) {
  cmd->add_option("--theta", q.theta, "Joint values v,v,... (degrees; a prismatic joint's d)")
      ->transform(numberListArg(rules::kJointValue));
  cmd->add_option("--encoders", q.encoders, "Encoder counts v,v,... (default: the home position)")
      ->transform(numberListArg(rules::kEncoderCount));
}

}  // namespace

void addTableOptions(CLI::App* cmd, RobotQuery& q) { addRobotArguments(cmd, q); }

void addMatrixOptions(CLI::App* cmd, RobotQuery& q) {
  addRobotArguments(cmd, q);
  cmd->add_option("i", q.from, "Frame I (0 = base)")->required()->transform(numberArg(rules::kFrameNumber));
  cmd->add_option("j", q.to, "Frame J")->required()->transform(numberArg(rules::kFrameNumber));
  addJointOptions(cmd, q);
}

void addWhereOptions(CLI::App* cmd, RobotQuery& q) {
  addRobotArguments(cmd, q, "Workcell or robot: description file (.rsd) or library name, e.g. scara-pick or scorobot");
  addJointOptions(cmd, q);
}

}  // namespace rs::cli
