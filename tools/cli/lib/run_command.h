// `robotsim run` and `robotsim check`: load the program, prepare its run,
// run it (in simulation or on a Rhino), trace it, print the summary.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "launch/program.h"
#include "launch/rhino.h"
#include "launch/run_request.h"

namespace CLI {
class App;
}

namespace rs::cli {

/// `run --profile`'s step limit when --max-steps is not given.
inline constexpr std::uint64_t kProfileMaxSteps = 10'000'000;

struct RunCommandOptions {
  launch::ProgramRequest program;
  launch::RunRequest run;
  launch::SerialRequest serial;
  std::string format = "text";  // summary: text or json
  std::string trace;            // "", "text" or "json"
  bool strict = false;          // check: warnings fail too
  bool profile = false;         // run: where the time went (runtime/run/profile.h)
  std::vector<std::string> programs = {};  // run --cell: LABEL=FILE for the cell's robots (cell_run_command.h)
};

/// The options of `run` and of `check` (one RunCommandOptions serves both).
void addRunCommandOptions(CLI::App* cmd, RunCommandOptions& o);
void addCheckCommandOptions(CLI::App* cmd, RunCommandOptions& o);

/// run (`check` false) or check; returns the exit code.
int runOrCheck(const RunCommandOptions& o, bool check, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
