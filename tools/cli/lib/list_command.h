// `robotsim list [--lib DIR]`: what the library holds (robots, grippers,
// objects, workcells, one line each with what it is) and the search path
// it looked in, in lookup order.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rs::cli {

struct ListOptions {
  std::vector<std::string> libDirs;  // --lib
};

void addListOptions(CLI::App* cmd, ListOptions& o);
int listCommand(const ListOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
