#include "tools/cli/lib/serial_commands.h"

#include <fmt/format.h>
#include <poll.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "base/file_io.h"
#include "diag/read_input.h"
#include "base/text.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/number_args.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "launch/rhino.h"
#include "runtime/rhino/emulator.h"
#include "runtime/rhino/interrupt.h"
#include "runtime/rhino/rhino_machine.h"
#include "runtime/rhino/serial_port.h"
#include "compiler/stimuli/stimuli_text.h"
#include "stdlib/default_robot.h"
#include "vm/io_lines.h"

namespace rs::cli {
namespace {

using rhino::Dialect;
using rhino::RhinoSettings;

// A whole number in lo..hi: an optional '+' (or a '-' for a signed type),
// digits, and nothing else ("5x", "1e3", "" and "-1" for a count are not).
template <typename T>
std::optional<T> parseWhole(std::string_view token, T lo, T hi) {
  if (token.starts_with('+')) {
    token.remove_prefix(1);
    if (token.starts_with('-')) return std::nullopt;
  }
  T v{};
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc{} || end != token.data() + token.size() || v < lo || v > hi) return std::nullopt;
  return v;
}

std::string helpSettingsList() {
  std::string keys;
  for (const auto& [key, value] : rhino::listSettings(rhino::defaultSettings(Dialect::Mark3))) {
    if (key.rfind("switch.", 0) == 0 && key != "switch.A") continue;
    if (key.rfind("input.", 0) == 0 && key != "input.1") continue;
    if (key.rfind("output.", 0) == 0 && key != "output.1.on" && key != "output.1.off") continue;
    keys += (keys.empty() ? "" : ", ") + key;
  }
  return keys;
}

// --serial-set KEY=VALUE is checked while the command line is parsed.
CLI::Validator settingValidator() {
  return CLI::Validator(
      [](std::string& arg) {
        const diag::Result<RhinoSettings> applied = rhino::applySettingArg(rhino::defaultSettings(Dialect::Mark3), arg);
        return applied ? std::string() : applied.failure().message;
      },
      "KEY=VALUE");
}

// Repeatable for a cell of several robots (LABEL=VALUE each): `first`
// keeps the first value, which is all a run of one robot takes.
CLI::Option* addRepeatable(CLI::App* cmd, const std::string& name, std::vector<std::string>& all, std::string& first,
                           const std::string& type, const std::string& help) {
  return cmd
      ->add_option_function<std::vector<std::string>>(
          name,
          [&all, &first](const std::vector<std::string>& v) {
            all = v;
            first = v.front();
          },
          help)
      ->type_name(type)
      ->allow_extra_args(false);
}

}  // namespace

void addSerialOptions(CLI::App* cmd, launch::SerialRequest& o) {
  CLI::Option* device =
      addRepeatable(cmd, "--device", o.devices, o.device, "DEVICE",
                    "Run on a Rhino controller on this serial device, in lock-step (robotsim ports lists them); with "
                    "--cell of several robots LABEL=DEVICE, repeatable, one controller a robot");
  cmd->add_option("--dialect", o.dialect, "Controller protocol: mark3 (default) or mark4")
      ->check(CLI::IsMember({"mark3", "mark4"}))
      ->needs(device);
  addRepeatable(cmd, "--log-serial", o.logFiles, o.logFile, "FILE",
                "Write every serial byte each way, with timestamps, to FILE (a cell of several robots: LABEL=FILE, "
                "repeatable)")
      ->needs(device);
  cmd->add_option("--serial-set", o.settings,
                  "Override a serial setting KEY=VALUE (repeatable; keys: " + helpSettingsList() + ", ...)")
      ->allow_extra_args(false)
      ->check(settingValidator())
      ->needs(device);
  cmd->add_option("--serial-config", o.settingsFile, "Serial settings file: one KEY = VALUE per line")->needs(device);
  for (const char* name : {"--stimuli", "--input"})
    if (CLI::Option* stimuli = cmd->get_option_no_throw(name)) device->excludes(stimuli);
}

