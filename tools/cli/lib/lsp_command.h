// `robotsim lsp`: the language server (tools/lsp/) on standard input and output,
// for editors. Its log (framing problems, a client that left) goes to
// standard error.
#pragma once

#include <ostream>

namespace CLI {
class App;
}

namespace rs::cli {

struct LspOptions {
  bool stdio = false;  // --stdio: what clients pass; stdio is the only transport
};

void addLspOptions(CLI::App* cmd, LspOptions& o);
/// Serves until `exit` or the end of input; 0 after shutdown and exit, 1
/// otherwise (as LSP asks).
int lspCommand(const LspOptions& o, std::ostream& err);

}  // namespace rs::cli
