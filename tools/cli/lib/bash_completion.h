// robotsim's bash completion script, written from the command table
// (completion_spec.h): the first word completes to a command, a word
// starting with '-' to that command's options, the value of --cell, --robot
// and of a command's cell or robot argument to the library's names (asked
// of robotsim itself: `robotsim __complete`), an option's fixed words to
// those words, anything else to file names. robotsim_gen_docs writes it.
#pragma once

#include <string>

#include "tools/cli/lib/commands.h"

namespace rs::cli {

/// The function completing robotsim's words (`complete -F` names it).
inline constexpr const char* kBashCompletionFunction = "_robotsim";

/// A script for bash to source: defines the function and registers it for
/// `robotsim`.
std::string bashCompletion(const CommandLine& commandLine);

}  // namespace rs::cli
