// `robotsim teach PROG.rsp --cell CELL --tui`: the terminal pendant
// (tools/teach/tui/) instead of the live page. The pendant is opened as the page
// opens it (teach::openPendant: the program file, the cell or the
// program's "; cell:" line, the device); then the terminal is handed to it.
#pragma once

#include <ostream>

#include "tools/cli/lib/teach_command.h"

namespace rs::cli {

/// Exit codes: 0 after q, 2 when the program, the cell, the device or the
/// terminal cannot be used (nothing is written then), 128 + the signal's
/// number after SIGINT, SIGTERM, SIGHUP or SIGQUIT.
int teachTuiCommand(const TeachOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
