// The terminal debugger's commands on a cell of several robots (a
// CellSession), text in and text out as Console is for one: every robot is
// a thread (`info threads`, `thread LABEL`), breakpoints name their file
// (`break right.rsp:7`, or a line of the current robot's), and the commands
// that look (print, backtrace, list) or step are about the current robot.
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "diag/source_file.h"
#include "tools/debug/cell_session.h"
#include "tools/debug/command_line.h"

namespace rs::debug {

class CellConsole {
 public:
  /// `sources`: each program's text (by program index; null: none).
  CellConsole(CellSession& session, std::vector<const diag::SourceFile*> sources, std::ostream& out);

  /// Carries out one command line; false after `quit`.
  bool execute(std::string_view line);
  /// Where the cell stands: the stop's reason, the current robot's place, clock and source line.
  void showStop(const CellStop& stop);
  /// The command names (for completion and help).
  static const std::vector<std::string>& commandNames();

 private:
  static const std::vector<Command>& commands();
  void breakCommand(std::string_view args);
  void deleteCommand(std::string_view args);
  void infoCommand(std::string_view args);
  void threadCommand(std::string_view args);
  void printCommand(std::string_view args);
  void watchCommand(std::string_view args);
  void setCommand(std::string_view args);
  diag::Result<int> lineBreakpoint(std::string_view args, std::string& note);
  void listCommand(std::string_view args);
  void backtrace();
  void error(std::string_view message);
  std::string sourceLine(std::size_t robot, std::uint32_t line) const;
  /// "line 8 @3, step 2": where robot `robot` stands.
  std::string place(std::size_t robot) const;

  CellSession& session_;
  std::vector<const diag::SourceFile*> sources_;
  std::ostream& out_;
};

}  // namespace rs::debug
