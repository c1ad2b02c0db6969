// `robotsim ik ROBOT|CELL X Y Z`: the encoder counts that put a robot's tool
// at a pose, and the POINTS line to paste into a program. The same solver
// as points written as poses (model/workcell/pose_solver.h), so the answer
// is the one the compiler would give.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rs::cli {

struct IkOptions {
  std::string target;                // robot or workcell: file or library name
  std::vector<double> position;      // X Y Z
  std::vector<std::string> libDirs;  // --lib
  std::string approach, normal;      // "x,y,z"
  std::string from;                  // the previous point's encoder counts "e,e,..."
  std::string frame = "world";       // world | robot
  std::string name = "P1";           // the point's name in the POINTS line
  int grip = 0;
  bool gripGiven = false;
  unsigned solution = 0;             // --solution N (1-based in the family's configurations), 0: choose
  bool json = false;
  std::string tip;                   // --tip, --precision: a URDF robot's
  double precision = 0.01;
};

void addIkOptions(CLI::App* cmd, IkOptions& o);
int ikCommand(const IkOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
