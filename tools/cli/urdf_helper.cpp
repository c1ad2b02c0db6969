// robotsim-urdf: the helper program that reads URDF files for robotsim
// (model/urdf/urdf_read_remote.h says why it is a program of its own).
//
//   robotsim-urdf read FILE [--tip LINK] [--precision P]
//
// writes the robot, or the errors, as urdf_read_wire.h's JSON on stdout
// and exits 0; 2 for a command line it does not understand (it is run by
// robotsim, not by people).
#include <cstdlib>
#include <iostream>
#include <string>

#include "model/urdf/urdf_read.h"
#include "model/urdf/urdf_read_wire.h"

int main(int argc, char** argv) {
  if (argc < 3 || std::string(argv[1]) != "read") {
    std::cerr << "usage: robotsim-urdf read FILE [--tip LINK] [--precision P] (robotsim runs it)\n";
    return 2;
  }
  rs::urdf::UrdfOptions options;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--tip") options.tip = argv[i + 1];
    else if (flag == "--precision") options.precision = std::strtod(argv[i + 1], nullptr);
    else {
      std::cerr << "robotsim-urdf: unknown option " << flag << "\n";
      return 2;
    }
  }
  std::cout << rs::urdf::encodeUrdfRead(rs::urdf::readUrdfFile(argv[2], options));
  return std::cout.good() ? 0 : 1;
}
