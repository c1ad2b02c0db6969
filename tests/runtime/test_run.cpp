// The run layer (runtime/run/run.h): stepping, pausing where asked, reading
// a run's view, pausing from another thread, the clock-standing-still
// limit, the bound on pending reactive stimuli, and snapshot/restore,
// checked against an uninterrupted run of the same program byte for byte
// (its JSON trace, written by the same TraceWriter `robotsim run --trace`
// uses).
#include <catch2/catch.hpp>

#include <chrono>
#include <sstream>
#include <thread>

#include "../render/render_test_util.h"
#include "runtime/run/trace.h"
#include "runtime/run/run.h"
#include "compiler/stimuli/stimuli.h"

namespace {

using rs::runtime::Run;
using rs::vm::Micros;
using rs::vm::StopReason;

constexpr Micros kRunSecond = 1'000'000;

const std::string kRunExamples = rendertest::kSourceDir + "/examples/";

struct Case {
  std::string program;  // under examples/
  std::string cell;
  std::string stimuli;  // under examples/, or ""
};

// A robot arm that grasps, reactive and timed stimuli, WAITFOR, GOSUB.
const std::vector<Case> kCases = {
    {"pick_and_place.rsp", "scara-pick", "pick_and_place.stim"},
    {"gantry_pick.rsp", "gantry-cell", ""},
    {"nested_subroutines.rsp", "scara-pick", ""},
    {"sensor_branching.rsp", "scara-pick", "sensor_branching.stim"},
};

rs::stimuli::Stimuli stimuliOf(const Case& c) {
  if (c.stimuli.empty()) return {};
  rs::diag::Result<rs::stimuli::Stimuli> parsed = rs::stimuli::loadStimuliFile(kRunExamples + c.stimuli);
  REQUIRE(parsed.ok());
  return std::move(parsed).value();
}

std::unique_ptr<Run> runOf(const Case& c) {
  const rs::workcell::Workcell cell = rendertest::cell(c.cell);
  return rendertest::runOf(rendertest::compile(kRunExamples + c.program, cell), &cell, stimuliOf(c), /*log=*/true);
}

// A run that writes its JSON trace into `out`.
struct Traced {
  std::ostringstream out;
  std::unique_ptr<Run> run;
  std::unique_ptr<rs::runtime::TraceWriter> trace;
  explicit Traced(const Case& c) : run(runOf(c)) {
    trace = std::make_unique<rs::runtime::TraceWriter>(out, rs::runtime::TraceFormat::Json, *run);
    run->observe(*trace);
  }
  std::string take() {
    std::string s = out.str();
    out.str("");
    return s;
  }
};

Run& simple(std::unique_ptr<Run>& holder, const std::string& text, rs::stimuli::Stimuli stimuli = {},
            rs::vm::RunLimits limits = {}) {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  rs::vm::Image image = rendertest::compileText(text, cell);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(std::move(image));
  spec.stimuli = std::move(stimuli);
  spec.limits = limits;
  holder = std::make_unique<Run>(std::move(spec));
  return *holder;
}

}  // namespace

TEST_CASE("run to a moment, snapshot, run on, restore, run on again: the same trace byte for byte", "[run]") {
  for (const Case& c : kCases) {
    INFO(c.program);
    Traced whole(c);
    const rs::vm::RunOutcome end = whole.run->runToEnd();
    REQUIRE(end.ok());
    const std::string all = whole.take();
    const std::uint64_t total = end.steps;
    REQUIRE(total > 8);
    for (const std::uint64_t at : {std::uint64_t{1}, total / 3, total / 2, total - 1}) {
      INFO("snapshot after step " << at);
      Traced t(c);
      t.run->runUntil({.moreSteps = at});
      CHECK(t.run->pauseCause() == StopReason::Step);
      const std::string before = t.take();
      const rs::runtime::RunSnapshot snap = t.run->snapshot();
      const rs::vm::RunOutcome first = t.run->runToEnd();
      const std::string after = t.take();
      const rs::runtime::RunSnapshot endOfFirst = t.run->snapshot();
      t.run->restore(snap);
      CHECK(t.run->snapshot() == snap);
      CHECK_FALSE(t.run->finished());
      const rs::vm::RunOutcome second = t.run->runToEnd();
      const std::string again = t.take();
      CHECK(first == end);
      CHECK(second == end);
      CHECK(before + after == all);
      CHECK(again == after);
      CHECK(t.run->snapshot() == endOfFirst);  // machine, world, log: all where they were
      CHECK(t.run->log()->steps.size() == total);
    }
  }
}

