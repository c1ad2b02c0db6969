// `robotsim export ROBOT --urdf -o FILE|-`: a robot (a library name or a
// .rsd) written as URDF for the ROS world (model/urdf/urdf_export.h;
// docs/models.md, "Writing URDF").
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rs::cli {

struct ExportOptions {
  std::string robot;                 // file or library name
  std::vector<std::string> libDirs;  // --lib
  bool urdf = false;                 // --urdf: the format (the only one)
  std::string output;                // -o FILE, or - for standard output
  double mmPerUnit = 1;              // --mm-per-unit
  std::string up = "y";              // --up y|z
};

void addExportOptions(CLI::App* cmd, ExportOptions& o);

int exportCommand(const ExportOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
