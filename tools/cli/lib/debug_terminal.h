// robotsim debug at a terminal: the prompt (libedit's readline interface:
// line editing, history) and Ctrl-C. One SIGINT handler is installed for
// the whole session, before the first prompt, and stays: it raises a flag
// and writes a byte to a pipe. The flag is taken by whoever is waiting
// for it, never cleared behind anyone's back: a run in progress pauses at
// its next slice (the session asks takeInterrupt()), and a prompt (our own
// key reader, which polls the terminal and the pipe together) gives up the
// line being typed. So a Ctrl-C is never lost, however it falls against
// the prompt: typed a moment before the prompt appears, it ends that
// prompt at once; typed right after a line was entered, it pauses the
// command the line runs.
//
// What Ctrl-C cannot do is take back keys the terminal has not delivered
// yet: the terminal itself (ISIG without NOFLSH) drops unread input when
// it sends SIGINT, so a Ctrl-C typed before the debugger has read the end
// of a line cancels that line, as in any shell.
#pragma once

#include <string>

namespace rs::cli {

struct TerminalLine {
  enum class Status { Line, Interrupted, End };
  Status status = Status::End;
  std::string text;  ///< the line, when status is Line
};

class DebugTerminal {
 public:
  /// Installs the SIGINT handler (the previous one comes back at the end).
  DebugTerminal();
  ~DebugTerminal();
  DebugTerminal(const DebugTerminal&) = delete;
  DebugTerminal& operator=(const DebugTerminal&) = delete;

  /// Whether Ctrl-C was pressed since it was last taken; takes it.
  bool takeInterrupt();
  /// A line typed after `prompt` (added to the history when not blank);
  /// Interrupted after Ctrl-C, End at the end of input (Ctrl-D).
  TerminalLine readLine(const char* prompt);
};

}  // namespace rs::cli
