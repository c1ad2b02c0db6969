// The Rhino serial backend on the command line: the --device options of
// run and check, `robotsim ports` and `robotsim emulate`. Everything is in
// runtime/rhino; this file only parses flags, opens, prints.
// docs/serial.md is the user's guide.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "launch/rhino.h"

namespace CLI {
class App;
}

namespace rs::cli {

/// run/check: adds --device, --dialect, --log-serial, --serial-set and
/// --serial-config to `cmd`. Call it after the stimuli options are added:
/// --device then excludes --stimuli and --input (inputs come from the
/// controller), and the other serial options need --device.
void addSerialOptions(CLI::App* cmd, launch::SerialRequest& o);
/// A run of one robot (or teach) drives one controller: true, with the
/// error said on `err`, when several --device or --log-serial were given.
bool refuseSeveralDevices(const launch::SerialRequest& o, std::ostream& err);

struct PortsOptions {
  bool all = false;  // also /dev/ttyS* nodes with no UART behind them
  bool json = false;
  std::string root = "/dev";
};
void addPortsOptions(CLI::App* cmd, PortsOptions& o);
int portsCommand(const PortsOptions& o, std::ostream& out, std::ostream& err);

struct EmulateOptions {
  std::string dialect = "mark3";
  std::string robot = "rhino-scara";
  std::vector<std::string> libDirs;
  double speed = 1.0;      // step rates multiplied by this
  double latency = 0.005;  // seconds
  int switchWidth = 20;
  std::string start;  // "E=120,D=-40"
  std::string fault = "none";
  std::uint64_t faultAfter = 0;
  double slowDelay = 2.0;
  std::string script;
  std::vector<std::string> settings;  // KEY=VALUE, as for run
  std::string settingsFile;
  std::string link;     // also make this symlink to the device
  double duration = 0;  // stop after this many seconds (0: never)
  int controllers = 1;  // each on its own pseudo-terminal (a cell of several robots)
  bool noStdin = false;
  bool quiet = false;
  bool verbose = false;
};
void addEmulateOptions(CLI::App* cmd, EmulateOptions& o);
/// Runs until Ctrl-C, `quit`, --duration or a hang-up fault. Reads console
/// commands from standard input unless noStdin.
int emulateCommand(const EmulateOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
