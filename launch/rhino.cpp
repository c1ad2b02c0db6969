#include "launch/rhino.h"

#include <fmt/format.h>

#include "diag/read_input.h"
#include "launch/program.h"
#include "runtime/rhino/interrupt.h"
#include "runtime/rhino/rhino_machine.h"
#include "runtime/rhino/serial_log.h"
#include "runtime/rhino/serial_port.h"

namespace rs::launch {

namespace {

using rhino::Dialect;
using rhino::RhinoSettings;

// Everything a serial run owns besides the machine, in the order it must be
// torn down (last member first): the log link, the port, the log, the
// clock, and last the Ctrl-C handler.
struct Connection {
  std::unique_ptr<rhino::InterruptGuard> guard;
  rhino::SteadyClock clock;
  std::unique_ptr<rhino::SerialLog> log;
  std::unique_ptr<rhino::SerialPort> port;
  std::unique_ptr<rhino::LoggedLink> logged;
};

// The bytes a second Ctrl-C writes from the signal handler.
std::string emergencyStop(const RhinoSettings& s, const std::vector<vm::MotorSpec>& motors) {
  std::string bytes;
  for (const std::string& c : rhino::stopCommands(s.dialect, motors)) {
    bytes += c;
    bytes += rhino::lineEndBytes(s.lineEnd);
  }
  return bytes;
}

}  // namespace

bool buildSettings(const std::string& dialectText, const std::string& file, const std::vector<std::string>& sets,
                   RhinoSettings& settings, std::vector<diag::Diagnostic>& diags) {
  settings = rhino::defaultSettings(dialectText == "mark4" ? Dialect::Mark4 : Dialect::Mark3);
  const std::size_t before = diags.size();
  if (!file.empty()) {
    const diag::Result<std::string> text = diag::readInput(file, kMaxInputBytes, "cannot read serial settings");
    if (!text) {
      diags.push_back(text.failure());
    } else {
      diag::Result<RhinoSettings> applied = rhino::applySettingsText(settings, *text, file);
      if (applied) settings = std::move(applied).value();
      const std::vector<diag::Diagnostic>& bad = applied.failures();
      diags.insert(diags.end(), bad.begin(), bad.end());
    }
  }
  for (const std::string& s : sets) {
    diag::Result<RhinoSettings> applied = rhino::applySettingArg(settings, s);
    if (applied) settings = std::move(applied).value();
    else diags.push_back(applied.failure());
  }
  return diags.size() == before;
}

std::unique_ptr<rhino::RhinoMachine> openRhino(const SerialRequest& o, const std::vector<vm::MotorSpec>& motors,
                                               vm::Micros maxTime, std::vector<diag::Diagnostic>& diags) {
  RhinoSettings settings;
  if (!buildSettings(o.dialect, o.settingsFile, o.settings, settings, diags)) return nullptr;
  std::string error;
  // What the system refused (the device, the log file, the controller's
  // answer) has no place in a file: "robotsim: error: ...", the message
  // naming the path.
  const auto failed = [&] {
    diags.push_back({"robotsim", {}, diag::Severity::Error, error});
    return nullptr;
  };
  auto conn = std::make_shared<Connection>();
  if (!o.logFile.empty()) {
    conn->log = rhino::SerialLog::create(o.logFile, error);
    if (!conn->log) return failed();
  }
  conn->port = rhino::SerialPort::open(o.device, settings.line, error);
  if (!conn->port) {
    if (conn->log) conn->log->comment("cannot open: " + error);
    return failed();
  }
  conn->guard = std::make_unique<rhino::InterruptGuard>();
  conn->guard->setEmergencyStop(conn->port->fd(), emergencyStop(settings, motors));
  rhino::Link* link = conn->port.get();
  if (conn->log) {
    conn->logged = std::make_unique<rhino::LoggedLink>(*conn->port, *conn->log, conn->clock);
    link = conn->logged.get();
  }
  auto machine = std::make_unique<rhino::RhinoMachine>(motors, settings, *link, conn->clock, conn->log.get(),
                                                        &conn->guard->flag());
  machine->keepAlive(conn);
  machine->setWaitLimit(maxTime);
  if (vm::Status st = machine->open(); !st) {
    diags.push_back({"robotsim", {}, diag::Severity::Error, st.message, {}, machine->openHint()});
    return nullptr;
  }
  return machine;
}

}  // namespace rs::launch
