// `robotsim teach PROG --cell CELL --tui`: the terminal pendant on the
// controlling terminal, with ncurses. It draws the TuiSession's screen and
// turns ncurses key codes into the shared key map's names.
//
// The terminal is put back as it was on every way out: `q`; SIGINT
// (Ctrl-C), SIGTERM, SIGHUP and SIGQUIT, which only set a flag the loop
// reads within 100 ms, then leave through endwin() like `q` (with
// --device, Ctrl-C also goes to the serial layer's handler, so a move
// under way stops every motor, and a second Ctrl-C writes stop to the port
// and exits after putting the terminal back as a crash does); an exception
// (endwin() before it goes on); and a crash (SIGSEGV, SIGBUS, SIGFPE,
// SIGILL, SIGABRT), whose handler can call nothing but async-signal-safe
// functions: it puts back the terminal modes saved before ncurses started
// (tcsetattr) and writes the terminal's own "leave the full-screen mode"
// and "show the cursor" strings, looked up in terminfo at start, then
// dies of the signal as it would have.
#pragma once

#include <string>

#include "tools/teach/pendant.h"

namespace rs::teach::tui {

struct TuiEnd {
  std::string error;  ///< why the pendant could not start ("" when it ran)
  int signal = 0;     ///< the signal that ended it (0: the user quit with q)
};

/// Runs until `q` or a signal; stdin and stdout must be a terminal.
TuiEnd runTerminalPendant(Pendant& pendant);

}  // namespace rs::teach::tui
