// The interpreter has two ways through a program (vm/interpreter.cpp):
// with an observer or breakpoints every instruction goes through the main
// loop's hook; without, the instructions that only compute (SET, ADD,
// JMPVAR, GOTO) run in a loop of their own first. Both must end in the
// same state, outcome and machine, on every program and at every pause:
// random programs of every kind of instruction, run to the end, to a step
// limit, and in slices, each way.
#include <catch2/catch.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "runtime/run/run.h"
#include "stdlib/default_robot.h"
#include "vm/interpreter.h"

namespace {

using rs::vm::InterpreterState;
using rs::vm::RunOutcome;

// Watches without acting: its presence alone sends the run through the
// main loop's hook.
class Watching final : public rs::vm::StepObserver {
 public:
  bool afterStep(const rs::vm::Interpreter&, std::uint32_t) override {
    ++steps;
    return false;
  }
  std::uint64_t steps = 0;
};

// A program of `length` (at least 5) random instructions over three
// variables, with the labels l0..l4 spread over it: counted loops, jumps
// each way, ADDs that can overflow, calls of a subroutine after the END,
// moves, outputs and delays.
std::string randomProgram(std::uint32_t& seed, int length) {
  auto next = [&seed](int n) { return static_cast<int>((seed = seed * 1664525u + 1013904223u) >> 8) % n; };
  const char* vars[] = {"A", "B", "C"};
  const char* cmps[] = {"<", ">", "="};
  const auto label = [&] { return " l" + std::to_string(next(5)); };
  std::string text;
  for (int i = 0, placed = 0; i < length; ++i) {
    if (placed < 5 && i == placed * length / 5) text += "l" + std::to_string(placed++) + ": ";
    const std::string v = vars[next(3)];
    switch (next(12)) {
      case 0: text += "SET " + v + " " + std::to_string(next(21) - 10) + "\n"; break;
      case 1:
      case 2: text += "ADD " + v + " " + std::to_string(next(7) - 3) + "\n"; break;
      case 3: text += "ADD " + v + " " + (next(2) ? "2147483647" : "-2147483648") + "\n"; break;
      case 4:
      case 5: text += "JMPVAR " + v + " " + cmps[next(3)] + " " + std::to_string(next(21) - 10) + label() + "\n"; break;
      case 6: text += "GOTO" + label() + "\n"; break;
      case 7: text += "GOSUB sub\n"; break;
      case 8: text += "MOVE " + std::to_string(next(11) - 5) + " 0 0 0 0\n"; break;
      case 9: text += "OUTSIG " + std::to_string(1 + next(8)) + (next(2) ? " ON\n" : " OFF\n"); break;
      case 10: text += "SETSOFT " + std::to_string(next(11) - 5) + " 0 0 0 0\n"; break;
      default: text += "DELAY 0.00" + std::to_string(next(9)) + "\n"; break;
    }
  }
  return text + "END\nsub: ADD B 1\nJMPVAR B > 3 done\nGOSUB sub\ndone: RETURN\n";
}

struct Ended {
  RunOutcome outcome;
  InterpreterState state;
  rs::vm::Micros clock = 0;
  std::vector<std::int32_t> motors;
  std::uint8_t outputs = 0;
};

// Runs the image to its end (or its limits), in slices of `slice` steps
// (0: one call), watched or not.
Ended runWay(const std::shared_ptr<const rs::vm::Image>& image, bool watched, std::uint64_t slice) {
  rs::runtime::RunSpec spec;
  spec.image = image;
  spec.limits.maxSteps = 5'000;
  spec.limits.maxStepsPerInstant = 700;
  rs::runtime::Run run(std::move(spec));
  Watching watching;
  if (watched) run.observe(watching);
  RunOutcome outcome;
  do {
    outcome = slice ? run.runUntil({.moreSteps = slice}) : run.runToEnd();
  } while (outcome.paused());
  // The observer hears of every step that ran, not of one that failed.
  const bool failed = outcome.reason == rs::vm::StopReason::RuntimeError || outcome.reason == rs::vm::StopReason::Deadlock;
  if (watched) CHECK(watching.steps + (failed ? 1 : 0) == outcome.steps);
  const auto motors = run.interpreter().machine().positions();
  return {outcome, run.interpreter().state(), run.interpreter().machine().now(), {motors.begin(), motors.end()},
          run.interpreter().machine().outputs()};
}

}  // namespace

TEST_CASE("the watched and the unwatched loop run every program alike", "[vm][dispatch]") {
  const rs::compiler::Target target{"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth};
  std::uint32_t seed = 23;
  int ran = 0, overflows = 0, limits = 0, ends = 0;
  for (int program = 0; program < 300; ++program) {
    const std::string text = randomProgram(seed, 5 + program % 40);
    const rs::diag::SourceFile source("random.rsp", text);
    rs::compiler::CompileResult compiled = rs::compiler::compile(source, target);
    if (!compiled.image) continue;  // e.g. a move out of range, known at compile time
    INFO(text);
    const auto image = std::make_shared<const rs::vm::Image>(std::move(*compiled.image));
    const Ended plain = runWay(image, false, 0);
    for (const std::uint64_t slice : {0ull, 1ull, 7ull, 300ull}) {
      for (const bool watched : {false, true}) {
        if (!watched && slice == 0) continue;  // that is `plain`
        INFO("slice " << slice << (watched ? ", watched" : ", unwatched"));
        const Ended other = runWay(image, watched, slice);
        CHECK(other.outcome == plain.outcome);
        CHECK(other.state == plain.state);
        CHECK(other.clock == plain.clock);
        CHECK(other.motors == plain.motors);
        CHECK(other.outputs == plain.outputs);
      }
    }
    ++ran;
    overflows += plain.outcome.message.find("overflows") != std::string::npos;
    limits += plain.outcome.reason == rs::vm::StopReason::StepLimit ||
              plain.outcome.reason == rs::vm::StopReason::InstantLimit;
    ends += plain.outcome.reason == rs::vm::StopReason::End;
  }
  // The programs reached every way a run stops here.
  CHECK(ran > 200);
  CHECK(overflows > 10);
  CHECK(limits > 10);
  CHECK(ends > 10);
}
