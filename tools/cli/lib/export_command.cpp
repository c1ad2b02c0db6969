#include "tools/cli/lib/export_command.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "base/file_write.h"
#include "base/text.h"
#include "compiler/description/library.h"
#include "model/urdf/urdf_export.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"

namespace rs::cli {

namespace {

constexpr NumberRule kMillimetresPerUnit{
    "millimetres per length unit", 0.0, 1e6, false, true,
    "1 for the library's millimetres, 2 for the paper's drawing units (scorobot, rhino-scara)"};

}  // namespace

void addExportOptions(CLI::App* cmd, ExportOptions& o) {
  cmd->add_option("robot", o.robot, "Robot description file (.rsd) or library name, e.g. abb-irb120")->required();
  cmd->add_option("--lib", o.libDirs, "Also look up names in this directory (repeatable)")->allow_extra_args(false);
  cmd->add_flag("--urdf", o.urdf, "Write URDF, the Robot Description Format of ROS (the one format; required)")
      ->required();
  cmd->add_option("-o,--output", o.output, "The file to write (replaced atomically), or - for standard output")
      ->required();
  cmd->add_option("--mm-per-unit", o.mmPerUnit,
                  "Millimetres per length unit of the description (default 1; the paper's scorobot and "
                  "rhino-scara are drawn in units of 2 mm)")
      ->transform(numberArg(kMillimetresPerUnit));
  cmd->add_option("--up", o.up,
                  "The description's up axis, turned to URDF's z: y (the library's convention, default) or z "
                  "(scorobot)")
      ->check(CLI::IsMember({"y", "z"}));
}

int exportCommand(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  compiler::Library library(compiler::librarySearchPath(o.libDirs));
  const std::optional<workcell::Robot> robot = library.robot(o.robot);
  for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
  if (!robot) return kExitBadInput;
  urdf::ExportOptions options;
  options.millimetresPerUnit = o.mmPerUnit;
  options.up = o.up == "z" ? urdf::UpAxis::Z : urdf::UpAxis::Y;
  diag::Result<std::string> text = urdf::exportUrdf(*robot, options);
  if (!text) {
    err << fmt::format("robotsim: error: {}\n", text.failure().message);
    return kExitBadInput;
  }
  if (o.output == "-") {
    out << *text;
    return kExitOk;
  }
  std::string error;
  if (!base::writeFileAtomically(o.output, *text, error)) {
    err << fmt::format("{}: error: cannot write: {}\n", base::safeText(o.output), error);
    return kExitBadInput;
  }
  const int joints = robot->chain->size();
  out << fmt::format("{} -> {} (URDF: {} joint{}{}, {} bytes)\n", base::safeText(robot->name),
                     base::safeText(o.output), joints, joints == 1 ? "" : "s",
                     robot->hasGripper ? " and a gripper" : "", text->size());
  return kExitOk;
}

}  // namespace rs::cli
