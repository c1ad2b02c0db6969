// The exit codes of every robotsim command (docs/cli.md, "Exit codes").
#pragma once

namespace rs::cli {

enum ExitCode : int {
  kExitOk = 0,         ///< all is well
  kExitRunFailed = 1,  ///< the program ran and failed: runtime error, deadlock, step or time limit
  kExitBadInput = 2,   ///< nothing could run: a compile error, unreadable or corrupt input, or bad usage
};

}  // namespace rs::cli
