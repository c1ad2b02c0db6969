// The semantics of the paper's 20 instructions, run on the simulated machine (the
// straight-line moves, which need a workcell: tests/runtime/test_straight_line.cpp).
//
// Programs are compiled from source and run by the interpreter on a
// SimMachine. Expected times are worked out by hand in the comments: a
// motor moving |delta| units at `speed` units/s takes
// ceil(|delta| * 1e6 / speed) microseconds, and a motion instruction lasts
// as long as its slowest motor. Default motors (stdlib/default_robot.cpp):
//   E speed 400, range -1000..1000    D speed 400, range -550..550
//   C speed 300, range -350..350      B speed 500, range -700..700
//   A speed 200, range 0..120
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "runtime/run/run.h"
#include "compiler/stimuli/stimuli.h"
#include "stdlib/default_robot.h"
#include "vm/interpreter.h"
#include "vm/verify.h"

namespace {

using rs::compiler::Target;
using rs::stimuli::InputChange;
using rs::stimuli::ReactiveRule;
using rs::runtime::SimMachine;
using rs::stimuli::Stimuli;
using rs::vm::Micros;
using rs::vm::RunLimits;
using rs::vm::StopReason;
using Values = std::vector<std::int32_t>;

constexpr Micros kSecond = 1'000'000;

Target rhinoTarget() { return {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth}; }

// Records every executed instruction: its index, the clock and the motors
// right after it ran.
class Recorder final : public rs::vm::StepObserver {
 public:
  bool afterStep(const rs::vm::Interpreter& vm, std::uint32_t index) override {
    indices.push_back(index);
    times.push_back(vm.machine().now());
    const auto p = vm.machine().positions();
    positions.emplace_back(p.begin(), p.end());
    return false;
  }
  std::vector<std::uint32_t> indices;
  std::vector<Micros> times;
  std::vector<Values> positions;
};

struct Run {
  rs::vm::Image image;
  std::unique_ptr<rs::runtime::Run> run;
  const SimMachine* machine = nullptr;  // the run's
  rs::vm::RunOutcome outcome;
  Values vars;
  Recorder trace;

  std::int32_t var(std::string_view name) const {
    const auto it = std::find(image.variables.begin(), image.variables.end(), name);
    REQUIRE(it != image.variables.end());
    return vars[static_cast<std::size_t>(it - image.variables.begin())];
  }
  Values positions() const { return {machine->positions().begin(), machine->positions().end()}; }
  Micros now() const { return machine->now(); }
};

rs::vm::Image compileFor(const std::string& text, const Target& target = rhinoTarget()) {
  const rs::diag::SourceFile source("vm.rsp", text);
  const rs::compiler::CompileResult r = rs::compiler::compile(source, target);
  INFO("program:\n" << text);
  for (const auto& d : r.diagnostics) INFO(d.pos.line << ':' << d.pos.col << ": " << d.message);
  REQUIRE(r.ok());
  return *r.image;
}

Run runImage(rs::vm::Image image, Stimuli stimuli = {}, RunLimits limits = {}) {
  Run r;
  r.image = std::move(image);
  REQUIRE(rs::vm::verify(r.image).message.empty());
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(r.image);
  spec.stimuli = std::move(stimuli);
  spec.limits = limits;
  r.run = std::make_unique<rs::runtime::Run>(std::move(spec));
  r.machine = r.run->rig().sim();
  r.run->observe(r.trace);
  r.outcome = r.run->runToEnd();
  const auto vars = r.run->interpreter().variables();
  r.vars.assign(vars.begin(), vars.end());
  return r;
}

Run run(const std::string& text, Stimuli stimuli = {}, RunLimits limits = {}, const Target& target = rhinoTarget()) {
  return runImage(compileFor(text, target), std::move(stimuli), limits);
}

void requireEnded(const Run& r) {
  INFO("stopped: " << r.outcome.message);
  REQUIRE(r.outcome.reason == StopReason::End);
  CHECK(r.outcome.message.empty());
}

}  // namespace

