// The simulated machine: motion timing and positions, outputs, reactive
// rules, waits and deadlocks. Expected values are worked out by hand in the
// comments (speeds: E 400, D 400, C 300, B 500, A 200 units per second).
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <vector>

#include "runtime/sim/sim_machine.h"
#include "compiler/stimuli/stimuli.h"
#include "stdlib/default_robot.h"

namespace {

using rs::stimuli::InputChange;
using rs::runtime::SimMachine;
using rs::stimuli::Stimuli;
using rs::vm::Micros;
using rs::vm::Status;
using Targets = std::vector<std::int32_t>;

constexpr Micros kSimSecond = 1'000'000;

SimMachine scara(Stimuli stimuli = {}) {
  return SimMachine(rs::stdlib::rhinoScaraMotors(), std::move(stimuli));
}

Stimuli parsed(std::string_view text) {
  auto result = rs::stimuli::parseStimuli(text, "test.stim");
  REQUIRE(result.ok());
  return std::move(result).value();
}

Targets positionsOf(const SimMachine& m) { return {m.positions().begin(), m.positions().end()}; }

}  // namespace

TEST_CASE("the default robot is the paper's Rhino SCARA", "[stdlib]") {
  const auto motors = rs::stdlib::rhinoScaraMotors();
  REQUIRE(motors.size() == 5);
  CHECK(rs::stdlib::rhinoScaraName() == "rhino-scara");
  CHECK(motors[0] == rs::vm::MotorSpec{'E', rs::vm::JointKind::Revolute, 0.1175, -1000, 1000, 400});
  CHECK(motors[1] == rs::vm::MotorSpec{'D', rs::vm::JointKind::Revolute, 0.2233, -550, 550, 400});
  CHECK(motors[2] == rs::vm::MotorSpec{'C', rs::vm::JointKind::Prismatic, 0.1200, -350, 350, 300});
  CHECK(motors[3] == rs::vm::MotorSpec{'B', rs::vm::JointKind::Revolute, 0.2233, -700, 700, 500});
  CHECK(motors[4] == rs::vm::MotorSpec{'A', rs::vm::JointKind::Gripper, 0.5, 0, 120, 200});
}

TEST_CASE("a new machine starts at zero with everything off", "[sim]") {
  auto m = scara();
  CHECK(m.now() == 0);
  CHECK(positionsOf(m) == Targets{0, 0, 0, 0, 0});
  CHECK(m.outputs() == 0);
  CHECK(m.inputs() == 0);
  CHECK(m.motors().size() == 5);
}

TEST_CASE("moving E by 400 units at 400 u/s takes exactly one second", "[sim][motion]") {
  auto m = scara();
  REQUIRE(m.moveTo(Targets{400, 0, 0, 0, 0}));
  CHECK(m.now() == 1'000'000);
  CHECK(positionsOf(m) == Targets{400, 0, 0, 0, 0});
  CHECK(m.segment(0).from == 0);
  CHECK(m.segment(0).to == 400);
  CHECK(m.segment(0).start == 0);
  CHECK(m.segment(0).end == 1'000'000);
}

