// robotsim's man pages, in troff with the man macros (man 7 man-pages:
// NAME, SYNOPSIS, DESCRIPTION, OPTIONS, EXIT STATUS, SEE ALSO), written
// from the command table and CLI11's own lists of each command's options,
// so that they say what the parser accepts. robotsim_gen_docs writes them.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "tools/cli/lib/commands.h"

namespace rs::cli {

/// robotsim(1): the commands, each with its one-line help.
std::string robotsimManPage(const CommandLine& commandLine);

/// robotsim-NAME(1) for the table's row `row`: its help, its footer, every
/// option and argument with its help.
std::string commandManPage(const CommandLine& commandLine, std::size_t row);

/// The page's file name: "robotsim.1", "robotsim-run.1".
std::string manPageFileName(std::string_view command);

/// `text` made safe in a troff text line: backslashes and hyphens escaped,
/// a leading dot or quote guarded.
std::string troffText(std::string_view text);

}  // namespace rs::cli