bool refuseSeveralDevices(const launch::SerialRequest& o, std::ostream& err) {
  if (o.devices.size() <= 1 && o.logFiles.size() <= 1) return false;
  err << "--device: error: a run of one robot drives one controller\n  hint: several --device LABEL=DEVICE are for "
         "run --cell CELL with several robots running programs\n";
  return true;
}

// --- robotsim ports --------------------------------------------------------------

void addPortsOptions(CLI::App* cmd, PortsOptions& o) {
  cmd->add_flag("--all", o.all, "Also list /dev/ttyS* nodes with no UART behind them");
  cmd->add_flag("--json", o.json, "Print one JSON object");
  cmd->add_option("--dev", o.root, "Look in this directory instead of /dev");
}

int portsCommand(const PortsOptions& o, std::ostream& out, std::ostream&) {
  std::vector<rhino::PortInfo> ports = rhino::listPorts(o.root);
  std::size_t hidden = 0;
  if (!o.all) {
    const auto before = ports.size();
    std::erase_if(ports, [](const rhino::PortInfo& p) { return !p.likely; });
    hidden = before - ports.size();
  }
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : ports) list.push_back({{"path", p.path}, {"note", p.note}, {"likely", p.likely}});
    const nlohmann::json doc{{"ports", list}, {"hidden", hidden}};
    out << doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return kExitOk;
  }
  if (ports.empty()) {
    out << fmt::format(
        "No serial devices found (looked for {0}/serial/by-id/*, {0}/ttyUSB*, {0}/ttyACM*, {0}/ttyS*{1}).\n"
        "Plug in the controller's USB-serial adapter, or try the serial path without a robot:\n"
        "  robotsim emulate      (prints a device to pass to robotsim run --device)\n",
        o.root, hidden ? fmt::format("; {} ttyS nodes without a UART hidden, --all shows them", hidden) : "");
    return kExitOk;
  }
  // Device names come from the file system (by-id names from the USB
  // device's own strings): printed escaped.
  std::size_t width = 0;
  for (const auto& p : ports) width = std::max(width, base::safeText(p.path).size());
  out << "Serial devices (use one with robotsim run --device):\n";
  for (const auto& p : ports)
    out << fmt::format("  {:<{}}  {}\n", base::safeText(p.path), width, base::safeText(p.note));
  if (hidden) out << fmt::format("({} /dev/ttyS* nodes without a UART not shown; --all lists them)\n", hidden);
  return kExitOk;
}

// --- robotsim emulate --------------------------------------------------------------

