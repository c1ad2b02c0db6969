// End to end through a real pseudo-terminal: the emulator runs on its own
// thread, the backend opens the device with termios like a real port. The
// same program run in pure simulation and on the emulator must end with the
// same encoder positions, outputs and variables.
#include <catch2/catch.hpp>

#include "runtime/sim/sim_machine.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using namespace rs::rhino::testing;
namespace vm = rs::vm;

// Moves, a taught point, relative moves, outputs, inputs and HRDHOME.
const char* const kSerialE2eProgram =
    "SET COUNT 0\n"
    "loop: MOVETO 300 100\n"
    "  OUTSIG 2 ON\n"
    "  MOVEP PICK\n"
    "  MOVE 40 -20\n"
    "  OUTSIG 5 ON\n"
    "  ADD COUNT 1\n"
    "  JMPIN 3 ON skip\n"
    "  ADD COUNT 100\n"
    "skip: WAITFOR 6 ON\n"
    "  JMPVAR COUNT < 2 loop\n"
    "  OUTSIG 2 OFF\n"
    "  MOVETO -250 120\n"
    "  HRDHOME\n"
    "  END\n"
    "POINTS\n"
    "PICK -120 80\n";

std::vector<vm::MotorSpec> fastMotors() {
  auto motors = twoMotors();
  motors[0].speed = 4000;
  motors[1].speed = 2000;
  return motors;
}

RunResult simulate(const vm::Image& image) {
  rs::stimuli::Stimuli stimuli;
  stimuli.changes = {{0, 3, true}, {0, 6, true}};
  rs::runtime::SimMachine sim(image.motors, stimuli);
  return runOn(image, sim);
}

RunResult onEmulator(const vm::Image& image, Dialect d) {
  const RhinoSettings settings = testSettings(d);
  PtyLine line(settings, emulatorFor(settings, image.motors), {3, 6});
  const auto& emu = line.emu;
  RhinoMachine machine(image.motors, settings, *line.port, line.clock);
  const vm::Status opened = machine.open();
  INFO(opened.message);
  REQUIRE(opened);
  RunResult r = runOn(image, machine);
  const EmulatorSnapshot snap = emu->snapshot();
  // The controller's own encoders agree with what the backend reports (a
  // Mark III homes to the edge of its switch, within the switch width).
  for (std::size_t i = 0; i < image.motors.size(); ++i) {
    const auto& m = snap.motors[static_cast<std::size_t>(image.motors[i].letter - 'A')];
    if (d == Dialect::Mark4)
      CHECK(m.position == r.positions[i]);
    else
      CHECK(std::abs(m.position - r.positions[i]) <= 20);
  }
  CHECK(snap.outputs == r.outputs);
  return r;
}

void sameEnd(Dialect d) {
  const vm::Image image = compileFor(kSerialE2eProgram, fastMotors());
  const RunResult sim = simulate(image);
  REQUIRE(sim.outcome.ok());
  const RunResult real = onEmulator(image, d);
  INFO(real.outcome.message);
  REQUIRE(real.outcome.ok());
  CHECK(real.positions == sim.positions);
  CHECK(real.outputs == sim.outputs);
  CHECK(real.variables == sim.variables);
  CHECK(real.outcome.steps == sim.outcome.steps);
}

}  // namespace

TEST_CASE("Mark III on a pty ends like the simulation", "[serial]") { sameEnd(Dialect::Mark3); }

TEST_CASE("Mark IV on a pty ends like the simulation", "[serial]") { sameEnd(Dialect::Mark4); }

TEST_CASE("positions mid-program match the simulation after every move", "[serial]") {
  const vm::Image image = compileFor("MOVETO 333 17\nMOVE -500 50\nMOVETO 0 120\nEND\n", fastMotors());
  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    const RhinoSettings settings = testSettings(d);
    PtyLine line(settings, emulatorFor(settings, image.motors));
    const auto& emu = line.emu;
    RhinoMachine machine(image.motors, settings, *line.port, line.clock);
    REQUIRE(machine.open());
    rs::runtime::SimMachine sim(image.motors, {});
    const std::vector<std::vector<std::int32_t>> targets = {{333, 17}, {-167, 67}, {0, 120}};
    for (const auto& t : targets) {
      REQUIRE(machine.moveTo(t));
      REQUIRE(sim.moveTo(t));
      CHECK(std::vector<std::int32_t>(machine.positions().begin(), machine.positions().end()) == t);
      const auto snap = emu->snapshot();
      CHECK(snap.motors[4].position == t[0]);  // E: the emulator's encoder agrees
      CHECK(snap.motors[0].position == t[1]);  // A
    }
    CHECK(machine.now() > 0);
  }
}
