// robotsim's bash completion script, written from the command table and
// CLI11's lists of each command's options: the first word completes to a
// command, a word starting with '-' to that command's options, anything
// else to file names. robotsim_gen_docs writes it.
#pragma once

#include <string>

#include "cli/lib/commands.h"

namespace rs::cli {

/// The function completing robotsim's words (`complete -F` names it).
inline constexpr const char* kBashCompletionFunction = "_robotsim";

/// A script for bash to source: defines the function and registers it for
/// `robotsim`.
std::string bashCompletion(const CommandLine& commandLine);

}  // namespace rs::cli
