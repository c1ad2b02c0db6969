// Helpers for the serial backend tests: compile a small program for a small
// motor table, and rigs that put a RhinoMachine in front of the emulator,
// either in-process on a manual clock (deterministic, for transcripts) or
// through a real pseudo-terminal on the wall clock (end to end).
#pragma once

#include <catch2/catch.hpp>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "runtime/run/run.h"
#include "runtime/rhino/emulator.h"
#include "runtime/rhino/rhino_machine.h"
#include "runtime/rhino/serial_log.h"
#include "runtime/rhino/serial_port.h"
#include "vm/interpreter.h"

namespace rs::rhino::testing {

/// Two motors keep transcripts short: an arm joint E and the gripper A.
inline std::vector<vm::MotorSpec> twoMotors() {
  return {{'E', vm::JointKind::Revolute, 0.1, -1000, 1000, 1000}, {'A', vm::JointKind::Gripper, 0.5, 0, 120, 500}};
}

inline vm::Image compileFor(const std::string& text, const std::vector<vm::MotorSpec>& motors) {
  const diag::SourceFile source("test.rsp", text);
  compiler::CompileResult r = compiler::compile(source, {"test-robot", motors, vm::kDefaultCallDepth});
  INFO(text);
  for (const auto& d : r.diagnostics) INFO(d.message);
  REQUIRE(r.ok());
  return *r.image;
}

/// Settings for tests: quick polls, short timeouts, so faults end fast.
inline RhinoSettings testSettings(Dialect d) {
  RhinoSettings s = defaultSettings(d);
  s.pollInterval = 20'000;
  s.timeout = 200'000;
  s.stallTimeout = 2'000'000;
  s.homeTimeout = 20'000'000;
  return s;
}

inline EmulatorConfig emulatorFor(const RhinoSettings& s, const std::vector<vm::MotorSpec>& motors) {
  EmulatorConfig c;
  c.settings = s;
  c.motors = motors;
  return c;
}

/// In-process, on a manual clock: the transcript is the same on every run.
struct LoopbackRig {
  ManualClock clock;
  EmulatorEngine engine;
  LoopbackLink link;
  std::ostringstream logText;
  SerialLog log{logText};
  LoggedLink logged;
  RhinoMachine machine;

  LoopbackRig(const RhinoSettings& s, const std::vector<vm::MotorSpec>& motors, const EmulatorConfig& emu,
              const std::atomic<bool>* interrupt = nullptr)
      : engine(emu),
        link(engine, clock),
        logged(link, log, clock),
        machine(motors, s, logged, clock, &log, interrupt) {}
};

/// Through a real pseudo-terminal, on the wall clock: the emulator made of
/// `config` (with `inputsOn` switched on) started behind the terminal, the
/// port open on its other end with the settings' line, a clock, and a log
/// for a LoggedLink when the test wants one. What every test of a fault on
/// the line sets up first.
struct PtyLine {
  std::unique_ptr<PtyEmulator> emu;
  std::unique_ptr<SerialPort> port;
  SteadyClock clock;
  std::ostringstream logText;
  SerialLog log{logText};

  PtyLine(const RhinoSettings& s, const EmulatorConfig& config, std::initializer_list<int> inputsOn = {}) {
    std::string error;
    emu = PtyEmulator::open(config, error);
    INFO(error);
    REQUIRE(emu);
    for (int input : inputsOn) emu->setInput(input, true);
    emu->start();
    port = SerialPort::open(emu->path(), s.line, error);
    INFO(error);
    REQUIRE(port);
  }
};

/// What a run left behind, for comparing two machines.
struct RunResult {
  vm::RunOutcome outcome;
  std::vector<std::int32_t> positions;
  std::uint8_t outputs = 0;
  std::vector<std::int32_t> variables;
};

/// A run of `image` (with no stimuli) on `machine`, which the caller keeps.
inline RunResult runOn(const vm::Image& image, vm::Machine& machine, vm::RunLimits limits = {1'000'000, 600'000'000}) {
  runtime::RunSpec spec;
  spec.image = std::make_shared<const vm::Image>(image);
  spec.limits = limits;
  runtime::Run run(std::move(spec), machine);
  RunResult r;
  r.outcome = run.runToEnd();
  r.positions.assign(machine.positions().begin(), machine.positions().end());
  r.outputs = machine.outputs();
  const auto vars = run.interpreter().variables();
  r.variables.assign(vars.begin(), vars.end());
  return r;
}

/// The commands of a transcript the host sent ("E+40", "E?", ...).
inline std::vector<std::string> sentCommands(const std::string& log) {
  std::vector<std::string> out;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    const auto gt = line.find(" > ");
    if (gt == std::string::npos || line[0] == '#') continue;
    const auto q = line.find('"', gt);
    const auto end = line.find("\\r\"", q);
    if (q != std::string::npos && end != std::string::npos) out.push_back(line.substr(q + 1, end - q - 1));
  }
  return out;
}

inline bool contains(const std::vector<std::string>& v, const std::string& s) {
  for (const auto& x : v)
    if (x == s) return true;
  return false;
}

}  // namespace rs::rhino::testing
