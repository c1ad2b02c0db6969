#include "tools/cli/lib/teach_tui_command.h"

#include "tools/cli/lib/exit_codes.h"
#include "tools/teach/open_pendant.h"
#include "tools/teach/tui/tui_curses.h"

namespace rs::cli {

int teachTuiCommand(const TeachOptions& o, std::ostream&, std::ostream& err) {
  teach::OpenedPendant opened = teach::openPendant(o.request);
  if (!opened.ok()) {
    launch::printDiagnostics(err, opened.diagnostics, opened.loaded);
    return kExitBadInput;
  }
  const teach::tui::TuiEnd end = teach::tui::runTerminalPendant(*opened.pendant);
  if (!end.error.empty()) {
    err << "robotsim: error: " << end.error << '\n';
    return kExitBadInput;
  }
  return end.signal == 0 ? kExitOk : 128 + end.signal;
}

}  // namespace rs::cli
