// The `robotsim` command as a function, so tests run it in-process.
#pragma once

#include <ostream>

namespace rs::cli {

/// Exit codes, documented in docs/cli.md.
enum Exit : int {
  kOk = 0,
  kRunFailed = 1,      // runtime error, deadlock, step or time limit
  kCompileError = 2,   // compile error, unreadable or corrupt input, bad usage
};

int runCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
