// A real Rhino controller (or `robotsim emulate`) as the machine of a run:
// the serial options of run and check, the settings they build, and the
// port, log and Ctrl-C handler a serial run owns. Everything that speaks
// the protocol is in runtime/rhino; this file only puts it together.
// docs/serial.md is the user's guide.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/rhino/rhino_machine.h"
#include "runtime/rhino/settings.h"
#include "vm/image.h"
#include "vm/machine.h"

namespace rs::launch {

/// --device, --dialect, --log-serial, --serial-set, --serial-config.
struct SerialRequest {
  std::string device;  ///< empty: simulation; the first of `devices`
  std::string dialect = "mark3";
  std::string logFile;  ///< the first of `logFiles`
  /// Every --device and --log-serial given: a cell run of several robots
  /// takes LABEL=DEVICE and LABEL=FILE, one per robot (cell_controllers.h).
  std::vector<std::string> devices;
  std::vector<std::string> logFiles;
  std::vector<std::string> settings;  ///< KEY=VALUE
  std::string settingsFile;
  bool active() const { return !device.empty(); }
};

/// Defaults for the dialect ("mark3" or "mark4"), then the settings file,
/// then each KEY=VALUE; false, with every problem in `diags`, when any is bad.
bool buildSettings(const std::string& dialect, const std::string& file, const std::vector<std::string>& sets,
                   rhino::RhinoSettings& settings, std::vector<diag::Diagnostic>& diags);

/// Opens the port, installs the Ctrl-C handler (until the machine goes),
/// makes first contact. Null, with the problems in `diags`, when anything
/// fails. `maxTime` bounds WAITFOR. The machine's own type, so that a
/// caller that reads the controller (its log, its sent commands) needs no cast.
std::unique_ptr<rhino::RhinoMachine> openRhino(const SerialRequest& request, const std::vector<vm::MotorSpec>& motors,
                                               vm::Micros maxTime, std::vector<diag::Diagnostic>& diags);

}  // namespace rs::launch
