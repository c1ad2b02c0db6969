// Safety: targets beyond a motor's soft limits are refused before a byte is
// sent; Ctrl-C stops every motor; a stopped machine stays stopped.
#include <signal.h>

#include <catch2/catch.hpp>

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "runtime/rhino/interrupt.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using namespace rs::rhino::testing;
namespace vm = rs::vm;

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST_CASE("a target beyond a soft limit is refused with no byte sent", "[serial]") {
  const auto motors = twoMotors();
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    LoopbackRig rig(testSettings(d), motors, emulatorFor(testSettings(d), motors));
    REQUIRE(rig.machine.open());
    const std::string before = rig.logText.str();
    const std::uint64_t commands = rig.engine.snapshot().commands;
    const std::vector<std::int32_t> beyond{1001, 0};
    const vm::Status st = rig.machine.moveTo(beyond);
    CHECK_FALSE(st);
    CHECK(st.message == "motor E target 1001 is outside its range -1000..1000: nothing was sent to the controller");
    const std::vector<std::int32_t> belowGripper{0, -1};
    CHECK_FALSE(rig.machine.moveTo(belowGripper));
    CHECK(rig.logText.str() == before);
    CHECK(rig.engine.snapshot().commands == commands);
    CHECK(rig.machine.positions()[0] == 0);
    // The machine is still usable: a good move goes through.
    const std::vector<std::int32_t> fine{1000, 120};
    CHECK(rig.machine.moveTo(fine));
  }
}

TEST_CASE("a MOVE that would leave the range stops the run with no byte for it", "[serial]") {
  const auto motors = twoMotors();
  const vm::Image image = compileFor("MOVETO 900 0\nMOVE 200 0\nEND\n", motors);
  LoopbackRig rig(testSettings(Dialect::Mark3), motors, emulatorFor(testSettings(Dialect::Mark3), motors));
  REQUIRE(rig.machine.open());
  const RunResult r = runOn(image, rig.machine);
  CHECK(r.outcome.reason == vm::StopReason::RuntimeError);
  CHECK(r.outcome.index == 1);
  CHECK_THAT(r.outcome.message, Catch::Contains("outside its range -1000..1000"));
  // The last thing on the line is the first move finishing: E? answered 0.
  const auto sent = sentCommands(rig.logText.str());
  REQUIRE_FALSE(sent.empty());
  CHECK(sent.back() == "E?");
  CHECK(r.positions == std::vector<std::int32_t>{900, 0});
}

TEST_CASE("Mark IV: a target the protocol cannot carry is refused with no byte sent", "[serial]") {
  std::vector<vm::MotorSpec> motors = {{'F', vm::JointKind::Revolute, 0.01, -40000, 40000, 1000}};
  LoopbackRig rig(testSettings(Dialect::Mark4), motors, emulatorFor(testSettings(Dialect::Mark4), motors));
  REQUIRE(rig.machine.open());
  const std::size_t before = lines(rig.logText.str());
  const std::vector<std::int32_t> far{32768};
  const vm::Status st = rig.machine.moveTo(far);
  CHECK_THAT(st.message, Catch::Contains("beyond what a Mark IV accepts (-32767..32767): nothing was sent"));
  CHECK(lines(rig.logText.str()) == before);
}

TEST_CASE("Ctrl-C: the next call stops every motor and ends the run", "[serial]") {
  const auto motors = twoMotors();
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    InterruptGuard guard;
    LoopbackRig rig(testSettings(d), motors, emulatorFor(testSettings(d), motors), &guard.flag());
    REQUIRE(rig.machine.open());
    ::raise(SIGINT);
    REQUIRE(guard.flag());
    const std::vector<std::int32_t> target{500, 50};
    const vm::Status st = rig.machine.moveTo(target);
    CHECK_THAT(st.message, Catch::StartsWith("interrupted (Ctrl-C); stop sent to every motor"));
    const auto sent = sentCommands(rig.logText.str());
    CHECK(contains(sent, d == Dialect::Mark3 ? "EX" : "MA"));
    CHECK_FALSE(contains(sent, "E+40"));
    // Stopped for good: nothing else goes out.
    const std::string before = rig.logText.str();
    CHECK_FALSE(rig.machine.setOutput(1, true));
    CHECK_FALSE(rig.machine.input(1));
    CHECK(rig.logText.str() == before);
    guard.clear();
  }
}

