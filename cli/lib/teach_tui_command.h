// `robotsim teach PROG.rsp --cell CELL --tui`: the terminal pendant
// (teach/tui/). This file loads what the pendant needs (the program file,
// the workcell, the device if any), builds the teach::Pendant and hands
// the terminal to it; the web pendant (the same command without --tui)
// builds the same pendant the same way.
#pragma once

#include <ostream>

#include "launch/program.h"
#include "launch/rhino.h"

namespace rs::cli {

struct TeachOptions {
  launch::ProgramRequest program;  ///< the program file, --cell, --lib
  launch::SerialRequest serial;    ///< --device, --dialect, ...
  bool tui = false;                ///< --tui: the terminal pendant
};

/// Exit codes: 0 after q, 2 when the program, the cell, the device or the
/// terminal cannot be used (nothing is written then), 128 + the signal's
/// number after SIGINT, SIGTERM, SIGHUP or SIGQUIT.
int teachTuiCommand(const TeachOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
