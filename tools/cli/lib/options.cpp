#include "tools/cli/lib/options.h"

#include <CLI/CLI.hpp>

#include "tools/cli/lib/number_args.h"

namespace rs::cli {

void addCellOptions(CLI::App* cmd, launch::ProgramRequest& request) {
  cmd->add_option("--cell", request.cell,
                  "Workcell (or robot) description file or library name to run on (an image carries its own)");
  cmd->add_option("--robot", request.robot,
                  "In a cell of several robots, the one (its label) the program runs on; default: the "
                  "program's '; robot:' line, else the robot whose PROGRAM it is, else the first");
  addLibOption(cmd, request);
}

void addLibOption(CLI::App* cmd, launch::ProgramRequest& request) {
  cmd->add_option("--lib", request.libDirs, "Also look up description names in this directory (repeatable)")
      ->allow_extra_args(false);
}

void addMaxErrorsOption(CLI::App* cmd, launch::ProgramRequest& request) {
  request.maxErrors = kDefaultMaxErrors;
  cmd->add_option("--max-errors", request.maxErrors,
                  "Print at most N errors and warnings, then how many more there were (default " +
                      std::to_string(kDefaultMaxErrors) + "; 0 prints all)")
      ->option_text("N")
      ->transform(numberArg(rules::kShownCount));
}

void addRunOptions(CLI::App* cmd, launch::RunRequest& request, const std::string& maxStepsDefault) {
  cmd->add_option("--input", request.inputs, "Input change N=ON@SECONDS or N=OFF@SECONDS (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--stimuli", request.stimuliFile, "Stimuli file: timed input changes and reactive rules");
  cmd->add_option_function<std::uint64_t>(
         "--max-steps", [&request](const std::uint64_t& n) { request.maxSteps = n; },
         "Stop after this many instructions (default " + maxStepsDefault + ")")
      ->transform(numberArg(rules::kStepCount));
  cmd->add_option("--max-time", request.maxTime, "Stop at this simulated time in seconds (default 3600)");
  cmd->add_option_function<std::uint64_t>(
         "--max-knots", [&request](const std::uint64_t& n) { request.maxKnots = n; },
         "Stop after the straight line (MOVES, APPRO, DEPART) that takes the small moves it is made of past this "
         "many in all (default " +
             std::to_string(vm::RunLimits{}.maxKnots) + ")")
      ->transform(numberArg(rules::kStepCount));
  addCollisionsOption(cmd, request.collisions);
}

void addCollisionsOption(CLI::App* cmd, std::string& mode) {
  cmd->add_option("--collisions", mode,
                  "On a workcell, what a collision during a move does: error (default: the run stops with a runtime "
                  "error naming the line, time and parts), warn (a warning at the move's line, in the trace and the "
                  "summary; the run goes on) or off (nothing is checked)")
      ->option_text("MODE");
}

}  // namespace rs::cli
