// The DESIGN ROBOT inspection commands: `robotsim table` (the paper's TABLE,
// Fig. 6), `robotsim matrix` (MATRIX, Fig. 7) and `robotsim where` (the tool
// centre point for given encoder values, in a workcell's world or a robot's
// design coordinates).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rs::compiler {
class Library;
}

namespace rs::cli {

struct RobotQuery {
  std::string robot;                 // file or library name
  std::vector<std::string> libDirs;  // --lib
  bool json = false;
  int from = 0, to = 0;              // matrix I J
  std::string theta;                 // "v,v,..." joint values (degrees or d)
  std::string encoders;              // "v,v,..." encoder counts
  std::string tip;                   // --tip LINK: a URDF chain's last link
  double precision = 0.01;           // --precision: a URDF robot's motors (urdf::kDefaultPrecision)
};

/// The robot argument, --lib and --json of table, matrix, where and
/// describe; `what` is the argument's help.
void addRobotArguments(CLI::App* cmd, RobotQuery& q,
                       const char* what = "Robot description file (.rsd), URDF file (.urdf) or library name, e.g. scorobot");
/// --tip and --precision, for commands that may read a URDF file.
void addUrdfOptions(CLI::App* cmd, RobotQuery& q);
void addTableOptions(CLI::App* cmd, RobotQuery& q);
void addMatrixOptions(CLI::App* cmd, RobotQuery& q);
void addWhereOptions(CLI::App* cmd, RobotQuery& q);

int tableCommand(const RobotQuery& q, std::ostream& out, std::ostream& err);
int matrixCommand(const RobotQuery& q, std::ostream& out, std::ostream& err);
int whereCommand(const RobotQuery& q, std::ostream& out, std::ostream& err);

/// A library that reads URDF files as the query's --tip and --precision say.
compiler::Library queryLibrary(const RobotQuery& q);

/// An angle in degrees brought into (-180, 180], at full precision: -180
/// and 180 are 180, 190 is -170, -179.99999 stays -179.99999.
double normalizeDegrees(double degrees);
/// An angle for the text tables: normalized, then as formatNumber, with a
/// value that rounds to -180 shown as 180 (-179.99999 prints "180").
std::string formatAngle(double degrees);

}  // namespace rs::cli