TEST_CASE("a mixed move ends when the slowest motor arrives", "[sim][motion]") {
  auto m = scara();
  // E 400/400 = 1 s, D 500/400 = 1.25 s, C 150/300 = 0.5 s,
  // B 250/500 = 0.5 s, A 100/200 = 0.5 s.
  REQUIRE(m.moveTo(Targets{400, 500, 150, -250, 100}));
  CHECK(m.now() == 1'250'000);
  CHECK(m.segment(0).end == 1'000'000);
  CHECK(m.segment(1).end == 1'250'000);
  CHECK(m.segment(2).end == 500'000);
  CHECK(m.segment(3).end == 500'000);
  CHECK(m.segment(4).end == 500'000);
  // A second move starts every motor from where the first left it.
  REQUIRE(m.moveTo(Targets{0, 500, 150, -250, 100}));  // only E: 400 u = 1 s
  CHECK(m.now() == 2'250'000);
  CHECK(m.segment(1).start == 1'250'000);
  CHECK(m.segment(1).end == 1'250'000);
}

TEST_CASE("travel time rounds up to the next microsecond", "[sim][motion]") {
  auto m = scara();
  // C: 1 unit at 300 u/s = 3333.33 us -> 3334 us.
  REQUIRE(m.moveTo(Targets{0, 0, 1, 0, 0}));
  CHECK(m.now() == 3334);
  CHECK(m.positionAt(2, 3333) == 0);
  CHECK(m.positionAt(2, 3334) == 1);
}

TEST_CASE("positionAt follows the segment analytically", "[sim][motion]") {
  auto m = scara();
  REQUIRE(m.moveTo(Targets{400, 0, 0, 0, 0}));
  CHECK(m.positionAt(0, 0) == 0);
  CHECK(m.positionAt(0, 500'000) == 200);  // halfway is exactly half
  CHECK(m.positionAt(0, 250'000) == 100);
  CHECK(m.positionAt(0, 1'000'000) == 400);
  CHECK(m.positionAt(0, 9'000'000) == 400);  // stays at the end
  CHECK(m.positionAt(1, 500'000) == 0);      // D did not move
  CHECK(m.positionAt(99, 500'000) == 0);     // no such motor

  SECTION("moving down rounds toward the start") {
    REQUIRE(m.moveTo(Targets{-100, 0, 0, 0, 0}));  // 500 u at 400 u/s = 1.25 s
    CHECK(m.now() == 2'250'000);
    CHECK(m.positionAt(0, 1'000'000 + 3'000) == 399);    // 1.2 units covered -> 1
    CHECK(m.positionAt(0, 1'000'000 + 625'000) == 150);  // halfway: 250 units
    CHECK(m.positionAt(0, 2'249'999) == -99);            // 499.9996 -> 499
    CHECK(m.positionAt(0, 2'250'000) == -100);
    CHECK(m.positionAt(0, 500'000) == 400);  // before this segment: its start
  }
}

TEST_CASE("a long move costs no more than a short one", "[sim][motion]") {
  // 4e9 units at 1 u/s: 4e15 us of virtual time, computed not stepped.
  const std::vector<rs::vm::MotorSpec> motors{
      {'Z', rs::vm::JointKind::Prismatic, 1.0, -2'000'000'000, 2'000'000'000, 1}};
  SimMachine m(motors, {});
  REQUIRE(m.moveTo(Targets{-2'000'000'000}));
  REQUIRE(m.moveTo(Targets{2'000'000'000}));
  CHECK(m.now() == 6'000'000'000'000'000);
  CHECK(m.positionAt(0, 4'000'000'000'000'000) == 0);
  CHECK(m.positionAt(0, 2'000'000'000'000'001) == -2'000'000'000);  // 1 us covers 0 units
  CHECK(m.positionAt(0, 5'999'999'999'999'999) == 1'999'999'999);
}

TEST_CASE("targets outside a motor's range are a fault and nothing moves", "[sim][motion]") {
  auto m = scara();
  const auto status = m.moveTo(Targets{1001, 0, 0, 0, 0});
  CHECK(status.code == Status::Code::Fault);
  CHECK(status.message == "motor E target 1001 is outside its range -1000..1000");
  CHECK(m.moveTo(Targets{0, 0, 0, 0, 121}).message ==
        "motor A target 121 is outside its range 0..120");
  CHECK(m.moveTo(Targets{0, 0, -351, 0, 0}).message ==
        "motor C target -351 is outside its range -350..350");
  CHECK(m.moveTo(Targets{0, 0, 0}).message == "move has 3 targets for 5 motors");
  CHECK(m.now() == 0);
  CHECK(positionsOf(m) == Targets{0, 0, 0, 0, 0});
}

TEST_CASE("hardHome moves to zero at motor speed, reset jumps there", "[sim][motion]") {
  auto m = scara();
  REQUIRE(m.moveTo(Targets{400, 0, 0, 0, 100}));  // 1 s (E), A 0.5 s
  REQUIRE(m.setOutput(4, true));
  REQUIRE(m.hardHome());
  CHECK(m.now() == 2'000'000);
  CHECK(positionsOf(m) == Targets{0, 0, 0, 0, 0});

  REQUIRE(m.moveTo(Targets{-200, 100, 0, 0, 0}));  // 0.5 s
  CHECK(m.now() == 2'500'000);
  REQUIRE(m.reset());
  CHECK(m.now() == 2'500'000);  // takes no time
  CHECK(positionsOf(m) == Targets{0, 0, 0, 0, 0});
  CHECK(m.positionAt(0, 2'500'000) == 0);
  CHECK(m.outputs() == 0b1000);  // outputs unchanged
}

TEST_CASE("delay advances the clock", "[sim]") {
  auto m = scara();
  REQUIRE(m.delay(1'500'000));
  REQUIRE(m.delay(0));
  CHECK(m.now() == 1'500'000);
  CHECK(m.delay(-1).code == Status::Code::Fault);
  CHECK(m.now() == 1'500'000);
}

TEST_CASE("the clock refuses to overflow", "[sim]") {
  auto m = scara();
  REQUIRE(m.delay(std::numeric_limits<Micros>::max() - 10));
  CHECK(m.delay(11).message == "the virtual clock overflowed");
  CHECK(m.moveTo(Targets{400, 0, 0, 0, 0}).message == "the virtual clock overflowed");
  CHECK(positionsOf(m) == Targets{0, 0, 0, 0, 0});
  REQUIRE(m.delay(10));
  CHECK(m.now() == std::numeric_limits<Micros>::max());
}

TEST_CASE("outputs are a bit mask, bit 0 = output 1", "[sim][io]") {
  auto m = scara();
  REQUIRE(m.setOutput(1, true));
  REQUIRE(m.setOutput(8, true));
  CHECK(m.outputs() == 0b1000'0001);
  REQUIRE(m.setOutput(1, false));
  CHECK(m.outputs() == 0b1000'0000);
  CHECK(m.setOutput(9, true).message == "output 9 does not exist (outputs are 1..8)");
  CHECK(m.setOutput(0, true).code == Status::Code::Fault);
}

TEST_CASE("timed changes apply at their time", "[sim][io]") {
  auto m = scara(parsed("at 1 input 4 on\nat 2 input 4 off\nat 0 input 8 on\n"));
  CHECK(m.inputs() == 0b1000'0000);  // changes at time 0 apply at once
  REQUIRE(m.delay(999'999));
  CHECK_FALSE(m.input(4));
  REQUIRE(m.delay(1));
  CHECK(m.input(4));
  SECTION("toggled on then off before now reads off") {
    REQUIRE(m.delay(2 * kSimSecond));
    CHECK_FALSE(m.input(4));
    CHECK(m.inputs() == 0b1000'0000);
  }
  SECTION("a move passes the changes too") {
    REQUIRE(m.moveTo(Targets{1000, 0, 0, 0, 0}));  // 2.5 s, ends at 3.5 s
    CHECK(m.now() == 3'500'000);
    CHECK(m.inputs() == 0b1000'0000);
  }
}

TEST_CASE("waitFor advances to the change that makes the input true", "[sim][io]") {
  auto m = scara(parsed("at 2 input 6 on\nat 3 input 6 on\nat 0 input 1 on\nat 2.5 input 1 off\n"));
  REQUIRE(m.waitFor(6, true));
  CHECK(m.now() == 2 * kSimSecond);
  REQUIRE(m.waitFor(6, true));  // already true: no time passes
  CHECK(m.now() == 2 * kSimSecond);
  REQUIRE(m.waitFor(1, false));
  CHECK(m.now() == 2'500'000);
  CHECK(m.inputs() == 0b0010'0000);
  CHECK(m.waitFor(9, true).code == Status::Code::Fault);
}

TEST_CASE("a wait nothing will satisfy is a deadlock, not a hang", "[sim][io]") {
  SECTION("nothing is scheduled") {
    auto m = scara();
    REQUIRE(m.delay(kSimSecond));
    const auto status = m.waitFor(3, true);
    CHECK(status.code == Status::Code::Deadlock);
    CHECK(status.message == "input 3 never turns ON: no stimulus is scheduled");
    CHECK(m.now() == kSimSecond);
  }
  SECTION("the only stimulus already happened") {
    auto m = scara(parsed("at 1 input 4 on\nat 2 input 4 off\n"));
    REQUIRE(m.delay(3 * kSimSecond));
    CHECK(m.waitFor(4, true).message == "input 4 never turns ON: no stimulus is scheduled");
  }
  SECTION("an on-off pulse within one microsecond is never seen") {
    auto m = scara(parsed("at 1 input 5 on\nat 1 input 5 off\n"));
    const auto status = m.waitFor(5, true);
    CHECK(status.code == Status::Code::Deadlock);
    CHECK(status.message == "input 5 never turns ON: no scheduled stimulus leaves it ON");
    CHECK(m.now() == 0);
  }
  SECTION("waiting for OFF") {
    auto m = scara(parsed("at 0 input 2 on\n"));
    CHECK(m.waitFor(2, false).message == "input 2 never turns OFF: no stimulus is scheduled");
  }
}

TEST_CASE("a reactive rule answers an output after its delay", "[sim][rules]") {
  auto m = scara(parsed("when output 1 on then input 2 on after 0.5\n"));
  REQUIRE(m.delay(kSimSecond));
  REQUIRE(m.setOutput(1, true));
  CHECK_FALSE(m.input(2));
  REQUIRE(m.waitFor(2, true));
  CHECK(m.now() == 1'500'000);
  CHECK(m.input(2));
}

TEST_CASE("rules fire only when the output really changes", "[sim][rules]") {
  auto m =
      scara(parsed("when output 1 on then input 3 on\n"
                   "when output 1 off then input 3 off\n"
                   "when output 1 on then input 7 on after 1\n"));
  REQUIRE(m.setOutput(1, true));
  CHECK(m.inputs() == 0b0000'0100);  // no delay: at once
  REQUIRE(m.delay(kSimSecond));
  CHECK(m.inputs() == 0b0100'0100);
  REQUIRE(m.setOutput(1, false));
  CHECK(m.inputs() == 0b0100'0000);
  REQUIRE(m.setOutput(1, false));  // already OFF: nothing fires
  REQUIRE(m.setOutput(7, true));   // no rule for output 7
  CHECK(m.inputs() == 0b0100'0000);
  CHECK(m.waitFor(3, true).code == Status::Code::Deadlock);
}

TEST_CASE("changes due together apply in scheduling order", "[sim][rules]") {
  // Timed first in file order (input 1: on then off = off), then the rule's
  // change scheduled later for the same time (input 2: off then on = on).
  auto m =
      scara(parsed("at 1 input 1 on\nat 1 input 1 off\n"
                   "at 1 input 2 off\n"
                   "when output 5 on then input 2 on after 0.5\n"));
  REQUIRE(m.delay(500'000));
  REQUIRE(m.setOutput(5, true));
  REQUIRE(m.waitFor(2, true));
  CHECK(m.now() == kSimSecond);
  CHECK(m.inputs() == 0b10);
}

TEST_CASE("many reactive changes keep their order as the schedule grows", "[sim][rules]") {
  auto m =
      scara(parsed("when output 1 on then input 1 on after 0.001\n"
                   "when output 1 off then input 1 off after 0.001\n"));
  for (int i = 0; i < 1000; ++i) {
    REQUIRE(m.setOutput(1, i % 2 == 0));
    REQUIRE(m.delay(500));
  }
  // The last change (output 1 OFF at 999 * 500 us) lands at 500.5 ms.
  REQUIRE(m.waitFor(1, false));
  CHECK(m.now() == 500'500);
  CHECK(m.waitFor(1, true).code == Status::Code::Deadlock);
}

TEST_CASE("window and view accumulate", "[sim][camera]") {
  auto m = scara();
  m.window(10, -20, 30);
  m.window(5, 5, 5);
  CHECK(m.windowShift() == rs::runtime::CameraTriple{15, -15, 35});
  m.view(350, 90, 0);
  m.view(20, -100, -10);
  CHECK(m.viewRotation() == rs::runtime::CameraTriple{10, 350, 350});
  CHECK(m.now() == 0);
}

TEST_CASE("hand-built stimuli with bad lines are ignored, not trusted", "[sim][io]") {
  Stimuli stimuli;
  stimuli.changes = {InputChange{0, 0, true}, InputChange{0, 9, true}, InputChange{0, 3, true}};
  stimuli.rules = {{1, true, 12, true, -5}};
  auto m = scara(stimuli);
  CHECK(m.inputs() == 0b100);
  REQUIRE(m.setOutput(1, true));
  CHECK(m.inputs() == 0b100);
}
