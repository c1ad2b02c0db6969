// The helper executables: the commands that need the renderer (cairo and
// its X11 and font libraries), the HTTP server (cpp-httplib, OpenSSL,
// brotli) or a terminal library (ncurses, libedit) are run by
// `robotsim-NAME`, installed beside the command in the libexec convention
// (as git's are), so that every other command starts without loading them
// (docs/performance.md, "Start-up: loading only what a command uses").
#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>
#include <vector>

#include "tools/cli/lib/commands.h"

namespace rs::cli {

/// The row that argv[1] names when this binary's table leaves it to a
/// helper (the main binary's table; never in the helpers' own or in tests'),
/// or nullptr.
const Command* commandLeftToHelper(std::span<const Command> table, int argc, const char* const* argv);

/// Where the helper of `command` may be, first found wins: the installed
/// layout (`BINDIR/../libexec/robotsim/robotsim-NAME`, the relative path
/// taken from GNUInstallDirs at configure time), then the build tree's
/// (`BUILD/libexec/robotsim/robotsim-NAME` beside `BUILD/robotsim`).
std::vector<std::filesystem::path> helperCandidates(const std::filesystem::path& executable, std::string_view command);

/// Replaces this process with the helper of `command`, argv[1..] unchanged,
/// so its output, exit code and signals are the command's own. Returns
/// only when it cannot: kExitBadInput, after saying on `err` which files
/// were looked for and how to get them.
int execHelper(std::string_view command, int argc, const char* const* argv, std::ostream& err);

}  // namespace rs::cli
