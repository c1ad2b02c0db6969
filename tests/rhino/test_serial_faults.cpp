// Every controller fault the emulator can inject, through a real pty, on
// both dialects: the documented error, a stop sent to every motor, and no
// hang (each run is timed; the timeout is 0.2 s here).
#include <catch2/catch.hpp>
#include <chrono>

#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using namespace rs::rhino::testing;
namespace vm = rs::vm;

struct FaultRun {
  vm::RunOutcome outcome;
  std::string log;
  std::vector<std::string> received;  // by the emulator
  EmulatorSnapshot after;
  double seconds = 0;
};

// A long move (E crosses 1800 steps at 1000/s) that the fault interrupts.
FaultRun runWithFault(Dialect d, FaultKind kind, std::uint64_t after) {
  const auto motors = twoMotors();
  const vm::Image image = compileFor("MOVETO 900 100\nMOVETO -900 0\nEND\n", motors);
  const RhinoSettings settings = testSettings(d);
  EmulatorConfig config = emulatorFor(settings, motors);
  config.fault = {kind, after, 1'000'000};  // slow: answers 1 s late, the timeout is 0.2 s
  PtyLine line(settings, config);
  const auto& emu = line.emu;
  LoggedLink logged(*line.port, line.log, line.clock);
  const auto t0 = std::chrono::steady_clock::now();
  FaultRun r;
  {
    RhinoMachine machine(motors, settings, logged, line.clock, &line.log);
    REQUIRE(machine.open());
    r.outcome = runOn(image, machine, {}).outcome;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Let the emulator take in the last bytes (the stops) before looking.
  for (int i = 0; i < 50 && !emu->hungUp(); ++i) {
    const auto got = emu->received();
    if (!got.empty() && (got.back() == "AX" || got.back() == "MA")) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  r.log = line.logText.str();
  r.received = emu->received();
  r.after = emu->snapshot();
  return r;
}

void stoppedEverything(const FaultRun& r, Dialect d) {
  INFO(r.outcome.message);
  INFO(r.log);
  CHECK(r.outcome.reason == vm::StopReason::RuntimeError);
  CHECK(r.seconds < 5.0);
  if (d == Dialect::Mark3) {
    CHECK_THAT(r.outcome.message, Catch::Contains("stop sent to every motor (EX AX)"));
    CHECK(contains(r.received, "EX"));
    CHECK(contains(r.received, "AX"));
    CHECK(r.after.motors[4].registerSteps == 0);  // E no longer moving
    CHECK(r.after.motors[0].registerSteps == 0);  // A
  } else {
    CHECK_THAT(r.outcome.message, Catch::Contains("stop sent to every motor (MA)"));
    CHECK(contains(r.received, "MA"));
    CHECK_FALSE(r.after.motors[4].running);
    CHECK_FALSE(r.after.motors[0].running);
  }
  CHECK_THAT(r.log, Catch::Contains(" ! stop sent to every motor"));
}

}  // namespace

TEST_CASE("a silent controller: timeout, stop, no hang", "[serial]") {
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    const FaultRun r = runWithFault(d, FaultKind::Silence, 8);
    CHECK_THAT(r.outcome.message, Catch::Contains("no reply from the controller to"));
    CHECK_THAT(r.outcome.message, Catch::Contains("within 0.200 s (timeout)"));
    stoppedEverything(r, d);
  }
}

TEST_CASE("a garbling controller: garbage error, stop, no hang", "[serial]") {
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    const FaultRun r = runWithFault(d, FaultKind::Garbage, 8);
    CHECK_THAT(r.outcome.message, Catch::StartsWith("garbage from the controller: "));
    CHECK_THAT(r.outcome.message, Catch::Contains("\\x15"));
    stoppedEverything(r, d);
  }
}

TEST_CASE("answers slower than the timeout: timeout error, stop, no hang", "[serial]") {
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    const FaultRun r = runWithFault(d, FaultKind::Slow, 8);
    CHECK_THAT(r.outcome.message, Catch::Contains("(timeout)"));
    stoppedEverything(r, d);
  }
}

TEST_CASE("a controller that hangs up: port error, stop attempted, no hang", "[serial]") {
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    const FaultRun r = runWithFault(d, FaultKind::Hangup, 8);
    INFO(r.outcome.message);
    INFO(r.log);
    CHECK(r.outcome.reason == vm::StopReason::RuntimeError);
    CHECK(r.seconds < 5.0);
    CHECK_THAT(r.outcome.message, Catch::StartsWith("the serial port /dev/"));
    CHECK_THAT(r.outcome.message, Catch::Contains("(the controller is gone)"));
    CHECK_THAT(r.outcome.message,
               Catch::EndsWith(
                   d == Dialect::Mark3
                       ? "stop could NOT be sent to every motor (EX AX): the port is gone; switch the controller off"
                       : "stop could NOT be sent to every motor (MA): the port is gone; switch the controller off"));
    // The stops were tried, each logged with why it did not go out.
    const char* stop = d == Dialect::Mark3 ? "\"EX\\r\"  (not sent: " : "\"MA\\r\"  (not sent: ";
    CHECK_THAT(r.log, Catch::Contains(stop));
    if (d == Dialect::Mark3) CHECK_THAT(r.log, Catch::Contains("\"AX\\r\"  (not sent: "));
  }
}

TEST_CASE("a controller silent from the start fails at open, before any move", "[serial]") {
  const auto motors = twoMotors();
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    const RhinoSettings settings = testSettings(d);
    EmulatorConfig config = emulatorFor(settings, motors);
    config.fault = {FaultKind::Silence, 0, 0};
    PtyLine line(settings, config);
    RhinoMachine machine(motors, settings, *line.port, line.clock);
    const vm::Status st = machine.open();
    CHECK_FALSE(st);
    CHECK_THAT(st.message, Catch::StartsWith(d == Dialect::Mark3 ? "no working Mark III controller on /dev/"
                                                                 : "no working Mark IV controller on /dev/"));
    CHECK_THAT(st.message, Catch::Contains("(timeout)"));
    CHECK_THAT(st.message, Catch::Contains("stop sent to every motor"));
    // And the machine refuses everything after that, without a byte.
    const std::vector<std::int32_t> zero{0, 0};
    CHECK_FALSE(machine.moveTo(zero));
  }
}

TEST_CASE("the in-process emulator injects the same faults on a manual clock", "[serial]") {
  const auto motors = twoMotors();
  const vm::Image image = compileFor("MOVETO 900 100\nEND\n", motors);
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4})
    for (const FaultKind k : {FaultKind::Silence, FaultKind::Garbage, FaultKind::Slow, FaultKind::Hangup}) {
      EmulatorConfig config = emulatorFor(testSettings(d), motors);
      config.fault = {k, 6, 1'000'000};
      LoopbackRig rig(testSettings(d), motors, config);
      REQUIRE(rig.machine.open());
      const RunResult r = runOn(image, rig.machine);
      INFO(faultName(k) << " " << r.outcome.message);
      CHECK(r.outcome.reason == vm::StopReason::RuntimeError);
      CHECK(rig.clock.now() < 5'000'000);
      const auto sent = sentCommands(rig.logText.str());
      CHECK(contains(sent, d == Dialect::Mark3 ? "AX" : "MA"));
      CHECK_FALSE(rig.machine.failure().empty());
    }
}
