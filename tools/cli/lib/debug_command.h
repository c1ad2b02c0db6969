// `robotsim debug PROG`: the terminal debugger. A gdb-style prompt with
// line editing and history (libedit), or a batch of commands (-x FILE, or
// standard input when it is not a terminal) for handouts and tests; the
// commands themselves are debug::Console's. With --view, the live
// workcell page follows the session (debug_view.h).
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "launch/program.h"
#include "launch/run_request.h"

namespace CLI {
class App;
}

namespace rs::cli {

struct DebugOptions {
  launch::ProgramRequest program;
  launch::RunRequest run;
  std::string commands;  // -x FILE
  bool view = false;     // --view: the live workcell page follows the session
  bool open = false;     // --open: and a browser opens it
};

void addDebugOptions(CLI::App* cmd, DebugOptions& o);
/// 0 after quit or the end of the commands; 2 when the program, its cell,
/// stimuli or limits, or the command file cannot be read.
int debugCommand(const DebugOptions& o, std::istream& in, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
