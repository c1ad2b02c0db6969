// robotsim's zsh completion function (`_robotsim`, for a folder on
// $fpath), written from the command table (completion_spec.h) with zsh's
// own _arguments and _describe: commands with their help, each command's
// options with theirs, fixed words, library names after --cell, --robot
// and a command's cell or robot argument (asked of robotsim itself:
// `robotsim __complete`), file names elsewhere. robotsim_gen_docs writes it.
#pragma once

#include <string>

#include "tools/cli/lib/commands.h"

namespace rs::cli {

/// The file zsh autoloads: "#compdef robotsim" and the function.
std::string zshCompletion(const CommandLine& commandLine);

}  // namespace rs::cli
