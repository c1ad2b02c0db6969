// `robotsim convert ARM.urdf -o ARM.rsd`: a URDF robot written as robotsim's
// own description, which gives the same D-H table, matrices and poses as
// the URDF file (docs/cli.md, "convert"; docs/models.md, "Reading URDF").
#pragma once

#include <ostream>
#include <string>

#include "model/workcell/model.h"
#include "tools/cli/lib/robot_commands.h"

namespace CLI {
class App;
}

namespace rs::cli {

struct ConvertOptions {
  RobotQuery robot;    // the URDF file, --lib, --tip, --precision
  std::string output;  // -o FILE, or - for standard output
};

/// The description (.rsd text) of a robot: a LINK block per link (its
/// lines), the ROBOT with every link's frame, joint and TOOL. Numbers are
/// written so that they read back as the same doubles.
std::string descriptionOf(const workcell::Robot& robot);

void addConvertOptions(CLI::App* cmd, ConvertOptions& o);
int convertCommand(const ConvertOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
