// The cell's one clock (runtime/cell/scheduler.h): events in (time,
// sequence) order, delta cycles at one instant, a flood stopped; and a
// robot's program run with its machine waiting on the scheduler (every
// move, DELAY and WAITFOR answers "not yet" and the scheduler wakes the
// robot) ends exactly where the same program run straight through does.
#include <catch2/catch.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "../render/render_test_util.h"
#include "compiler/stimuli/stimuli.h"
#include "runtime/cell/scheduler.h"
#include "runtime/run/rig.h"
#include "vm/interpreter.h"

namespace cellclocktest {

using rs::runtime::CellEvent;
using rs::runtime::CellProcess;
using rs::runtime::Scheduler;
using rs::vm::Micros;

// Writes down every wake: "name@time/tag".
struct Recorder final : CellProcess {
  std::string label;
  std::vector<std::string>* log;
  Recorder(std::string l, std::vector<std::string>& out) : label(std::move(l)), log(&out) {}
  void wake(const CellEvent& e, Scheduler&) override {
    log->push_back(label + "@" + std::to_string(e.at) + "/" + std::to_string(e.tag));
  }
  std::string name() const override { return label; }
};

// A signal written in evaluate, committed in update (the delta-cycle
// discipline), and a reader that copies what it sees into its own signal.
struct Signal final : CellProcess {
  bool value = false, next = false;
  std::vector<std::uint32_t> readers;
  void wake(const CellEvent& e, Scheduler&) override { next = e.tag != 0; }
  bool update(Scheduler& clock) override {
    if (next == value) return false;
    value = next;
    for (std::uint32_t r : readers) clock.schedule(clock.now(), r);
    return true;
  }
  std::string name() const override { return "signal"; }
};
struct Copier final : CellProcess {
  const Signal* from;
  std::uint32_t to;
  bool invert;
  Copier(const Signal& f, std::uint32_t t, bool inv) : from(&f), to(t), invert(inv) {}
  void wake(const CellEvent&, Scheduler& clock) override { clock.schedule(clock.now(), to, (from->value != invert) ? 1 : 0); }
  std::string name() const override { return invert ? "wire NOT" : "wire"; }
};

// A line, a DELAY, a WAITFOR the stimulus ends at 7.5 s, an output, a move.
const char* const kLineDelayWait =
    "        MOVES DIAG\n"
    "        DELAY 1.5\n"
    "        WAITFOR 3 ON\n"
    "        OUTSIG 2 ON\n"
    "        MOVETO 0 0 0 0\n"
    "        END\n"
    "POINTS\n"
    "DIAG 40 16 0 0\n";

}  // namespace cellclocktest

using namespace cellclocktest;

TEST_CASE("the cell's clock runs events by time, then by the order they were scheduled", "[cell]") {
  std::vector<std::string> log;
  Recorder a("a", log), b("b", log);
  Scheduler clock;
  const std::uint32_t ia = clock.add(a), ib = clock.add(b);
  REQUIRE(clock.schedule(300, ib, 1));
  REQUIRE(clock.schedule(100, ib, 2));
  REQUIRE(clock.schedule(300, ia, 3));  // same time as b's first: scheduled later, runs later
  REQUIRE(clock.schedule(100, ia, 4));
  REQUIRE(clock.nextTime() == Micros{100});
  REQUIRE(clock.advanceTo(200));
  CHECK(clock.now() == 200);
  CHECK(log == std::vector<std::string>{"b@100/2", "a@100/4"});
  CHECK_FALSE(clock.schedule(150, ia));  // the past is refused
  REQUIRE(clock.advanceTo(1000));
  CHECK(log == std::vector<std::string>{"b@100/2", "a@100/4", "b@300/1", "a@300/3"});
  CHECK(clock.now() == 1000);
  CHECK(clock.idle());
  // The same schedule restored replays the same order.
  Scheduler::State empty = clock.state();
  REQUIRE(clock.schedule(2000, ia, 5));
  const Scheduler::State one = clock.state();
  clock.restore(empty);
  CHECK(clock.idle());
  clock.restore(one);
  REQUIRE(clock.advanceTo(3000));
  CHECK(log.back() == "a@2000/5");
}

TEST_CASE("what a process reads at an instant does not depend on the order the processes are visited", "[cell]") {
  // Two readers of one signal, each copying what it reads into a signal of
  // its own, registered in both orders: with delta cycles both read the
  // committed value, never the other's write of the same delta.
  for (const bool swapped : {false, true}) {
    INFO("readers registered " << (swapped ? "second first" : "first first"));
    Signal in, outA, outB;
    Scheduler clock;
    const std::uint32_t iin = clock.add(in), ia = clock.add(outA), ib = clock.add(outB);
    Copier toA(in, ia, false), toB(outA, ib, false);  // B reads A's output: one delta later
    const std::uint32_t first = clock.add(swapped ? static_cast<CellProcess&>(toB) : toA);
    const std::uint32_t second = clock.add(swapped ? static_cast<CellProcess&>(toA) : toB);
    (swapped ? outA : in).readers.push_back(first);
    (swapped ? in : outA).readers.push_back(second);
    REQUIRE(clock.schedule(500, iin, 1));
    REQUIRE(clock.advanceTo(500));
    CHECK(in.value);
    CHECK(outA.value);
    CHECK(outB.value);
    // in, the copy to A, A, the copy to B, B: five deltas in either order.
    CHECK(clock.lastDeltas() == 5);
  }
}