TEST_CASE("snapshots every 10 steps, restored out of order, replay the same steps", "[run]") {
  const Case c = kCases[0];
  Traced whole(c);
  REQUIRE(whole.run->runToEnd().ok());
  const std::string all = whole.take();
  // One entry a step: its line, after the input changes it saw (their own lines).
  std::vector<std::string> lines;
  std::string events;
  std::istringstream in(all);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(R"({"event":"input")", 0) == 0) {
      events += line + '\n';
    } else {
      lines.push_back(events + line);
      events.clear();
    }

  Traced t(c);
  std::vector<rs::runtime::RunSnapshot> snaps;
  while (!t.run->finished()) {
    snaps.push_back(t.run->snapshot());
    t.run->runUntil({.moreSteps = 10});
  }
  t.take();
  REQUIRE(snaps.size() > 2);
  for (std::size_t i : {snaps.size() - 1, std::size_t{0}, snaps.size() / 2}) {
    INFO("snapshot " << i);
    t.run->restore(snaps[i]);
    t.run->runUntil({.moreSteps = 10});
    std::string want;
    for (std::size_t l = 10 * i; l < std::min(lines.size(), 10 * i + 10); ++l) want += lines[l] + '\n';
    CHECK(t.take() == want);
  }
}

TEST_CASE("step, run until a line, a label, a time or a condition, and look", "[run]") {
  std::unique_ptr<Run> holder;
  Run& run = simple(holder,
                    "        SET N 0\n"         // line 1
                    "loop:   ADD N 1\n"         // 2
                    "        GOSUB sub\n"       // 3
                    "        JMPVAR N < 5 loop\n"  // 4
                    "        END\n"             // 5
                    "sub:    MOVE 100 0 0 0 0\n"  // 6: E 100 units at 400/s: 0.25 s
                    "        RETURN\n");        // 7
  rs::runtime::RunView v = run.view();
  CHECK(v.instruction == 0);
  CHECK(v.line == 1);
  CHECK(v.clock == 0);
  CHECK_FALSE(v.finished);
  REQUIRE(v.variables.size() == 1);
  CHECK(v.variables[0].first == "N");

  CHECK(run.runUntil({.moreSteps = 1}).paused());
  CHECK(run.pauseCause() == StopReason::Step);
  CHECK(run.view().line == 2);

  const rs::vm::RunOutcome atSub = run.runUntil({.lines = {6}});
  CHECK(atSub.paused());
  CHECK(run.pauseCause() == StopReason::Breakpoint);
  v = run.view();
  CHECK(v.line == 6);
  REQUIRE(v.callStack.size() == 1);
  CHECK(v.callStack[0].line == 3);
  CHECK(v.variables[0].second == 1);
  CHECK(v.steps == 3);

  // A breakpoint the run stands on does not stop it again at once.
  const std::optional<std::uint32_t> sub = rs::runtime::labelInstruction(*run.spec().image, "SUB");
  REQUIRE(sub == std::optional<std::uint32_t>(5));
  CHECK(run.runUntil({.instructions = {*sub}}).paused());
  CHECK(run.view().line == 6);
  CHECK(run.view().variables[0].second == 2);
  CHECK(run.view().clock == kRunSecond / 4);
  CHECK_FALSE(rs::runtime::labelInstruction(*run.spec().image, "nowhere"));
  CHECK(rs::runtime::labelInstruction(*run.spec().image, "loop") == std::optional<std::uint32_t>(1));

  // The third MOVE ends at 0.75 s: the first step past 0.6 s.
  CHECK(run.runUntil({.time = 600'000}).paused());
  CHECK(run.pauseCause() == StopReason::Time);
  CHECK(run.rig().clock() == 3 * kRunSecond / 4);
  CHECK(run.view().line == 7);

  rs::runtime::RunUntil until;
  until.when = [](const Run& r) { return r.interpreter().variables()[0] == 5; };
  CHECK(run.runUntil(until).paused());
  CHECK(run.pauseCause() == StopReason::Condition);
  CHECK(run.view().line == 3);  // right after the ADD that made N 5

  const rs::vm::RunOutcome end = run.runToEnd();
  CHECK(end.ok());
  CHECK(run.finished());
  CHECK(run.outcome() == std::optional(end));
  CHECK(run.view().line == 5);  // the END it ended on
  CHECK(run.view().motors[0] == 500);
  CHECK(run.runUntil({.moreSteps = 1}) == end);  // a finished run stays finished
}

TEST_CASE("stepping one instruction at a time gives the run the uninterrupted run gives", "[run]") {
  const Case c = kCases[0];
  Traced whole(c);
  const rs::vm::RunOutcome end = whole.run->runToEnd();
  Traced stepped(c);
  std::uint64_t calls = 0;
  while (!stepped.run->finished()) stepped.run->runUntil({.moreSteps = 1}), ++calls;
  CHECK(calls == end.steps);
  CHECK(stepped.run->outcome() == std::optional(end));
  CHECK(stepped.take() == whole.take());
  CHECK(stepped.run->snapshot() == whole.run->snapshot());
}

TEST_CASE("a run pauses when asked from another thread, and goes on", "[run]") {
  std::unique_ptr<Run> holder;
  rs::vm::RunLimits limits;
  limits.maxSteps = std::uint64_t{1} << 60;
  limits.maxStepsPerInstant = 0;
  Run& run = simple(holder, "loop: ADD N 1\nGOTO loop\n", {}, limits);
  std::thread asker([&run] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    run.requestPause();
  });
  const rs::vm::RunOutcome o = run.runToEnd();
  asker.join();
  CHECK(o.paused());
  CHECK(run.pauseCause() == StopReason::Pause);
  const std::uint64_t steps = run.view().steps;
  CHECK(steps > 0);
  CHECK(run.runUntil({.moreSteps = 10}).paused());
  CHECK(run.view().steps == steps + 10);
  // A total and a count from here: the nearer of the two pauses it.
  CHECK(run.runUntil({.steps = steps + 15, .moreSteps = 100}).paused());
  CHECK(run.view().steps == steps + 15);
  CHECK(run.runUntil({.steps = steps + 100, .moreSteps = 3}).paused());
  CHECK(run.view().steps == steps + 18);
  CHECK(run.pauseCause() == StopReason::Step);
}

TEST_CASE("a loop that never lets the clock move stops with its own reason", "[run]") {
  rs::vm::RunLimits limits;
  limits.maxStepsPerInstant = 1000;
  std::unique_ptr<Run> holder;
  const rs::vm::RunOutcome still = simple(holder, "loop: ADD N 1\nGOTO loop\n", {}, limits).runToEnd();
  CHECK(still.reason == StopReason::InstantLimit);
  CHECK(still.steps == 1000);
  CHECK(still.message.find("1000 instructions ran at 0.000 s") != std::string::npos);
  // With a DELAY in the loop the clock moves, and the step limit stops it.
  limits.maxSteps = 5000;
  const rs::vm::RunOutcome moving = simple(holder, "loop: ADD N 1\nDELAY 0.01\nGOTO loop\n", {}, limits).runToEnd();
  CHECK(moving.reason == StopReason::StepLimit);
  CHECK(moving.steps == 5000);
}

TEST_CASE("a rule that cannot keep up with its output is a runtime error naming the rule", "[run]") {
  rs::diag::Result<rs::stimuli::Stimuli> parsed =
      rs::stimuli::parseStimuli("; the conveyor\nwhen output 1 on then input 1 on after 10\n", "flicker.stim");
  REQUIRE(parsed.ok());
  std::unique_ptr<Run> holder;
  const rs::vm::RunOutcome o =
      simple(holder, "loop: OUTSIG 1 ON\nOUTSIG 1 OFF\nGOTO loop\n", *parsed).runToEnd();
  CHECK(o.reason == StopReason::RuntimeError);
  CHECK(o.message.find("the stimuli rule of line 2 'when output 1 ON then input 1 ON after 10.000' has 100000 input "
                       "changes waiting to happen") != std::string::npos);
  CHECK(o.steps < 400'000);
}
