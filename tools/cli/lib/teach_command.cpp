#include "tools/cli/lib/teach_command.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <ostream>
#include <thread>

#include "runtime/rhino/interrupt.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/open_browser.h"
#include "tools/cli/lib/options.h"
#include "tools/cli/lib/serial_commands.h"
#include "tools/live/live_server.h"
#include "tools/teach/page.h"
#include "tools/teach/pendant_source.h"

namespace rs::cli {

bool parseListen(const std::string& text, std::string& host, int& port) {
  port = 0;
  std::string portText;
  bool hasPort = false;
  if (!text.empty() && text[0] == '[') {
    const std::size_t close = text.find(']');
    if (close == std::string::npos) return false;
    host = text.substr(1, close - 1);
    if (close + 1 < text.size()) {
      if (text[close + 1] != ':') return false;
      portText = text.substr(close + 2);
      hasPort = true;
    }
  } else {
    const std::size_t colon = text.find(':');
    if (colon != std::string::npos && text.find(':', colon + 1) != std::string::npos) {
      host = text;  // a bare IPv6 address
    } else {
      host = text.substr(0, colon);
      if (colon != std::string::npos) portText = text.substr(colon + 1), hasPort = true;
    }
  }
  if (host.empty()) return false;
  if (hasPort) {
    const auto [end, ec] = std::from_chars(portText.data(), portText.data() + portText.size(), port);
    if (ec != std::errc() || end != portText.data() + portText.size() || port < 0 || port > 65535) return false;
  }
  return true;
}

bool isLoopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.starts_with("127.");
}

void addTeachOptions(CLI::App* cmd, TeachOptions& o) {
  cmd->add_option("file", o.request.program.file, "Program source (.rsp) whose points to teach")->required();
  addCellOptions(cmd, o.request.program);
  addSerialOptions(cmd, o.request.serial);
  CLI::Option* open =
      cmd->add_flag("--open", o.open,
                    "Open the page in a browser (xdg-open, given a private file that leads to the URL: the token never "
                    "appears on a command line)");
  CLI::Option* listen =
      cmd->add_option("--listen", o.listen,
                      "Serve on HOST[:PORT] instead of 127.0.0.1 and a free port (another machine can then reach "
                      "it: a warning is printed)")
          ->option_text("HOST[:PORT]");
  cmd->add_flag("--tui", o.tui,
                "The terminal pendant instead of the page: ncurses in this terminal (80x24 or larger), the same "
                "keys and the same writes")
      ->excludes(open)
      ->excludes(listen);
  cmd->footer(
      "The page shows the workcell, each motor's encoder count with jog buttons and a slider, the gripper, the "
      "tool centre point, the inputs and outputs and the program's points; TEACH names the current pose as a "
      "point. Jogs move a motor (joint mode) or the tool along and about the cell's axes (world) or its own "
      "(tool), through the inverse kinematics; m switches the mode. Every change of the points is written to "
      "the program at once (only its POINTS rows change; the file as it was is kept in PROG.rsp.bak). The URL carries a secret token; Ctrl-C stops the server. "
      "--tui shows the same pendant in the terminal instead, with the same keys (? lists them, q quits). "
      "docs/teach.md has the whole guide.");
}

int teachCommand(const TeachOptions& o, std::ostream& out, std::ostream& err) {
  std::string host = "127.0.0.1";
  int port = 0;
  if (!o.listen.empty() && !parseListen(o.listen, host, port)) {
    err << fmt::format("--listen: error: '{}' is not HOST or HOST:PORT\n", o.listen);
    return kExitBadInput;
  }
  const rhino::InterruptGuard interrupt;  // Ctrl-C raises its flag: the loop below stops the server
  teach::OpenedPendant opened = teach::openPendant(o.request);
  if (!opened.ok()) {
    launch::printDiagnostics(err, opened.diagnostics, opened.loaded);
    return kExitBadInput;
  }
  teach::Pendant& pendant = *opened.pendant;
  teach::PendantSource source(pendant, teach::teachPageHtml(pendant.cell(), o.request.program.file));
  live::LiveServer server(source, live::randomToken());
  std::string error;
  if (!server.start(host, port, error)) {
    err << "robotsim: error: " << error << '\n';
    return kExitBadInput;
  }
  if (!isLoopback(host))
    err << fmt::format(
        "robotsim: warning: listening on {}: anyone who can reach this machine and has the URL can move the "
        "robot and write {}\n",
        host, o.request.program.file);
  out << fmt::format("robotsim teach: {} on {}{}\n", o.request.program.file, pendant.cell().name,
                     o.request.serial.active() ? " with the robot on " + o.request.serial.device : "");
  out << "  " << server.url() << "\n  (Ctrl-C stops)\n" << std::flush;
  PageLink link;  // the browser's way in, never the token on a command line; removed when teach ends
  if (std::string why; o.open && !openBrowser(server.url(), link, why))
    err << "robotsim: note: " << why << "; open the URL yourself\n";
  while (!interrupt.flag().load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server.stop();
  out << fmt::format("robotsim teach: stopped; {} has {} points\n", o.request.program.file,
                     pendant.state().points.size());
  return kExitOk;
}

}  // namespace rs::cli