TEST_CASE("a loop of zero-delay changes at one instant is stopped with an error naming what loops", "[cell]") {
  Signal s;
  Scheduler clock;
  const std::uint32_t is = clock.add(s);
  Copier inverter(s, is, true);  // the signal drives itself, inverted, with no delay
  s.readers.push_back(clock.add(inverter));
  REQUIRE(clock.schedule(1'000'000, is, 1));
  const rs::vm::Status st = clock.advanceTo(2'000'000);
  REQUIRE_FALSE(st);
  CHECK(st.message.find("at 1.000 s") != std::string::npos);
  CHECK(st.message.find("signal, wire NOT keep changing each other") != std::string::npos);
  CHECK(clock.now() == 1'000'000);
}

namespace cellclocktest {

// The robot as a process of the cell: woken, it runs its program until a
// call says "not yet", and asks to be woken when that wait ends.
struct Robot final : CellProcess {
  rs::vm::Interpreter* vm = nullptr;
  std::uint32_t id = 0;
  rs::vm::RunOutcome last;
  int wakes = 0;
  void wake(const CellEvent&, Scheduler& clock) override {
    ++wakes;
    last = vm->run({});
    if (last.waiting && last.wakeAt != rs::vm::Status::kNever) clock.schedule(last.wakeAt, id);
  }
  std::string name() const override { return "robot"; }
};

struct Ending {
  Micros clock = 0;
  std::vector<std::int32_t> motors;
  std::uint64_t steps = 0, knots = 0, takes = 0;
  rs::vm::IoMask outputs = 0, inputs = 0;
  rs::vm::RunOutcome outcome;
};

// `alone`: the machine finishes a move or a DELAY at once when nothing
// else in the cell is due by its end (SimMachine::finishAlone); `other`, a
// time at which a process of the cell other than the robot wakes.
Ending runOnRig(const std::string& program, bool onScheduler, int* wakes = nullptr, bool alone = false,
                std::optional<Micros> other = std::nullopt, std::vector<std::string>* otherLog = nullptr) {
  auto cell = std::make_shared<const rs::workcell::Workcell>(rendertest::cell("gantry-cell"));
  const rs::vm::Image image = rendertest::compileText(program, *cell);
  auto stimuli = rs::stimuli::parseStimuli("at 7.5 input 3 on\n", "cell.stim");
  REQUIRE(stimuli.ok());
  rs::runtime::Rig rig(cell, image.motors, std::move(stimuli).value(), rs::runtime::CollisionMode::Warn);
  rs::vm::Interpreter vm(image, rig.machine());
  Ending e;
  if (!onScheduler) {
    e.outcome = vm.run({});
  } else {
    rig.sim()->waitOnScheduler(true);
    rig.sim()->finishAlone(alone);
    // The rig's cell clock is the one the machine runs on; the test drives it.
    Scheduler& clock = rig.running().clock();
    Robot robot;
    robot.vm = &vm;
    robot.id = clock.add(robot);
    std::vector<std::string> ignored;
    Recorder recorder("other", otherLog ? *otherLog : ignored);
    const std::uint32_t otherId = clock.add(recorder);
    REQUIRE(clock.schedule(0, robot.id));
    if (other) REQUIRE(clock.schedule(*other, otherId));
    while (!clock.idle()) REQUIRE(clock.advanceTo(*clock.nextTime()));
    e.outcome = robot.last;
    if (wakes) *wakes = robot.wakes;
  }
  e.clock = rig.clock();
  e.motors.assign(rig.motors().begin(), rig.motors().end());
  e.steps = vm.steps(), e.knots = rig.machine().knots();
  e.takes = rig.world()->takeCount();
  e.outputs = rig.machine().outputs(), e.inputs = rig.machine().inputs();
  return e;
}

}  // namespace cellclocktest

TEST_CASE("a program whose waits say not yet, woken by the cell's scheduler, ends where it ends run straight through",
          "[cell]") {
  const std::string program = kLineDelayWait;
  const Ending straight = runOnRig(program, false);
  int wakes = 0;
  const Ending woken = runOnRig(program, true, &wakes);
  REQUIRE(straight.outcome.ok());
  REQUIRE(woken.outcome.ok());
  CHECK_FALSE(woken.outcome.waiting);
  // The WAITFOR ends at the stimulus, 7.5 s, after the line and the delay.
  CHECK(straight.clock > 7'500'000);
  CHECK(woken.clock == straight.clock);
  CHECK(woken.motors == straight.motors);
  CHECK(woken.steps == straight.steps);
  CHECK(woken.knots == straight.knots);
  CHECK(woken.takes == straight.takes);
  CHECK(woken.outputs == straight.outputs);
  CHECK(woken.inputs == straight.inputs);
  // Once at the start, once per knot of the line, the delay, the wait, the last move.
  CHECK(wakes == 1 + static_cast<int>(straight.knots) + 3);
}

