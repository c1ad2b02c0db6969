// `robotsim dap`: the debug adapter (tools/dap/) on standard input and output,
// for VS Code and other DAP clients. Its log goes to standard error.
#pragma once

#include <ostream>

namespace CLI {
class App;
}

namespace rs::cli {

void addDapOptions(CLI::App* cmd);
/// Serves until disconnect or the end of input: 0 after disconnect, 1 when
/// the client left without one.
int dapCommand(std::ostream& err);

}  // namespace rs::cli
