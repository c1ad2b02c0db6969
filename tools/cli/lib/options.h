// The options several commands share, each defined once: the program's
// workcell (--cell, --lib) and a run's stimuli and limits (--input,
// --stimuli, --max-steps, --max-time). Commands add them with these
// functions; the values land in the launch layer's requests.
#pragma once

#include <string>

#include "launch/program.h"
#include "launch/run_request.h"

namespace CLI {
class App;
}

namespace rs::cli {

/// --cell CELL (the workcell or robot to compile and run for) and --lib DIR.
void addCellOptions(CLI::App* cmd, launch::ProgramRequest& request);
/// --lib DIR alone (for commands whose workcell is a positional argument).
void addLibOption(CLI::App* cmd, launch::ProgramRequest& request);
/// --max-errors N: the commands that compile print at most N diagnostics
/// (kDefaultMaxErrors unless given; 0 = all), then how many more there were.
inline constexpr std::size_t kDefaultMaxErrors = 50;
void addMaxErrorsOption(CLI::App* cmd, launch::ProgramRequest& request);
/// --input, --stimuli, --max-steps, --max-time. `maxStepsDefault` is what
/// --help says when --max-steps is not given.
void addRunOptions(CLI::App* cmd, launch::RunRequest& request, const std::string& maxStepsDefault = "100000000");
/// --collisions error|warn|off (part of addRunOptions; alone for `test`).
void addCollisionsOption(CLI::App* cmd, std::string& mode);

}  // namespace rs::cli
