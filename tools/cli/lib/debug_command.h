// `robotsim debug PROG`: the terminal debugger. A gdb-style prompt with
// line editing and history (libedit), or a batch of commands (-x FILE, or
// standard input when it is not a terminal) for handouts and tests; the
// commands themselves are debug::Console's. With --view, the live
// workcell page follows the session (debug_view.h).
#pragma once

#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "launch/program.h"
#include "launch/run_request.h"

namespace CLI {
class App;
}

namespace rs::cli {

struct DebugOptions {
  launch::ProgramRequest program;
  launch::RunRequest run;
  std::vector<std::string> programs;  // --cell: LABEL=FILE for the cell's robots (debug_cell_command.cpp)
  std::string commands;  // -x FILE
  bool view = false;     // --view: the live workcell page follows the session
  bool open = false;     // --open: and a browser opens it
};

class DebugTerminal;

void addDebugOptions(CLI::App* cmd, DebugOptions& o);
/// One command line for a console; false after quit.
using ConsoleLine = std::function<bool(std::string_view)>;
/// The -x file's text ("" without one), or nullopt after saying why it cannot be read.
std::optional<std::string> readCommandFile(const DebugOptions& o, std::ostream& err);
/// The -x commands, then the prompt (a terminal) or standard input's lines (batch), until quit.
void driveConsole(const DebugOptions& o, const std::string& commands, const ConsoleLine& execute,
                  DebugTerminal& terminal, std::istream& in, std::ostream& out);
/// `debug --cell CELL [LABEL=FILE ...]` when several robots have programs
/// (debug_cell_command.cpp): its exit code; nullopt for a debug of one.
std::optional<int> debugCellIfSeveral(const DebugOptions& o, std::istream& in, std::ostream& out, std::ostream& err);
/// 0 after quit or the end of the commands; 2 when the program, its cell,
/// stimuli or limits, or the command file cannot be read.
int debugCommand(const DebugOptions& o, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