void addEmulateOptions(CLI::App* cmd, EmulateOptions& o) {
  cmd->footer(fmt::format(
      "Console commands (standard input or --script, one per line):\n"
      "  in N on|off              set input N (1..{})\n"
      "  switch L open|closed|auto  force motor L's home switch, or let position decide\n"
      "  fault KIND [after N]     start a fault: silence, garbage, slow, hangup; 'fault off' ends it\n"
      "  status                   print the whole state\n"
      "  wait SECONDS             pause the script\n"
      "  quit                     stop the emulator\n"
      "With --controllers N, 'K: COMMAND' is for controller K (1..N); without it, for controller 1.\n"
      "See docs/serial.md, \"The emulator\".",
      vm::kIoCount));
  cmd->add_option("--dialect", o.dialect, "Controller to play: mark3 (default) or mark4")
      ->check(CLI::IsMember({"mark3", "mark4"}));
  cmd->add_option("--robot", o.robot, "Robot whose motors to emulate: library name or .rsd file (default rhino-scara)");
  cmd->add_option("--lib", o.libDirs, "Also look up robot names in this directory (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--speed", o.speed, "Multiply every motor's step rate (default 1: the robot's speeds)")
      ->transform(numberArg(rules::kSpeedFactor));
  cmd->add_option("--latency", o.latency, "Seconds before each answer (default 0.005)")->transform(numberArg(rules::kLatency));
  cmd->add_option("--switch-width", o.switchWidth, "A home switch is closed within this many steps of 0 (default 20)")
      ->transform(numberArg(rules::kSwitchWidth));
  cmd->add_option("--start", o.start, "Where motors start, e.g. E=120,D=-40 (default all 0)");
  cmd->add_option("--fault", o.fault, "Inject a fault: silence, garbage, slow or hangup")
      ->check(CLI::IsMember({"none", "silence", "garbage", "slow", "hangup"}));
  cmd->add_option("--fault-after", o.faultAfter, "Serve this many commands normally first (default 0)")
      ->transform(numberArg(rules::kCommandCount));
  cmd->add_option("--slow-delay", o.slowDelay, "With --fault slow: seconds each answer is late (default 2)")
      ->transform(numberArg(rules::kSlowDelay));
  cmd->add_option("--script", o.script, "Run console commands from FILE (with 'wait SECONDS' between them)");
  cmd->add_option("--serial-set", o.settings, "Play a different assumption KEY=VALUE, as for run (repeatable)")
      ->allow_extra_args(false)
      ->check(settingValidator());
  cmd->add_option("--serial-config", o.settingsFile, "Serial settings file, as for run");
  cmd->add_option("--link", o.link,
                  "Also make this symbolic link to the device (e.g. /tmp/rhino; with --controllers N: LINK1..LINKN)");
  cmd->add_option("--controllers", o.controllers,
                  "Play N controllers at once, each on its own pseudo-terminal (one a robot of a cell; default 1)")
      ->transform(numberArg(rules::kControllers));
  cmd->add_option("--duration", o.duration, "Stop after this many seconds (default: run until Ctrl-C or quit)")
      ->transform(numberArg(rules::kDuration));
  cmd->add_flag("--no-stdin", o.noStdin, "Do not read console commands from standard input");
  cmd->add_flag("-q,--quiet", o.quiet, "No status line and no event lines");
  cmd->add_flag("-v,--verbose", o.verbose, "Print every command the host sends");
}

