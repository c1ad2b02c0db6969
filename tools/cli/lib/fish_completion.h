// robotsim's fish completions (robotsim.fish, for a vendor_completions.d
// folder), written from the command table (completion_spec.h) as fish's
// own `complete` lines: commands with their help, each command's options
// with theirs, fixed words, library names after --cell, --robot and a
// command's cell or robot argument (asked of robotsim itself:
// `robotsim __complete`), file names elsewhere. robotsim_gen_docs writes it.
#pragma once

#include <string>

#include "tools/cli/lib/commands.h"

namespace rs::cli {

std::string fishCompletion(const CommandLine& commandLine);

}  // namespace rs::cli
