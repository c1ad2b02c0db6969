#include "tools/cli/lib/convert_command.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdlib>
#include <fmt/format.h>
#include <set>

#include "base/file_write.h"
#include "base/text.h"
#include "compiler/description/description.h"
#include "compiler/description/library.h"
#include "model/urdf/urdf_read.h"
#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

namespace {

// The shortest text that reads back as the same double, without an
// exponent (descriptions have none).
std::string number(double v) {
  if (v == 0) return "0";
  std::string s = fmt::format("{}", v);
  if (s.find_first_of("eE") == std::string::npos) return s;
  for (int decimals = 1; decimals <= 400; ++decimals) {
    s = fmt::format("{:.{}f}", v, decimals);
    if (std::strtod(s.c_str(), nullptr) == v) return s;
  }
  return s;
}

std::string point(const Eigen::Vector3d& p) { return fmt::format("{} {} {}", number(p.x()), number(p.y()), number(p.z())); }

// A name the description language reads (letters, digits, _ - .,
// starting with a letter or _), unique among `used`.
std::string nameOf(const std::string& urdfName, std::set<std::string>& used) {
  std::string s;
  for (char c : urdfName)
    s += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ? c : '_';
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) s = "_" + s;
  std::string unique = s;
  for (int k = 2; used.contains(unique); ++k) unique = fmt::format("{}_{}", s, k);
  used.insert(unique);
  return unique;
}

std::string frameText(const Eigen::Isometry3d& F) {
  const Eigen::Vector3d o = F.translation();
  return fmt::format("ORIGIN {}  XAXIS {}  ZAXIS {}", point(o), point(o + 100.0 * F.linear().col(0)),
                     point(o + 100.0 * F.linear().col(2)));
}

}  // namespace

std::string descriptionOf(const workcell::Robot& robot) {
  std::set<std::string> used;
  std::string out;
  if (robot.urdf)
    out += fmt::format("; {}: converted from the URDF file {} by robotsim convert (the chain from link {} to link {}).\n"
                       "; Millimetres, y up: URDF's z up turned by -90 degrees about x.\n\n",
                       robot.name, base::safeText(robot.urdf->file), robot.urdf->rootLink, robot.urdf->tipLink);
  std::vector<std::string> linkNames;
  for (const workcell::Shape& link : robot.links) {
    linkNames.push_back(nameOf(link.name, used));
    out += fmt::format("LINK {}\n", linkNames.back());
    for (const workcell::Segment& s : link.segments)
      out += fmt::format("  LINE {}  {}  COLOR {}\n", point(s.a), point(s.b), compiler::colorName(s.color));
    out += "END\n\n";
  }
  out += fmt::format("ROBOT {}\n", nameOf(robot.name, used));
  for (std::size_t i = 0; i < robot.links.size() && i < robot.frames.size(); ++i)
    out += fmt::format("  LINK {}  FRAME {}\n", linkNames[i], frameText(robot.frames[i]));
  for (std::size_t i = 0; i < robot.joints.size(); ++i) {
    const workcell::JointSpec& j = robot.joints[i];
    out += fmt::format("  JOINT {} {}  LETTER {}  PRECISION {}  RANGE {} {}  COUPLING {}  SPEED {}\n", i + 1,
                       j.type == kinematics::JointType::Revolute ? "REVOLUTE" : "PRISMATIC", j.letter,
                       number(j.precision), j.min, j.max, j.coupling ? "ON" : "OFF", j.speed);
  }
  if (robot.tool) out += fmt::format("  TOOL {}\n", frameText(*robot.tool));
  out += "END\n";
  return out;
}

void addConvertOptions(CLI::App* cmd, ConvertOptions& o) {
  cmd->add_option("robot", o.robot.robot, "The URDF file (.urdf)")->required();
  cmd->add_option("-o,--output", o.output, "The description to write (.rsd), or - for standard output")->required();
  cmd->add_option("--lib", o.robot.libDirs, "Also look up names in this directory (repeatable)")->allow_extra_args(false);
  addUrdfOptions(cmd, o.robot);
  cmd->footer(
      "Writes a URDF robot as a robotsim description: its links' lines, every link's D-H frame, its joints with "
      "LETTER, PRECISION, RANGE, COUPLING and SPEED, and a TOOL where the tip link is no D-H frame. robotsim table, "
      "matrix and where give the same answers for both files (docs/models.md, \"Reading URDF\").");
}

int convertCommand(const ConvertOptions& o, std::ostream& out, std::ostream& err) {
  if (!urdf::isUrdfName(o.robot.robot)) {
    err << fmt::format("robotsim: error: convert reads URDF files (.urdf), not '{}'\n", base::safeText(o.robot.robot));
    return kExitBadInput;
  }
  compiler::Library library = queryLibrary(o.robot);
  const std::optional<workcell::Robot> robot = library.robot(o.robot.robot);
  for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
  if (!robot) return kExitBadInput;
  std::string error;
  if (!base::writeFileAtomically(o.output, descriptionOf(*robot), error)) {
    err << fmt::format("{}: error: cannot write: {}\n", base::safeText(o.output), error);
    return kExitBadInput;
  }
  (o.output == "-" ? err : out) << fmt::format("{} -> {} ({} joints)\n", base::safeText(o.robot.robot),
                                               base::safeText(o.output), robot->joints.size());
  return kExitOk;
}

}  // namespace rs::cli
