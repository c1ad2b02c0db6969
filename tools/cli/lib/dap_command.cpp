#include "tools/cli/lib/dap_command.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include "tools/dap/serve.h"
#include "tools/wire/transport.h"

namespace rs::cli {

void addDapOptions(CLI::App* cmd) {
  cmd->footer(
      "Speaks the Debug Adapter Protocol over stdin and stdout (Content-Length framing, as robotsim lsp).\n"
      "launch takes program, and optionally cell, stimuli, inputs (N=ON@T strings), maxSteps, maxTime, maxKnots,\n"
      "lib and stopOnEntry. Line breakpoints with conditions (N = 3, out 2 = 1) and hit counts (N, >= N,\n"
      "== N, % N); exception breakpoints deadlock, runtimeError, limit; stepping in, over, out and back\n"
      "(stepBack, reverseContinue); scopes Variables, Motors (with TCP), Inputs/Outputs, Objects, Clock;\n"
      "evaluate a variable, a motor letter, in N, out N. Editors start it themselves: docs/debugging.md.");
}

int dapCommand(std::ostream& err) {
  wire::FdInput in(STDIN_FILENO);
  wire::FdOutput out(STDOUT_FILENO);
  return dap::serve(in, out, err);
}

}  // namespace rs::cli
