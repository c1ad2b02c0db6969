#include "tools/cli/lib/debug_command.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <optional>
#include <sstream>

#include "base/file_io.h"
#include "base/text.h"
#include "tools/cli/lib/debug_terminal.h"
#include "tools/cli/lib/debug_view.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/open_browser.h"
#include "tools/cli/lib/options.h"
#include "tools/debug/console.h"
#include "tools/debug/debug_session.h"

namespace rs::cli {

namespace {

constexpr const char* kPrompt = "(rsdb) ";

// Lines from a stream, each echoed after the prompt so that a transcript
// reads like the session a person would have typed.
bool batch(std::istream& in, const ConsoleLine& execute, std::ostream& out) {
  std::string line;
  while (std::getline(in, line)) {
    out << kPrompt << base::safeText(line) << '\n';
    if (!execute(line)) return false;
  }
  return true;
}

// The prompt on a terminal. Ctrl-C there gives up the line being typed,
// not the session: a fresh prompt. Ctrl-D (the end of input) leaves.
void interactive(DebugTerminal& terminal, const ConsoleLine& execute, std::ostream& out) {
  for (;;) {
    out.flush();
    const TerminalLine line = terminal.readLine(kPrompt);
    if (line.status != TerminalLine::Status::Line) out << '\n';
    if (line.status == TerminalLine::Status::End) return;
    if (line.status == TerminalLine::Status::Line && !execute(line.text)) return;
  }
}

}  // namespace

void addDebugOptions(CLI::App* cmd, DebugOptions& o) {
  cmd->add_option("file", o.program.file, "Program source or compiled image");
  cmd->add_option("programs", o.programs,
                  "With --cell: LABEL=FILE gives or overrides the program of the cell's robot LABEL; without a "
                  "file, every robot with a program is a thread of the session (docs/debugging.md)");
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
  addRunOptions(cmd, o.run);
  cmd->add_option("-x,--commands", o.commands, "Run the debugger commands in this file first (one a line)");
  CLI::Option* view = cmd->add_flag(
      "--view", o.view,
      "Serve the live workcell page (as robotsim teach does, read-only): it shows the robot, the objects, the "
      "inputs, outputs and clock where the run stopped, after every command; needs a workcell");
  cmd->add_flag("--open", o.open, "With --view: open the page in a browser (xdg-open)")->needs(view);
  cmd->footer(
      "A gdb-style prompt (line editing and history) on the simulated run, standing before the first\n"
      "instruction. Commands: break (b) LINE|LABEL|@N|at TIME|when COND [if COND] [hits N],\n"
      "break sensor NAME [on|off]|feeder NAME|sink NAME (a cell's devices), delete (d),\n"
      "info breakpoints, step (s) [N], next (n), finish (fin), continue (c), until (u) TIME,\n"
      "reverse-step (rs) [N], reverse-next (rn), reverse-continue (rc), goto-time (gt) TIME,\n"
      "print (p) VAR|motors|tcp|io|objects|devices|clock, backtrace (bt), list (l), disasm (da),\n"
      "set input N on|off, watch (w) VAR|output N, help (h), quit (q).\n"
      "With -x FILE, or when standard input is not a terminal, commands are read and echoed one a line\n"
      "(batch mode). Going backwards re-runs from snapshots: docs/debugging.md.\n"
      "robotsim debug --cell CELL [LABEL=FILE ...] debugs every robot of the cell that has a program, each a\n"
      "thread (info threads, thread LABEL, break FILE:LINE; help lists the commands there).\n"
      "--view prints the page's address (127.0.0.1 and a free port, a secret token in the URL); the page\n"
      "follows every stop, forwards and backwards, and refuses to jog or teach (robotsim teach does that).");
}

std::optional<std::string> readCommandFile(const DebugOptions& o, std::ostream& err) {
  if (o.commands.empty()) return std::string();
  base::FileRead read = base::readFile(o.commands, launch::kMaxInputBytes);
  if (read.bytes) return std::move(*read.bytes);
  err << fmt::format("{}: error: cannot read the command file: {}\n", base::safeText(o.commands), read.error);
  return std::nullopt;
}

void driveConsole(const DebugOptions& o, const std::string& commands, const ConsoleLine& execute,
                  DebugTerminal& terminal, std::istream& in, std::ostream& out) {
  bool goOn = true;
  if (!o.commands.empty()) {
    std::istringstream lines(commands);
    goOn = batch(lines, execute, out);
  }
  // The terminal prompt only for the process's own stdin on a terminal.
  if (goOn) {
    if (&in == &std::cin && ::isatty(STDIN_FILENO)) interactive(terminal, execute, out);
    else batch(in, execute, out);
  }
}

int debugCommand(const DebugOptions& o, std::istream& in, std::ostream& out, std::ostream& err) {
  if (const std::optional<int> cell = debugCellIfSeveral(o, in, out, err)) return *cell;
  launch::LoadedProgram program = launch::loadProgram(o.program);
  std::vector<diag::Diagnostic> diags = program.diagnostics;
  const std::optional<runtime::RunSpec> spec = launch::prepareRun(program, o.run, diags);
  if (!spec || !program.ok()) {
    launch::printDiagnostics(err, diags, program);
    return kExitBadInput;
  }
  launch::printDiagnostics(err, program.diagnostics, program);  // warnings
  // Read whole, as every input file is: a FIFO or a device is refused, not waited on.
  const std::optional<std::string> commands = readCommandFile(o, err);
  if (!commands) return kExitBadInput;

  DebugTerminal terminal;  // Ctrl-C pauses a run from here on, also in batch mode
  debug::DebugSession session(*spec);
  session.setInterrupt([&terminal] { return terminal.takeInterrupt(); });
  debug::Console console(session, program.source ? &*program.source : nullptr, out);
  out << fmt::format("robotsim debug: {} ({} instructions); help lists the commands\n",
                     base::safeText(spec->image->sourceName), spec->image->code.size());
  std::shared_ptr<DebugView> view;
  PageLink link;  // --open's way in for the browser; removed when the session ends
  if (o.view) {
    std::string error;
    view = DebugView::start(session, o.program.file, error);
    if (!view) {
      err << "robotsim debug: error: " << error << '\n';
      return kExitBadInput;
    }
    out << "live view: " << view->url() << '\n' << std::flush;
    if (std::string why; o.open && !openBrowser(view->url(), link, why))
      err << "robotsim: note: " << why << "; open the URL yourself\n";
  }
  console.showStop(session.lastStop());
  driveConsole(o, *commands, [&console](std::string_view line) { return console.execute(line); }, terminal, in, out);
  return kExitOk;
}

}  // namespace rs::cli
