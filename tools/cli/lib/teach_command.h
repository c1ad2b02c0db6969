// `robotsim teach PROG.rsp --cell CELL [--device DEV] [--open] [--listen ADDR]`:
// the teach pendant's live page (tools/teach/), served until Ctrl-C.
#pragma once

#include <iosfwd>
#include <string>

#include "tools/teach/open_pendant.h"

namespace CLI {
class App;
}

namespace rs::cli {

struct TeachOptions {
  teach::TeachRequest request;
  bool open = false;   ///< --open: start a browser on the URL
  std::string listen;  ///< --listen HOST[:PORT]: other than 127.0.0.1 and a free port
  bool tui = false;    ///< --tui: the terminal pendant instead (teach_tui_command.h)
};

void addTeachOptions(CLI::App* cmd, TeachOptions& o);
int teachCommand(const TeachOptions& o, std::ostream& out, std::ostream& err);

/// --listen's HOST[:PORT] ([V6]:PORT for IPv6); false when malformed.
bool parseListen(const std::string& text, std::string& host, int& port);
/// 127.0.0.0/8, ::1 or localhost.
bool isLoopback(const std::string& host);

}  // namespace rs::cli