TEST_CASE("Ctrl-C during a long move on a pty stops the motors within a poll", "[serial]") {
  auto motors = twoMotors();
  motors[0].speed = 200;  // 900 steps: 4.5 s if nobody stops it
  const RhinoSettings settings = testSettings(Dialect::Mark3);
  PtyLine line(settings, emulatorFor(settings, motors));
  const auto& emu = line.emu;
  InterruptGuard guard;
  RhinoMachine machine(motors, settings, *line.port, line.clock, nullptr, &guard.flag());
  REQUIRE(machine.open());
  // Ctrl-C once the motor is on its way (not after a fixed delay: on a
  // loaded machine the move may start late), then time the stop from there.
  std::atomic<std::int64_t> pressedAt{0};
  std::thread presser([&] {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (emu->snapshot().motors[4].position <= 0 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    pressedAt = std::chrono::steady_clock::now().time_since_epoch().count();
    ::raise(SIGINT);
  });
  const std::vector<std::int32_t> target{900, 0};
  const vm::Status st = machine.moveTo(target);
  const auto returned = std::chrono::steady_clock::now().time_since_epoch();
  presser.join();
  const double seconds =
      std::chrono::duration<double>(returned - std::chrono::steady_clock::duration(pressedAt.load())).count();
  CHECK_THAT(st.message, Catch::StartsWith("interrupted (Ctrl-C); stop sent to every motor (EX AX)"));
  CHECK(seconds < 1.5);  // within a poll of the key, not at the move's end (4.5 s)
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const auto snap = emu->snapshot();
  CHECK(snap.motors[4].registerSteps == 0);
  CHECK(snap.motors[4].position > 0);
  CHECK(snap.motors[4].position < 900);
  CHECK(machine.positions()[0] > 0);  // the last count the controller reported
  guard.clear();
}

TEST_CASE("Ctrl-C while a read waits on a silent controller ends the wait at once", "[serial]") {
  const auto motors = twoMotors();
  RhinoSettings settings = testSettings(Dialect::Mark3);
  settings.timeout = 10'000'000;  // the read would wait 10 s for an answer
  PtyLine line(settings, emulatorFor(settings, motors));
  const auto& emu = line.emu;
  InterruptGuard guard;
  RhinoMachine machine(motors, settings, *line.port, line.clock, nullptr, &guard.flag());
  REQUIRE(machine.open());
  emu->setFault({FaultKind::Silence, 1, 0});  // obeys "E+40", never answers "E?"
  // The signal goes to this thread, blocked in poll(), not to the presser.
  const pthread_t reader = ::pthread_self();
  std::atomic<std::int64_t> pressedAt{0};
  std::thread presser([&] {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (emu->snapshot().commands < 3 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // well into the read's wait
    pressedAt = std::chrono::steady_clock::now().time_since_epoch().count();
    ::pthread_kill(reader, SIGINT);
  });
  const std::vector<std::int32_t> target{900, 0};
  const vm::Status st = machine.moveTo(target);
  const auto returned = std::chrono::steady_clock::now().time_since_epoch();
  presser.join();
  const double seconds =
      std::chrono::duration<double>(returned - std::chrono::steady_clock::duration(pressedAt.load())).count();
  CHECK_THAT(st.message, Catch::StartsWith("interrupted (Ctrl-C); stop sent to every motor (EX AX)"));
  CHECK(seconds < 1.0);  // at the key, not at the 10 s timeout
  guard.clear();
}

TEST_CASE("Mark III: never more steps to go than one answer byte can report", "[serial]") {
  const auto motors = twoMotors();
  RhinoSettings s = testSettings(Dialect::Mark3);
  s.chunk = 120;  // the register would hold it, the answer byte could not
  LoopbackRig rig(s, motors, emulatorFor(s, motors));
  REQUIRE(rig.machine.open());
  const std::vector<std::int32_t> far{-700, 120};
  REQUIRE(rig.machine.moveTo(far));
  CHECK(std::vector<std::int32_t>(rig.machine.positions().begin(), rig.machine.positions().end()) == far);
  CHECK(rig.engine.snapshot().motors[4].position == -700);  // the emulator's encoder agrees
  for (const std::string& c : sentCommands(rig.logText.str()))
    if (c.size() > 2 && (c[1] == '+' || c[1] == '-')) CHECK(std::abs(std::stoi(c.substr(1))) <= 95);
}
