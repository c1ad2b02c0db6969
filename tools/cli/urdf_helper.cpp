// robotsim-urdf: the helper program that reads URDF files for robotsim
// (model/urdf/urdf_read_remote.h says why it is a program of its own).
//
//   robotsim-urdf read FILE [--tip LINK] [--precision P] [--stdin]
//
// (with --stdin the file's text is read from standard input: an editor's
// unsaved buffer, FILE naming it) writes the robot, or the errors, as urdf_read_wire.h's JSON on stdout
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
  bool fromStdin = false;
  for (int i = 3; i < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--stdin") {
      fromStdin = true;
      --i;
    } else if (i + 1 >= argc) {
      std::cerr << "robotsim-urdf: " << flag << " needs a value\n";
      return 2;
    } else if (flag == "--tip") {
      options.tip = argv[i + 1];
    } else if (flag == "--precision") {
      options.precision = std::strtod(argv[i + 1], nullptr);
    } else {
      std::cerr << "robotsim-urdf: unknown option " << flag << "\n";
      return 2;
    }
  }
  if (fromStdin) {
    // At most one byte more than a URDF may be: readUrdfText refuses it.
    std::string text;
    char buffer[1 << 16];
    while (std::cin.read(buffer, sizeof buffer) || std::cin.gcount() > 0) {
      text.append(buffer, static_cast<std::size_t>(std::cin.gcount()));
      if (text.size() > rs::urdf::kMaxUrdfBytes) break;
    }
    std::cout << rs::urdf::encodeUrdfRead(rs::urdf::readUrdfText(text, argv[2], options));
  } else {
    std::cout << rs::urdf::encodeUrdfRead(rs::urdf::readUrdfFile(argv[2], options));
  }
  return std::cout.good() ? 0 : 1;
}
