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

/// Whether `table` is the main binary's (it leaves rows to helpers), not a
/// helper's, which answers the helper handshake (helper_handshake.h).
bool leavesRowsToHelpers(std::span<const Command> table);

/// Where the helper of `command` may be, first found wins: the installed
/// layout (`BINDIR/../libexec/robotsim/robotsim-NAME`, the relative path
/// taken from GNUInstallDirs at configure time), only when the executable
/// stands in a folder named as BINDIR is (`bin`); then the build tree's
/// (`BUILD/libexec/robotsim/robotsim-NAME` beside `BUILD/robotsim`).
std::vector<std::filesystem::path> helperCandidates(const std::filesystem::path& executable, std::string_view command);

/// Replaces this process with the helper of `command`, argv[1..] unchanged,
/// so its output, exit code and signals are the command's own. The first
/// candidate that exists must be a regular file, not the running
/// executable itself (the same file: a link back to robotsim would exec
/// for ever), and answer the helper handshake as this build's helper;
/// the file checked is the file run (fexecve). Returns only when it
/// cannot: kExitBadInput, after saying on `err` which files were looked
/// for or why the one found was refused, and how to get the right ones.
int execHelper(std::string_view command, int argc, const char* const* argv, std::ostream& err);

}  // namespace rs::cli
