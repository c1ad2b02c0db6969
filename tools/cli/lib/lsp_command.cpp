#include "tools/cli/lib/lsp_command.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include "tools/cli/lib/build_info.h"
#include "tools/lsp/server.h"
#include "tools/lsp/transport.h"

namespace rs::cli {

void addLspOptions(CLI::App* cmd, LspOptions& o) {
  cmd->footer(
      "Speaks the Language Server Protocol 3.17 over stdin and stdout (Content-Length framing): diagnostics as\n"
      "you type, hover, completion, signature help, go to definition, references, rename, symbols, folding,\n"
      "formatting, code actions, inlay hints and semantic tokens for programs (.rsp); diagnostics, symbols,\n"
      "hover and go to definition for descriptions (.rsd) and stimuli (.stim). A program is checked against\n"
      "the cell its '; cell: NAME' comment names, else the setting robotsim.cell, else the default robot.\n"
      "Editors start it themselves; docs/lsp.md lists the features and settings.");
  cmd->add_flag("--stdio", o.stdio, "Use stdin and stdout (the default and only transport; accepted for clients)");
}

int lspCommand(const LspOptions&, std::ostream& err) {
  lsp::FdInput in(STDIN_FILENO);
  lsp::FdOutput out(STDOUT_FILENO);
  return lsp::serve(in, out, err, std::string(buildInfo().version));
}

}  // namespace rs::cli
