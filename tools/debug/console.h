// The terminal debugger's commands, text in and text out: one line of a
// gdb-style command (`break 12 if N = 3`, `reverse-step`, `print motors`)
// is carried out on a DebugSession and answered on a stream. The prompt, line
// editing and history are the front end's (tools/cli/); a test or a handout
// drives this directly with the same lines. A bad command gets one clear
// message and changes nothing: the session goes on.
#pragma once

#include <ostream>
#include <string>
#include <string_view>

#include "diag/source_file.h"
#include "tools/debug/command_line.h"
#include "tools/debug/debug_session.h"

namespace rs::debug {

class Console {
 public:
  /// `source` is the program's text for `list` and the line shown at each
  /// stop (may be null: an image without its source).
  Console(DebugSession& session, const diag::SourceFile* source, std::ostream& out);

  /// Carries out one command line; false after `quit`.
  bool execute(std::string_view line);
  /// Where the run stands: the stop's reason, place, clock and source line.
  void showStop(const Stop& stop);
  /// The command names and short forms (for completion).
  static const std::vector<std::string>& commandNames();

 private:
  static const std::vector<Command>& commands();
  void breakCommand(std::string_view args);
  void deleteCommand(std::string_view args);
  void infoCommand(std::string_view args);
  void printCommand(std::string_view args);
  void watchCommand(std::string_view args);
  void setCommand(std::string_view args);
  void setVariable(std::string_view name, std::string_view value);
  void listCommand(std::string_view args);
  void disasmCommand(std::string_view args);
  void backtrace();
  void moved(const Stop& stop) { showStop(stop); }
  void error(std::string_view message);
  std::string sourceLine(std::uint32_t line) const;
  std::string frameText(std::uint32_t line, std::uint32_t instruction) const;

  DebugSession& session_;
  const diag::SourceFile* source_;
  std::ostream& out_;
};

}  // namespace rs::debug
