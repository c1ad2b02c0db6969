// robotsim: the command-line entry point. All the work is in tools/cli/lib.
#include <iostream>

#include "tools/cli/lib/app.h"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  return rs::cli::runCommand(argc, argv, std::cout, std::cerr);
}
