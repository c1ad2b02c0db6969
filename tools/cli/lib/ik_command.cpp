#include "tools/cli/lib/ik_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/ascii.h"
#include "base/number_text.h"
#include "base/text.h"
#include "compiler/description/library.h"
#include "compiler/program/kinematics_diagnostic.h"
#include "diag/diagnostic.h"
#include "model/kinematics/ik.h"
#include "model/workcell/pose_solver.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"
#include "tools/cli/lib/robot_commands.h"

namespace rs::cli {

using base::formatNumber;

namespace {

using Json = nlohmann::ordered_json;

// "1,0,-1" -> numbers by `rule`, `want` of them (any number when 0); an
// error names the option.
bool numbers(const std::string& text, std::string_view option, const NumberRule& rule, std::size_t want,
             std::vector<double>& out, std::ostream& err) {
  if (!parseNumberList(text, option, rule, out, err)) return false;
  if (want != 0 && out.size() != want) {
    err << numberError(option, fmt::format("{} numbers needed, separated by commas; found {}", want, out.size()), rule);
    return false;
  }
  return true;
}

std::string configText(std::uint8_t config, kinematics::IkFamily family) {
  if (family == kinematics::IkFamily::Cartesian || family == kinematics::IkFamily::Numeric) return "the only one";
  std::string s = config & kinematics::kShoulderBack ? "shoulder back" : "shoulder front";
  if (family == kinematics::IkFamily::Scara) s.clear();
  s += fmt::format("{}elbow {}", s.empty() ? "" : ", ", config & kinematics::kElbowDown ? "-" : "+");
  if (family == kinematics::IkFamily::Articulated6 || family == kinematics::IkFamily::Spherical6)
    s += config & kinematics::kWristFlip ? ", wrist flipped" : ", wrist not flipped";
  return s;
}

}  // namespace

void addIkOptions(CLI::App* cmd, IkOptions& o) {
  cmd->add_option("robot", o.target, "Robot or workcell: description file (.rsd) or library name, e.g. puma-cell")
      ->required();
  cmd->add_option("xyz", o.position, "The tool centre point X Y Z")
      ->expected(3)
      ->required()
      ->transform(numberArg(rules::kCoordinate));
  cmd->add_option("--approach", o.approach, "The tool's approach direction a (its z axis) ax,ay,az")
      ->transform(numberListArg(rules::kDirection));
  cmd->add_option("--normal", o.normal, "The tool's normal n (its x axis, the way the fingers close) nx,ny,nz")
      ->transform(numberListArg(rules::kDirection));
  cmd->add_option("--grip", o.grip, "The gripper motor's encoder count (default: the --from point's)")
      ->transform(numberArg(rules::kEncoderCount))
      ->each([&o](const std::string&) { o.gripGiven = true; });
  cmd->add_option("--frame", o.frame, "Coordinates of X Y Z and the directions: world (the cell's; the default) or "
                                      "robot (the robot's design coordinates, as `where` prints)")
      ->check(CLI::IsMember({"world", "robot"}));
  cmd->add_option("--from", o.from, "The previous point's encoder counts e,e,... (default: home, all 0)")
      ->transform(numberListArg(rules::kEncoderCount));
  cmd->add_option("--name", o.name, "The point's name in the POINTS line (default P1)");
  cmd->add_option("--lib", o.libDirs, "Also look up names in this directory (repeatable)")->allow_extra_args(false);
  cmd->add_option("--tip", o.tip, "A URDF robot's chain ends at this link (where its tree has several leaves)");
  cmd->add_option("--precision", o.precision, "A URDF robot's motors: degrees (or mm) per encoder count (default 0.01)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--solution", o.solution,
                  "Only configuration N of the family (1-based; scara: elbow +, -; articulated-5: shoulder front "
                  "elbow +, -, back +, -; six-axis: each of those with the wrist not flipped, then flipped), solved "
                  "alone")
      ->transform(numberArg(rules::kSolution));
  cmd->add_flag("--json", o.json, "Print one JSON object");
  cmd->footer(
      "Solves in closed form for the library's arm families (cartesian, scara, articulated-5, articulated-6,\n"
      "spherical-6), numerically for other robots (docs/models.md). What is not given is kept from the --from\n"
      "point; of several solutions the quickest move from it within the motors' ranges is chosen, as the\n"
      "compiler does for a point written 'NAME AT X Y Z ...' (docs/language.md). Negative numbers: put\n"
      "'--' before X Y Z when X starts with '-', e.g. robotsim ik scara-pick -- -130 800 0.");
}

int ikCommand(const IkOptions& o, std::ostream& out, std::ostream& err) {
  compiler::Library library(compiler::librarySearchPath(o.libDirs));
  library.setUrdfOptions({o.tip, o.precision});
  const std::optional<workcell::Workcell> cell = library.workcell(o.target);
  for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
  if (!cell || library.hasErrors()) return kExitBadInput;
  if (!cell->drivenRobot() || !cell->drivenRobot()->robot.chain) {
    err << fmt::format("robotsim: error: {} has no robot with a kinematic chain\n", base::safeText(o.target));
    return kExitBadInput;
  }
  const workcell::PlacedRobot& placed = *cell->drivenRobot();
  const workcell::PoseSolver solver(placed);
  // A URDF arm gets a closed form where its geometry is one of the families;
  // the numeric method is for robotsim's own descriptions (docs/models.md,
  // "Reading URDF").
  if (placed.robot.urdf && solver.ik().family() == kinematics::IkFamily::Numeric) {
    err << fmt::format("robotsim: error: no closed-form inverse kinematics applies to {}: its D-H table is none of "
                       "the families cartesian, scara, articulated-5, articulated-6, spherical-6\n"
                       "  hint: robotsim table {} shows the table; docs/models.md, \"Inverse kinematics\", the families\n",
                       base::safeText(placed.robot.name), base::safeText(o.target));
    return kExitBadInput;
  }
  workcell::PoseRequest request;
  request.robotFrame = o.frame == "robot";
  request.position = Eigen::Vector3d(o.position[0], o.position[1], o.position[2]);
  std::vector<double> v;
  if (!o.approach.empty()) {
    if (!numbers(o.approach, "--approach", rules::kDirection, 3, v, err)) return kExitBadInput;
    request.approach = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  if (!o.normal.empty()) {
    if (!numbers(o.normal, "--normal", rules::kDirection, 3, v, err)) return kExitBadInput;
    request.normal = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  if (o.gripGiven) request.grip = o.grip;
  const std::span<const std::uint8_t> configurations = solver.ik().configurations();
  if (o.solution > configurations.size()) {
    err << fmt::format("--solution: error: the {} family has {} configuration{}: N from 1 to {}\n",
                       kinematics::familyName(solver.ik().family()), configurations.size(),
                       configurations.size() == 1 ? "" : "s", configurations.size());
    return kExitBadInput;
  }
  if (o.solution) request.configuration = configurations[o.solution - 1];
  std::vector<std::int32_t> reference(solver.motorCount(), 0);
  if (!o.from.empty()) {
    if (!numbers(o.from, "--from", rules::kEncoderCount, reference.size(), v, err)) return kExitBadInput;
    for (std::size_t i = 0; i < v.size(); ++i) reference[i] = static_cast<std::int32_t>(std::lround(v[i]));
  }
  request.optionWords = true;
  const workcell::PoseResult r = solver.solveAnyOrientation(request, reference);
  const std::vector<vm::MotorSpec> motors = compiler::motorTable(placed.robot);
  const std::string robotName = base::safeText(placed.robot.name);
  const kinematics::IkFamily family = solver.ik().family();
  if (!r.ok()) {
    err << diag::render(compiler::kinematicsDiagnostic(*r.problem, {"robotsim", placed.robot.name, {}}), nullptr);
    return kExitBadInput;
  }
  std::string pose = fmt::format("AT {}{} {} {}", request.robotFrame ? "ROBOT " : "", formatNumber(o.position[0]),
                                 formatNumber(o.position[1]), formatNumber(o.position[2]));
  std::string line = base::safeText(o.name);
  for (const std::int32_t e : r.encoders) line += fmt::format(" {}", e);
  if (o.json) {
    Json j;
    j["robot"] = placed.robot.name;
    j["family"] = kinematics::familyName(family);
    j["frame"] = o.frame;
    j["position"] = o.position;
    j["solutions"] = r.solutions;
    j["in_range"] = r.inRange;
    if (o.solution) j["solution"] = o.solution;
    j["joints"] = r.q;
    j["approach"] = {r.rotation(0, 2), r.rotation(1, 2), r.rotation(2, 2)};
    j["normal"] = {r.rotation(0, 0), r.rotation(1, 0), r.rotation(2, 0)};
    j["orientations_tried"] = r.orientationsTried;
    j["turned"] = r.turned;
    Json enc = Json::object();
    for (std::size_t i = 0; i < r.encoders.size(); ++i) enc[std::string(1, motors[i].letter)] = r.encoders[i];
    j["encoders"] = enc;
    j["rounding"] = r.rounding;
    j["points_line"] = line;
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return kExitOk;
  }
  out << fmt::format("{} ({} family): tool centre point {} ({} coordinates)\n", robotName,
                     kinematics::familyName(family), pose, request.robotFrame ? "the robot's design" : "world");
  if (o.solution)
    out << fmt::format("  solution {} of {} asked for ({}), solved alone\n", o.solution, configurations.size(),
                       configText(r.config, family));
  else
    out << fmt::format("  {} solution{}, {} within the motors' ranges; chosen: {} (the quickest move from {})\n",
                       r.solutions, r.solutions == 1 ? "" : "s", r.inRange, configText(r.config, family),
                       o.from.empty() ? "home" : "--from");
  if (r.orientationsTried > 0) {
    const auto axis = [&](int c) {
      return fmt::format("{},{},{}", formatNumber(r.rotation(0, c)), formatNumber(r.rotation(1, c)),
                         formatNumber(r.rotation(2, c)));
    };
    out << fmt::format("  the orientation kept from {} does not reach it; free orientation {} tried, turned {} "
                       "degrees from it, does: --approach {} --normal {}\n",
                       o.from.empty() ? "home" : "--from", r.orientationsTried, formatNumber(r.turned), axis(2),
                       axis(0));
  }
  std::string joints;
  for (std::size_t i = 0; i < r.q.size(); ++i)
    joints += fmt::format("{}{}", i ? "  " : "", formatNumber(r.q[i]));
  out << fmt::format("  joint values {}\n", joints);
  std::string encoders;
  for (std::size_t i = 0; i < r.encoders.size(); ++i)
    encoders += fmt::format("{}{}={}", i ? " " : "", motors[i].letter, r.encoders[i]);
  out << fmt::format("  encoders {}\n", encoders);
  out << fmt::format("  whole encoder counts put the tool centre point {} from the exact pose\n",
                     formatNumber(r.rounding));
  out << "POINTS line:\n" << line << '\n';
  return kExitOk;
}

}  // namespace rs::cli