namespace {

// `fault KIND after N` counts from now: far below where the count wraps.
constexpr std::uint64_t kMaxFaultAfter = 1'000'000'000'000;

struct EmulatorSession {
  std::vector<std::unique_ptr<rhino::PtyEmulator>>& emus;
  std::ostream& out;
  bool quit = false;
  vm::Micros waitUntil = 0;  // script: next line not before
};

struct ControllerConsole {
  rhino::PtyEmulator& emu;
  std::ostream& out;
  bool& quit;
  vm::Micros& waitUntil;
};

std::string consoleCommand(ControllerConsole s, const std::string& line);

// One console line, "K: COMMAND" for controller K: "" when fine, else what is wrong.
std::string consoleCommand(EmulatorSession& s, const std::string& line) {
  std::size_t k = 1;
  std::string rest = line;
  const std::size_t first = line.find_first_not_of(' ');
  const std::size_t colon = line.find(':');
  if (first != std::string::npos && colon != std::string::npos && colon > first &&
      line.find_first_not_of("0123456789", first) == colon) {
    const auto n = parseWhole<std::size_t>(std::string_view(line).substr(first, colon - first), 1, s.emus.size());
    if (!n) return fmt::format("'{}': K: COMMAND names a controller 1..{}", line, s.emus.size());
    k = *n, rest = line.substr(colon + 1);
  }
  return consoleCommand(ControllerConsole{*s.emus[k - 1], s.out, s.quit, s.waitUntil}, rest);
}

std::string consoleCommand(ControllerConsole s, const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string word; in >> word;) {
    if (word[0] == '#') break;
    w.push_back(word);
  }
  if (w.empty()) return {};
  const std::string& verb = w[0];
  if (verb == "quit" || verb == "exit") {
    s.quit = true;
  } else if (verb == "help") {
    s.out << "in N on|off | switch L open|closed|auto | fault KIND [after N] | fault off | status | wait S | quit\n";
  } else if (verb == "in" && w.size() == 3 && (w[2] == "on" || w[2] == "off")) {
    const auto n = parseWhole<int>(w[1], 1, vm::kIoCount);
    if (!n) return fmt::format("in N on|off: N is an input 1..{}, not {}", vm::kIoCount, stimuli::text::quoted(w[1]));
    s.emu.setInput(*n, w[2] == "on");
    s.out << fmt::format("input {} {}\n", *n, w[2] == "on" ? "ON" : "OFF");
  } else if (verb == "switch" && w.size() == 3 && w[1].size() == 1 && std::toupper(w[1][0]) >= 'A' &&
             std::toupper(w[1][0]) <= 'H' && (w[2] == "open" || w[2] == "closed" || w[2] == "auto")) {
    const char letter = static_cast<char>(std::toupper(w[1][0]));
    s.emu.forceSwitch(letter, w[2] == "auto" ? std::nullopt : std::optional<bool>(w[2] == "closed"));
    s.out << fmt::format("switch {} {}\n", letter, w[2]);
  } else if (verb == "fault" && (w.size() == 2 || (w.size() == 4 && w[2] == "after"))) {
    rhino::FaultPlan plan;
    if (!rhino::parseFault(w[1], plan.kind)) return "fault takes silence, garbage, slow, hangup or off";
    if (w.size() == 4) {
      const auto after = parseWhole<std::uint64_t>(w[3], 0, kMaxFaultAfter);
      if (!after)
        return fmt::format("fault KIND after N: N is a whole number of commands 0..{}, not {}", kMaxFaultAfter,
                           stimuli::text::quoted(w[3]));
      plan.after = *after;
    }
    s.emu.setFault(plan);
  } else if (verb == "status") {
    const rhino::EmulatorSnapshot snap = s.emu.snapshot();
    s.out << s.emu.statusLine() << '\n';
    for (const rhino::EmulatedMotor& m : snap.motors)
      s.out << fmt::format("  motor {}: position {}, step rate {}/s{}\n", m.letter, m.position, std::lround(m.rate),
                           m.used ? "" : " (not in the robot)");
  } else if (verb == "wait" && w.size() == 2) {
    const diag::Result<vm::Micros> sec = stimuli::text::parseSeconds(w[1]);
    if (!sec) return "wait: " + sec.failure().message;
    s.waitUntil = s.emu.now() + *sec;
  } else {
    return fmt::format("unknown command '{}' (type help)", line);
  }
  return {};
}

// --start L=N,...: where each of the motors A..H starts (`start`, the others as they were).
diag::Result<std::array<std::int32_t, 8>> parseStart(const std::string& text, std::array<std::int32_t, 8> start) {
  const auto refused = [](std::string message) {
    return diag::Diagnostic{"robotsim", {}, diag::Severity::Error, std::move(message)};
  };
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const std::size_t eq = item.find('=');
    const char letter = item.empty() ? 0 : static_cast<char>(std::toupper(item[0]));
    if (eq != 1 || letter < 'A' || letter > 'H')
      return refused(fmt::format("--start: '{}' is not L=N (motor letter A..H, encoder count)", item));
    const auto v = parseWhole<std::int32_t>(std::string_view(item).substr(2), -1'000'000, 1'000'000);
    if (!v) return refused(fmt::format("--start: '{}' is not L=N with N in -1000000..1000000", item));
    start[static_cast<std::size_t>(letter - 'A')] = *v;
  }
  return start;
}

std::string motorList(const std::vector<vm::MotorSpec>& motors) {
  std::string s;
  for (const vm::MotorSpec& m : motors) s += fmt::format("{}{} {}/s", s.empty() ? "" : ", ", m.letter, m.speed);
  return s;
}

}  // namespace

