// `robotsim debug --cell CELL [LABEL=FILE ...]`: the programs chosen as
// `run --cell` chooses them (launch/cell_programs.h), one session on the
// whole cell (debug::CellSession), every robot a thread of the console.
// A cell where one robot has a program is debugged as a program alone.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "base/text.h"
#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "tools/cli/lib/debug_command.h"
#include "tools/cli/lib/debug_terminal.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/debug/cell_console.h"
#include "tools/debug/cell_session.h"

namespace rs::cli {

std::optional<int> debugCellIfSeveral(const DebugOptions& o, std::istream& in, std::ostream& out, std::ostream& err) {
  launch::ProgramRequest request = o.program;
  std::vector<std::string> assignments = o.programs;
  std::error_code ec;
  if (launch::isProgramAssignment(request.file) && !std::filesystem::exists(request.file, ec))
    assignments.insert(assignments.begin(), request.file), request.file.clear();
  // A program of its own (PROG --cell CELL) drives the one robot, as before.
  if (!request.file.empty() && assignments.empty()) return std::nullopt;
  if (request.cell.empty()) {
    err << "robotsim: error: which program? give a program file, or --cell CELL to debug every PROGRAM its ROBOT "
           "lines name (LABEL=FILE gives or overrides one)\n";
    return kExitBadInput;
  }
  launch::CellPrograms programs;
  const auto sourceOf = [&programs](const std::string& file) { return programs.sourceOf(file); };
  if (!launch::assignCellPrograms(request, assignments, programs)) {
    std::vector<diag::Diagnostic> all = programs.allDiagnostics();
    launch::printDiagnostics(err, all, sourceOf, request.maxErrors, {});
    return kExitBadInput;
  }
  if (programs.programs.empty()) {
    err << fmt::format("{}: error: no robot of the cell has a program\n  hint: give one a PROGRAM on its ROBOT line, "
                       "or LABEL=FILE on the command line\n",
                       base::safeText(request.cell));
    return kExitBadInput;
  }
  if (programs.programs.size() == 1) {
    DebugOptions one = o;
    one.program.file = programs.files[0], one.program.robot = programs.labels[0], one.programs.clear();
    return debugCommand(one, in, out, err);
  }
  launch::compileAssignedPrograms(request, programs);
  // Each program's load read the cell again: its warnings are said once.
  std::vector<diag::Diagnostic> diags = programs.diagnosticsOnce();
  const std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, o.run, diags);
  launch::printDiagnostics(err, diags, sourceOf, request.maxErrors, {});
  if (!spec) return kExitBadInput;
  if (o.view) {
    err << "robotsim debug: error: --view shows one robot: a cell of several is not shown yet\n  hint: debug one "
           "robot's program with PROG --cell CELL --robot LABEL --view\n";
    return kExitBadInput;
  }
  const std::optional<std::string> commands = readCommandFile(o, err);
  if (!commands) return kExitBadInput;

  DebugTerminal terminal;
  debug::CellSession session(*spec);
  session.setInterrupt([&terminal] { return terminal.takeInterrupt(); });  // Ctrl-C pauses a long run
  std::vector<const diag::SourceFile*> sources;
  for (const launch::LoadedProgram& l : programs.loaded) sources.push_back(l.source ? &*l.source : nullptr);
  debug::CellConsole console(session, sources, out);
  out << fmt::format("robotsim debug: cell {}, {} robots with programs; help lists the commands\n",
                     base::safeText(spec->cell->name), session.size());
  for (std::size_t p = 0; p < session.size(); ++p)
    out << fmt::format("  thread {}: {} runs {} ({} instructions)\n", p + 1, base::safeText(session.label(p)),
                       base::safeText(programs.files[p]), session.cell().robot(p).spec().image->code.size());
  console.showStop(session.lastStop());
  driveConsole(o, *commands, [&console](std::string_view line) { return console.execute(line); }, terminal, in, out);
  return kExitOk;
}

}  // namespace rs::cli