TEST_CASE("a WAITFOR nothing will satisfy leaves the robot waiting on the scheduler, which decides it is stuck",
          "[cell]") {
  int wakes = 0;
  const Ending e = runOnRig("        WAITFOR 5 ON\n        END\n", true, &wakes);
  CHECK(e.outcome.waiting);
  CHECK(e.outcome.wakeAt == rs::vm::Status::kNever);
  CHECK(e.outcome.index == 0);
  CHECK(e.steps == 0);
  CHECK(wakes == 1);
  // Run straight through, the machine itself says so.
  const Ending straight = runOnRig("        WAITFOR 5 ON\n        END\n", false);
  CHECK(straight.outcome.reason == rs::vm::StopReason::Deadlock);
}

TEST_CASE("the cell's clock: a cancelled event does not happen, and cancelling one that ran is refused", "[cell]") {
  std::vector<std::string> log;
  Recorder a("a", log);
  Scheduler clock;
  const std::uint32_t ia = clock.add(a);
  REQUIRE(clock.schedule(100, ia, 1));
  const std::uint64_t first = clock.lastSeq();
  REQUIRE(clock.schedule(100, ia, 2));
  const std::uint64_t second = clock.lastSeq();
  REQUIRE(clock.schedule(200, ia, 3));
  CHECK(first != second);
  CHECK(clock.cancel(100, first));
  CHECK_FALSE(clock.cancel(100, first));   // gone already
  CHECK_FALSE(clock.cancel(200, second));  // no such event at that time
  REQUIRE(clock.advanceTo(150));
  CHECK(log == std::vector<std::string>{"a@100/2"});
  CHECK_FALSE(clock.cancel(100, second));  // it ran
  REQUIRE(clock.advanceTo(300));
  CHECK(log == std::vector<std::string>{"a@100/2", "a@200/3"});
}

namespace cellclocktest {
// Counts its wakes and updates.
struct Counter final : CellProcess {
  int wakes = 0, updates = 0;
  void wake(const CellEvent&, Scheduler&) override { ++wakes; }
  bool update(Scheduler&) override { return ++updates, false; }
  std::string name() const override { return "counter"; }
};
}  // namespace cellclocktest

TEST_CASE("the cell's clock updates the processes a delta woke, once each, and no other", "[cell]") {
  Counter a, b;
  Scheduler clock;
  const std::uint32_t ia = clock.add(a);
  clock.add(b);
  REQUIRE(clock.schedule(100, ia));
  REQUIRE(clock.schedule(100, ia));  // woken twice in the delta: updated once
  REQUIRE(clock.schedule(200, ia));
  REQUIRE(clock.advanceTo(1000));
  CHECK(a.wakes == 3);
  CHECK(a.updates == 2);  // once at 100, once at 200
  CHECK(b.wakes == 0);
  CHECK(b.updates == 0);  // never woken: nothing of its to commit
}

TEST_CASE("a robot alone in its cell finishes a move or a DELAY at once, unless something else in the cell is due "
          "before its end", "[cell]") {
  const std::string program = kLineDelayWait;
  const Ending straight = runOnRig(program, false);
  REQUIRE(straight.outcome.ok());
  REQUIRE(straight.knots > 1);
  int woken = 0, alone = 0;
  const Ending waited = runOnRig(program, true, &woken);
  const Ending finished = runOnRig(program, true, &alone, true);
  REQUIRE(finished.outcome.ok());
  CHECK(finished.clock == straight.clock);
  CHECK(finished.motors == straight.motors);
  CHECK(finished.steps == straight.steps);
  CHECK(finished.knots == straight.knots);
  CHECK(finished.outputs == straight.outputs);
  CHECK(finished.inputs == straight.inputs);
  // The line's knots and the WAITFOR still wait; the DELAY and the last
  // move do not: two wakes fewer.
  CHECK(alone == woken - 2);
  CHECK(alone == 1 + static_cast<int>(straight.knots) + 1);

  // Something else due during the DELAY (after the line): the DELAY waits,
  // and the other process wakes at its own time with the clock there.
  const Micros lineEnd = [&] {
    const Ending line = runOnRig("        MOVES DIAG\n        END\nPOINTS\nDIAG 40 16 0 0\n", false);
    return line.clock;
  }();
  std::vector<std::string> log;
  int wakesWithOther = 0;
  const Micros during = lineEnd + 700'000;
  const Ending shared = runOnRig(program, true, &wakesWithOther, true, during, &log);
  REQUIRE(shared.outcome.ok());
  CHECK(shared.clock == straight.clock);
  CHECK(shared.motors == straight.motors);
  CHECK(log == std::vector<std::string>{"other@" + std::to_string(during) + "/0"});
  CHECK(wakesWithOther == alone + 1);  // the DELAY's wake
}