int emulateCommand(const EmulateOptions& o, std::ostream& out, std::ostream& err) {
  rhino::EmulatorConfig config;
  std::vector<diag::Diagnostic> problems;
  if (!launch::buildSettings(o.dialect, o.settingsFile, o.settings, config.settings, problems)) {
    for (const diag::Diagnostic& d : problems) err << diag::render(d, nullptr);
    return kExitBadInput;
  }
  std::string error;
  if (o.robot == stdlib::rhinoScaraName()) {
    config.motors = stdlib::rhinoScaraMotors();
  } else {
    compiler::Library library(compiler::librarySearchPath(o.libDirs));
    std::optional<workcell::Robot> robot = library.robot(o.robot);
    for (const diag::Diagnostic& d : library.diagnostics()) err << diag::render(d, library.source(d.file));
    if (!robot) return kExitBadInput;
    config.motors = compiler::motorTable(*robot);
  }
  if (std::string e = rhino::unsupportedMotor(config.settings.dialect, config.motors); !e.empty()) {
    err << "robotsim: error: " << e << '\n';
    return kExitBadInput;
  }
  const diag::Result<std::array<std::int32_t, 8>> start = parseStart(o.start, config.start);
  if (!start) {
    err << "robotsim: error: " << start.failure().message << '\n';
    return kExitBadInput;
  }
  config.start = *start;
  config.rateScale = o.speed;
  config.latency = static_cast<vm::Micros>(std::llround(o.latency * 1e6));
  config.switchWidth = o.switchWidth;
  rhino::parseFault(o.fault, config.fault.kind);
  config.fault.after = o.faultAfter;
  config.fault.slowDelay = static_cast<vm::Micros>(std::llround(o.slowDelay * 1e6));
  std::vector<std::string> script;
  if (!o.script.empty()) {
    const diag::Result<std::string> text = diag::readInput(o.script, launch::kMaxInputBytes, "cannot read the script");
    if (!text) {
      err << fmt::format("{}: error: {}\n", o.script, text.failure().message);
      return kExitBadInput;
    }
    std::istringstream lines(*text);
    for (std::string line; std::getline(lines, line);) script.push_back(line);
  }

  std::vector<std::unique_ptr<rhino::PtyEmulator>> emus;
  for (int k = 0; k < o.controllers; ++k) {
    emus.push_back(rhino::PtyEmulator::open(config, error));
    if (!emus.back()) {
      err << "robotsim: error: " << error << '\n';
      return kExitRunFailed;
    }
  }
  const bool several = emus.size() > 1;
  // With several controllers, each has a label (its number) and a link of its own.
  const auto linkOf = [&](std::size_t k) { return o.link.empty() || !several ? o.link : o.link + std::to_string(k + 1); };
  const auto named = [&](std::size_t k) { return several ? fmt::format("controller {}: ", k + 1) : std::string(); };
  for (std::size_t k = 0; k < emus.size() && !o.link.empty(); ++k) {
    std::error_code ec;
    const std::string link = linkOf(k);
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(link, ec)))
      std::filesystem::remove(link, ec);  // a stale link from an earlier run; never a file
    std::filesystem::create_symlink(emus[k]->path(), link, ec);
    if (ec) err << fmt::format("robotsim: warning: cannot make the link {}: {}\n", link, ec.message());
  }
  const std::string dialect(rhino::dialectName(config.settings.dialect));
  const auto deviceOf = [&](std::size_t k) { return o.link.empty() ? emus[k]->path() : linkOf(k); };
  if (several) {
    out << fmt::format("{} Rhino {} controller emulators:\n", emus.size(), rhino::dialectTitle(config.settings.dialect));
    for (std::size_t k = 0; k < emus.size(); ++k)
      out << fmt::format("controller {} on {}{}\n", k + 1, emus[k]->path(),
                         o.link.empty() ? "" : " (also " + linkOf(k) + ")");
  } else {
    out << fmt::format("Rhino {} controller emulator on {}{}\n", rhino::dialectTitle(config.settings.dialect),
                       emus[0]->path(), o.link.empty() ? "" : " (also " + o.link + ")");
  }
  out << fmt::format("robot {}: motors {}; line {}\n", o.robot, motorList(config.motors),
                     describe(config.settings.line));
  if (several) {
    std::string devices;
    for (std::size_t k = 0; k < emus.size(); ++k) devices += fmt::format(" --device LABEL{}={}", k + 1, deviceOf(k));
    out << fmt::format("connect: robotsim run --cell CELL{} --dialect {}\n", devices, dialect);
  } else {
    out << fmt::format("connect: robotsim run PROGRAM --device {} --dialect {}\n", deviceOf(0), dialect);
  }
  if (config.fault.kind != rhino::FaultKind::None)
    out << fmt::format("fault: {} after {} commands{}\n", rhino::faultName(config.fault.kind), config.fault.after,
                       several ? ", on every controller" : "");
  out << (o.noStdin ? "Ctrl-C quits.\n" : "Type 'help' for commands; Ctrl-C or 'quit' stops.\n");
  out.flush();

  // The first controller is pumped here, with the console; the others each on a thread of their own.
  for (std::size_t k = 1; k < emus.size(); ++k) emus[k]->start();
  rhino::PtyEmulator& first = *emus[0];
  rhino::InterruptGuard guard;
  EmulatorSession session{emus, out};
  const bool statusLine = !o.quiet && &out == &std::cout && ::isatty(STDOUT_FILENO);
  bool stdinOpen = !o.noStdin;
  std::string typed;
  std::size_t scriptLine = 0;
  std::vector<std::uint64_t> echoed(emus.size(), 0);  // commands received and already echoed (--verbose)
  vm::Micros lastStatus = -1'000'000;
  const vm::Micros end = o.duration > 0 ? first.now() + static_cast<vm::Micros>(std::llround(o.duration * 1e6)) : 0;
  const auto clearStatus = [&] {
    if (statusLine) out << "\r\x1b[K";
  };
  bool hungUp = false;
  while (!guard.flag() && !session.quit && !hungUp && !(end && first.now() >= end)) {
    if (first.pump(20'000, stdinOpen ? STDIN_FILENO : -1)) {
      char buf[512];
      const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
      if (n <= 0)
        stdinOpen = false;  // EOF: keep emulating (it may run in the background)
      else
        typed.append(buf, static_cast<std::size_t>(n));
    }
    for (std::size_t nl; (nl = typed.find('\n')) != std::string::npos;) {
      clearStatus();
      if (std::string e = consoleCommand(session, typed.substr(0, nl)); !e.empty()) out << e << '\n';
      typed.erase(0, nl + 1);
    }
    while (scriptLine < script.size() && first.now() >= session.waitUntil && !session.quit) {
      clearStatus();
      if (std::string e = consoleCommand(session, script[scriptLine]); !e.empty())
        out << fmt::format("{}:{}: {}\n", o.script, scriptLine + 1, e);
      ++scriptLine;
    }
    for (std::size_t k = 0; k < emus.size(); ++k) {
      rhino::PtyEmulator& emu = *emus[k];
      if (o.verbose)
        for (const std::string& c : emu.receivedSince(echoed[k])) {
          clearStatus();
          out << named(k) << "host: " << c << '\n';
        }
      if (!o.quiet)
        for (const std::string& e : emu.takeEvents()) {
          clearStatus();
          out << named(k) << e << '\n';
        }
      if (emu.hungUp()) {
        clearStatus();
        out << named(k) << "The emulator hung up as asked (--fault hangup); start it again to reconnect.\n";
        hungUp = true;
      }
    }
    if (statusLine && first.now() - lastStatus >= 100'000) {
      out << '\r' << first.statusLine() << "\x1b[K";
      out.flush();
      lastStatus = first.now();
    }
    out.flush();
  }
  clearStatus();
  for (std::size_t k = 0; k < emus.size(); ++k) {
    emus[k]->stop();
    out << named(k) << "emulator stopped: " << emus[k]->statusLine() << '\n';
  }
  for (std::size_t k = 0; k < emus.size() && !o.link.empty(); ++k) {
    std::error_code ec;
    const std::string link = linkOf(k);
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(link, ec))) std::filesystem::remove(link, ec);
  }
  return kExitOk;
}

}  // namespace rs::cli