TEST_CASE("MOVE moves every motor by a relative amount, the slowest motor sets the time", "[vm]") {
  const Run r = run("MOVE 100 -50 30 7 3\nMOVE 100 -50 30 7 3\nEND\n");
  requireEnded(r);
  CHECK(r.positions() == Values{200, -100, 60, 14, 6});
  // E 100/400 = 250000 us, D 50/400 = 125000, C 30/300 = 100000,
  // B 7/500 = 14000, A 3/200 = 15000: each MOVE takes 250000 us.
  CHECK(r.trace.times == std::vector<Micros>{250'000, 500'000, 500'000});
  CHECK(r.trace.positions[0] == Values{100, -50, 30, 7, 3});
  CHECK(r.outcome.steps == 3);
}

TEST_CASE("motion time is rounded up to the next microsecond", "[vm]") {
  // C: 1 unit at 300 u/s = 3333.33 us -> 3334 us, each way.
  const Run r = run("MOVE 0 0 1 0 0\nMOVE 0 0 -1 0 0\n");
  requireEnded(r);
  CHECK(r.trace.times == std::vector<Micros>{3334, 6668});
  CHECK(r.positions() == Values{0, 0, 0, 0, 0});

  // A custom table: X at 10 u/s, Y at 3 u/s. X 1 unit = 100000 us,
  // Y 1 unit = 333333.3 -> 333334 us.
  const Target two{"two",
                   {{'X', rs::vm::JointKind::Revolute, 1.0, -10, 10, 10}, {'Y', rs::vm::JointKind::Prismatic, 1.0, 0, 5, 3}},
                   rs::vm::kDefaultCallDepth};
  const Run t = run("MOVE 1 1\nMOVETO 10 1\n", {}, {}, two);
  requireEnded(t);
  // Second move: X 9 units = 900000 us, Y stays.
  CHECK(t.trace.times == std::vector<Micros>{333'334, 1'233'334});
  CHECK(t.positions() == Values{10, 1});
}

TEST_CASE("MOVETO moves to absolute positions", "[vm]") {
  const Run r = run("MOVETO 1000 0 0 0 0\nMOVETO 1000 550 0 0 0\nEND\n");
  requireEnded(r);
  // E 1000/400 = 2.5 s; then only D moves, 550/400 = 1.375 s.
  CHECK(r.trace.times == std::vector<Micros>{2'500'000, 3'875'000, 3'875'000});
  CHECK(r.positions() == Values{1000, 550, 0, 0, 0});
}

TEST_CASE("MOVEP moves to a taught point", "[vm]") {
  const Run r = run("MOVEP P1\nMOVEP p2\nEND\nPOINTS\nP1 100 200 -300 400 60\nP2 100 200 -300 400 0\n");
  requireEnded(r);
  // P1: E 0.25 s, D 0.5 s, C 1.0 s, B 0.8 s, A 0.3 s -> 1.0 s.
  // P2: only A moves, 60/200 = 0.3 s.
  CHECK(r.trace.times == std::vector<Micros>{1'000'000, 1'300'000, 1'300'000});
  CHECK(r.trace.positions[0] == Values{100, 200, -300, 400, 60});
  CHECK(r.positions() == Values{100, 200, -300, 400, 0});
}

TEST_CASE("GOTO jumps to an instruction number or a label", "[vm]") {
  const Run r = run("SET N 1\nGOTO 4\nSET N 2\n; comment lines do not count\n\nSET M 3\nGOTO done\nSET M 4\ndone: END\n");
  requireEnded(r);
  CHECK(r.var("N") == 1);
  CHECK(r.var("M") == 3);
  CHECK(r.trace.indices == std::vector<std::uint32_t>{0, 1, 3, 4, 6});
  CHECK(r.now() == 0);  // jumps take no time
}

TEST_CASE("OUTSIG switches outputs and takes no time", "[vm]") {
  const Run r = run("OUTSIG 1 ON\nOUTSIG 8 ON\nOUTSIG 3 ON\nOUTSIG 1 OFF\nOUTSIG 3 off\nEND\n");
  requireEnded(r);
  CHECK(r.machine->outputs() == 0x80);
  CHECK(r.now() == 0);
}

TEST_CASE("JMPIN jumps only when the input is in the given state", "[vm]") {
  const std::string onProgram = "JMPIN 3 ON yes\nSET R 1\nEND\nyes: SET R 2\nEND\n";
  const std::string offProgram = "JMPIN 3 OFF yes\nSET R 1\nEND\nyes: SET R 2\nEND\n";
  const Stimuli input3On{{InputChange{0, 3, true}}, {}};
  SECTION("ON, input on: jumps") { CHECK(run(onProgram, input3On).var("R") == 2); }
  SECTION("ON, input off: falls through") { CHECK(run(onProgram).var("R") == 1); }
  SECTION("OFF, input off: jumps") { CHECK(run(offProgram).var("R") == 2); }
  SECTION("OFF, input on: falls through") { CHECK(run(offProgram, input3On).var("R") == 1); }
  SECTION("another input does not count") {
    CHECK(run(onProgram, Stimuli{{InputChange{0, 4, true}}, {}}).var("R") == 1);
  }
  SECTION("a change reads from its time on, not before") {
    const Stimuli at1{{InputChange{kSecond, 3, true}}, {}};
    CHECK(run("DELAY 0.999\n" + onProgram, at1).var("R") == 1);
    CHECK(run("DELAY 1\n" + onProgram, at1).var("R") == 2);
  }
}

TEST_CASE("JMPVAR compares with <, > and =", "[vm]") {
  struct Case {
    const char* compare;
    int value;
    bool taken;
  };
  // N is 5.
  const Case cases[] = {{"<", 6, true},  {"<", 5, false}, {"<", 4, false}, {">", 4, true},  {">", 5, false},
                        {">", 6, false}, {"=", 5, true},  {"=", 4, false}, {"=", 6, false}, {"<", -6, false},
                        {">", -6, true}};
  for (const Case& c : cases) {
    const std::string text = std::string("SET N 5\nJMPVAR N ") + c.compare + " " + std::to_string(c.value) +
                             " yes\nSET R 1\nEND\nyes: SET R 2\nEND\n";
    INFO(text);
    const Run r = run(text);
    requireEnded(r);
    CHECK(r.var("R") == (c.taken ? 2 : 1));
  }
}

TEST_CASE("JMPVAR compares the whole 32-bit range without overflow", "[vm]") {
  // The loop compares by the sign of the difference: at the ends of the
  // range a subtraction in 32 bits would overflow and give the wrong sign.
  struct Case {
    const char* n;
    const char* compare;
    const char* value;
    bool taken;
  };
  const Case cases[] = {{"2147483647", ">", "-2147483648", true},  {"2147483647", "<", "-2147483648", false},
                        {"-2147483648", "<", "2147483647", true},  {"-2147483648", ">", "2147483647", false},
                        {"-2147483648", "=", "2147483647", false}, {"-2147483648", "=", "-2147483648", true},
                        {"2147483647", "=", "2147483647", true},   {"2147483647", "<", "2147483647", false}};
  for (const Case& c : cases) {
    const std::string text = std::string("SET N ") + c.n + "\nJMPVAR N " + c.compare + " " + c.value +
                             " yes\nSET R 1\nEND\nyes: SET R 2\nEND\n";
    INFO(text);
    const Run r = run(text);
    requireEnded(r);
    CHECK(r.var("R") == (c.taken ? 2 : 1));
  }
}

TEST_CASE("a counted loop with SET, ADD and JMPVAR", "[vm]") {
  const Run r = run("SET N 0\nloop: ADD N 1\nJMPVAR N < 10 loop\nEND\n");
  requireEnded(r);
  CHECK(r.var("N") == 10);
  CHECK(r.outcome.steps == 1 + 10 * 2 + 1);
}

TEST_CASE("GOSUB and RETURN nest", "[vm]") {
  const Run r = run(
      "GOSUB a\n"     // 1
      "SET Z 3\n"     // 2
      "END\n"         // 3
      "a: SET X 1\n"  // 4
      "GOSUB b\n"     // 5
      "ADD X 10\n"    // 6
      "RETURN\n"      // 7
      "b: SET Y 2\n"  // 8
      "RETURN\n");    // 9
  requireEnded(r);
  CHECK(r.trace.indices == std::vector<std::uint32_t>{0, 3, 4, 7, 8, 5, 6, 1, 2});
  CHECK(r.var("X") == 11);
  CHECK(r.var("Y") == 2);
  CHECK(r.var("Z") == 3);
}

TEST_CASE("call stack overflow is a runtime error naming the GOSUB", "[vm]") {
  SECTION("default depth 64") {
    const Run r = run("sub: GOSUB sub\n");
    CHECK(r.outcome.reason == StopReason::RuntimeError);
    CHECK(r.outcome.message == "call stack overflow: more than 64 nested GOSUBs");
    CHECK(r.outcome.index == 0);
    CHECK(r.outcome.steps == 65);  // 64 calls succeed, the 65th fails
  }
  SECTION("a smaller limit from the target") {
    Target t = rhinoTarget();
    t.callDepthLimit = 3;
    const rs::vm::Image image = compileFor("SET N 0\nsub: ADD N 1\nGOSUB sub\n", t);
    CHECK(image.callDepthLimit == 3);
    const Run r = runImage(image);
    CHECK(r.outcome.reason == StopReason::RuntimeError);
    CHECK(r.outcome.message == "call stack overflow: more than 3 nested GOSUBs");
    CHECK(r.outcome.index == 2);
    CHECK(r.image.lines[r.outcome.index] == 3);
    // SET, then (ADD, GOSUB) three times, then ADD and the failing GOSUB.
    CHECK(r.outcome.steps == 9);
    CHECK(r.var("N") == 4);
  }
}

TEST_CASE("RETURN without a GOSUB at run time", "[vm]") {
  // The compiler refuses such a program, so the image is built by hand.
  rs::vm::Image image;
  image.sourceName = "hand.rsp";
  image.motors = rs::stdlib::rhinoScaraMotors();
  image.code = {{rs::vm::Op::OutSig, 2, 1, 0, 0}, {rs::vm::Op::Return, 0, 0, 0, 0}};
  image.lines = {1, 2};
  image.columns = {1, 3};
  const Run r = runImage(image);
  CHECK(r.outcome.reason == StopReason::RuntimeError);
  CHECK(r.outcome.message == "RETURN without a GOSUB");
  CHECK(r.outcome.index == 1);
  CHECK(r.outcome.steps == 2);
  CHECK(r.machine->outputs() == 0x02);
}

TEST_CASE("WAITFOR returns at once or when a stimulus sets the input", "[vm]") {
  SECTION("already in the state: no time passes") {
    const Run r = run("WAITFOR 3 OFF\nEND\n");
    requireEnded(r);
    CHECK(r.now() == 0);
  }
  SECTION("a timed stimulus") {
    const Run r = run("WAITFOR 3 ON\nWAITFOR 3 OFF\nEND\n",
                      Stimuli{{InputChange{1'500'000, 3, true}, InputChange{4 * kSecond, 3, false}}, {}});
    requireEnded(r);
    CHECK(r.trace.times == std::vector<Micros>{1'500'000, 4'000'000, 4'000'000});
  }
  SECTION("a reactive rule: input 2 follows output 1 after 0.5 s") {
    const Run r = run("DELAY 1\nOUTSIG 1 ON\nWAITFOR 2 ON\nEND\n",
                      Stimuli{{}, {ReactiveRule{1, true, 2, true, 500'000}}});
    requireEnded(r);
    CHECK(r.now() == 1'500'000);
    CHECK(r.machine->inputs() == 0x02);
    CHECK(r.machine->outputs() == 0x01);
  }
}

TEST_CASE("a WAITFOR nothing can satisfy is a deadlock naming the instruction", "[vm]") {
  SECTION("no stimulus at all") {
    const Run r = run("SET N 1\nWAITFOR 2 ON\nEND\n");
    CHECK(r.outcome.reason == StopReason::Deadlock);
    CHECK(r.outcome.message == "input 2 never turns ON: no stimulus is scheduled");
    CHECK(r.outcome.index == 1);
    CHECK(r.image.lines[r.outcome.index] == 2);
    CHECK(r.outcome.steps == 2);
  }
  SECTION("only stimuli that leave it OFF") {
    const Run r = run("WAITFOR 2 ON\nEND\n", Stimuli{{InputChange{kSecond, 2, false}}, {}});
    CHECK(r.outcome.reason == StopReason::Deadlock);
    CHECK(r.outcome.message == "input 2 never turns ON: no scheduled stimulus leaves it ON");
  }
  SECTION("a rule whose output never changes") {
    const Run r = run("WAITFOR 2 ON\nOUTSIG 1 ON\nEND\n", Stimuli{{}, {ReactiveRule{1, true, 2, true, 0}}});
    CHECK(r.outcome.reason == StopReason::Deadlock);
    CHECK(r.outcome.index == 0);
  }
}

TEST_CASE("ADD adds, and overflow is a runtime error", "[vm]") {
  SECTION("adds and subtracts") {
    const Run r = run("SET N 5\nADD N -7\nADD N 3\nADD M 4\nEND\n");
    requireEnded(r);
    CHECK(r.var("N") == 1);
    CHECK(r.var("M") == 4);  // variables start at 0
  }
  SECTION("above the 32-bit range") {
    const Run r = run("SET N 2147483647\nADD N 1\nEND\n");
    CHECK(r.outcome.reason == StopReason::RuntimeError);
    CHECK(r.outcome.message == "ADD overflows variable N (values are 32-bit)");
    CHECK(r.outcome.index == 1);
    CHECK(r.outcome.steps == 2);
  }
  SECTION("below the 32-bit range") {
    const Run r = run("SET N -2147483648\nADD N -1\nEND\n");
    CHECK(r.outcome.reason == StopReason::RuntimeError);
    CHECK(r.outcome.message == "ADD overflows variable N (values are 32-bit)");
  }
}

// Regression (a bug these tests found, fixed since): the failing ADD leaves the wrapped-around result in the
// variable (__builtin_add_overflow stores it), so the summary after the
// error shows N=-2147483648, a value the program never computed. A failed
// MOVE, by contrast, leaves the motors where they were.
TEST_CASE("a failed ADD leaves its variable unchanged", "[vm]") {
  const Run r = run("SET N 2147483647\nADD N 1\nEND\n");
  REQUIRE(r.outcome.reason == StopReason::RuntimeError);
  CHECK(r.var("N") == 2147483647);
}

TEST_CASE("RESET puts the motors back instantly, keeping outputs, variables and the clock", "[vm]") {
  const Run r = run("MOVETO 400 0 0 0 120\nOUTSIG 2 ON\nSET N 7\nRESET\nEND\n");
  requireEnded(r);
  // E 400/400 = 1 s, A 120/200 = 0.6 s.
  CHECK(r.trace.times == std::vector<Micros>{kSecond, kSecond, kSecond, kSecond, kSecond});
  CHECK(r.positions() == Values{0, 0, 0, 0, 0});
  CHECK(r.machine->outputs() == 0x02);
  CHECK(r.var("N") == 7);
}

TEST_CASE("WINDOW and VIEW change the camera and take no time", "[vm]") {
  const Run r = run("WINDOW 1 2 3\nWINDOW 1 2 3\nVIEW 350 0 -10\nVIEW 20 0 0\nEND\n");
  requireEnded(r);
  CHECK(r.machine->windowShift() == rs::runtime::CameraTriple{2, 4, 6});
  CHECK(r.machine->viewRotation() == rs::runtime::CameraTriple{10, 0, 350});
  CHECK(r.now() == 0);
  CHECK(r.positions() == Values{0, 0, 0, 0, 0});
}

TEST_CASE("DELAY advances the clock by exact milliseconds", "[vm]") {
  const Run r = run("DELAY 0.25\nDELAY 1.5\nDELAY 0.001\nDELAY 0\nEND\n");
  requireEnded(r);
  CHECK(r.trace.times == std::vector<Micros>{250'000, 1'750'000, 1'751'000, 1'751'000, 1'751'000});
}

TEST_CASE("HRDHOME drives every motor to 0 at motor speed", "[vm]") {
  const Run r = run("MOVETO 400 -400 300 -500 120\nHRDHOME\nEND\n");
  requireEnded(r);
  // Out: E, D, C, B 1 s each, A 0.6 s; back the same.
  CHECK(r.trace.times == std::vector<Micros>{kSecond, 2 * kSecond, 2 * kSecond});
  CHECK(r.positions() == Values{0, 0, 0, 0, 0});
}

TEST_CASE("SETSOFT sets the soft home without moving, GOSOFT goes there", "[vm]") {
  const Run r = run("GOSOFT\nSETSOFT 400 0 -150 0 0\nGOSOFT\nMOVE 0 10 0 0 0\nGOSOFT\nEND\n");
  requireEnded(r);
  // GOSOFT before any SETSOFT: all zeros, already there. SETSOFT: no motion,
  // no time. GOSOFT: E 400/400 = 1 s, C 150/300 = 0.5 s. MOVE: D 10/400 =
  // 25000 us. GOSOFT: D back, 25000 us.
  CHECK(r.trace.times == std::vector<Micros>{0, 0, kSecond, 1'025'000, 1'050'000, 1'050'000});
  CHECK(r.trace.positions[1] == Values{0, 0, 0, 0, 0});
  CHECK(r.trace.positions[2] == Values{400, 0, -150, 0, 0});
  CHECK(r.positions() == Values{400, 0, -150, 0, 0});
}

TEST_CASE("SET assigns, variable names are case-insensitive", "[vm]") {
  const Run r = run("SET N -5\nSET n 7\nSET Other -2147483648\nEND\n");
  requireEnded(r);
  CHECK(r.image.variables == std::vector<std::string>{"N", "Other"});
  CHECK(r.var("N") == 7);
  CHECK(r.var("Other") == -2147483648);
}

TEST_CASE("END stops the run, running off the end stops it too", "[vm]") {
  SECTION("END") {
    const Run r = run("SET N 1\nEND\nSET N 2\n");
    requireEnded(r);
    CHECK(r.var("N") == 1);
    CHECK(r.outcome.steps == 2);
  }
  SECTION("off the end") {
    const Run r = run("SET N 1\nSET N 2\n");
    requireEnded(r);
    CHECK(r.var("N") == 2);
    CHECK(r.outcome.steps == 2);
  }
}

TEST_CASE("a relative MOVE that leaves the range fails at run time, naming the motor", "[vm]") {
  SECTION("E above its maximum") {
    const Run r = run("MOVE 600 0 0 0 0\nMOVE 600 0 0 0 0\nEND\n");
    CHECK(r.outcome.reason == StopReason::RuntimeError);
    CHECK(r.outcome.message == "MOVE takes motor E to 1200, outside its range -1000..1000");
    CHECK(r.outcome.index == 1);
    // The failed MOVE neither moved the motors nor took time.
    CHECK(r.positions() == Values{600, 0, 0, 0, 0});
    CHECK(r.now() == 1'500'000);
  }
  SECTION("the gripper below 0") {
    const Run r = run("MOVE 0 0 0 0 -1\n");
    CHECK(r.outcome.reason == StopReason::RuntimeError);
    CHECK(r.outcome.message == "MOVE takes motor A to -1, outside its range 0..120");
    CHECK(r.outcome.index == 0);
  }
}

TEST_CASE("the step limit stops an endless loop", "[vm]") {
  const Run r = run("SET N 0\nloop: ADD N 1\nGOTO loop\n", {}, RunLimits{10, 3600 * kSecond});
  CHECK(r.outcome.reason == StopReason::StepLimit);
  CHECK(r.outcome.message == "step limit of 10 instructions reached");
  CHECK(r.outcome.steps == 10);
  // SET, then ADD/GOTO four times, then the fifth ADD is step 10: the
  // GOTO (index 2) would have been next.
  CHECK(r.outcome.index == 2);
  CHECK(r.var("N") == 5);
}

TEST_CASE("a run of exactly the step limit finishes normally", "[vm]") {
  requireEnded(run("SET N 1\nEND\n", {}, RunLimits{2, 3600 * kSecond}));
  requireEnded(run("SET N 1\nSET N 2\n", {}, RunLimits{2, 3600 * kSecond}));
  const Run r = run("SET N 1\nSET N 2\nEND\n", {}, RunLimits{2, 3600 * kSecond});
  CHECK(r.outcome.reason == StopReason::StepLimit);
  CHECK(r.outcome.index == 2);
  const Run zero = run("END\n", {}, RunLimits{0, 3600 * kSecond});
  CHECK(zero.outcome.reason == StopReason::StepLimit);
  CHECK(zero.outcome.message == "step limit of 0 instructions reached");
  CHECK(zero.outcome.steps == 0);
}

TEST_CASE("the time limit stops a run past its simulated time", "[vm]") {
  SECTION("past the limit") {
    const Run r = run("loop: DELAY 1\nGOTO loop\n", {}, RunLimits{1000, 2'500'000});
    CHECK(r.outcome.reason == StopReason::TimeLimit);
    CHECK(r.outcome.message == "simulated time limit of 2.500 s passed (clock at 3.000 s)");
    CHECK(r.outcome.index == 0);
    CHECK(r.outcome.steps == 5);
  }
  SECTION("exactly at the limit is fine") {
    const Run r = run("DELAY 3\nEND\n", {}, RunLimits{1000, 3 * kSecond});
    requireEnded(r);
  }
  SECTION("a move counts too") {
    const Run r = run("MOVETO 1000 0 0 0 0\nEND\n", {}, RunLimits{1000, 2 * kSecond});
    CHECK(r.outcome.reason == StopReason::TimeLimit);
    CHECK(r.outcome.message == "simulated time limit of 2.000 s passed (clock at 2.500 s)");
  }
}
