// The `robotsim` command as a function, so tests run it in-process.
#pragma once

#include <ostream>

#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

int runCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
