// The property behind stepping backwards (tools/debug/timeline.h): for random
// programs, random stimuli and random moments of their runs, stepping back
// N instructions and forward N again gives a state byte-identical to the
// one before (RunSnapshot: interpreter, machine, input schedule, world),
// stepping back lands on the state a fresh run reaches after as many
// instructions, and goto-time T gives the state of a fresh run paused at T
// (Run::runUntil with a time). Small snapshot intervals make the re-execution
// start from many different snapshots. CI runs a modest count;
// ROBOTSIM_DEBUG_PROPERTY_RUNS=N runs N programs (2,000 take about a second).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <random>

#include "bench/generate.h"
#include "tests/debug/debug_test_util.h"
#include "tools/debug/debug_session.h"

namespace {

using rs::debug::DebugSession;
using rs::runtime::Run;

int programCount() {
  const char* env = std::getenv("ROBOTSIM_DEBUG_PROPERTY_RUNS");
  return env ? std::max(1, std::atoi(env)) : 40;
}

// Timed changes on random inputs at random times within the first 30 s:
// WAITFOR and JMPIN in the generated programs then take other branches.
rs::stimuli::Stimuli randomStimuli(std::mt19937_64& rng) {
  rs::stimuli::Stimuli s;
  const int n = static_cast<int>(rng() % 6);
  for (int i = 0; i < n; ++i)
    s.changes.push_back({static_cast<rs::vm::Micros>(rng() % 30'000'000), static_cast<int>(1 + rng() % 8), rng() % 2 == 0});
  std::stable_sort(s.changes.begin(), s.changes.end(), [](const auto& a, const auto& b) { return a.at < b.at; });
  if (rng() % 2) s.rules.push_back({1, true, 2, true, static_cast<rs::vm::Micros>(rng() % 500'000), 0});
  return s;
}

void checkProgram(const rs::runtime::RunSpec& spec, std::mt19937_64& rng) {
  Run whole(spec);
  whole.runToEnd();
  const std::uint64_t total = whole.interpreter().steps();
  const rs::vm::Micros end = whole.rig().clock();
  DebugSession session(spec, {1 + rng() % 200, rs::debug::kDefaultSnapshotBudget});
  for (int trial = 0; trial < 8; ++trial) {
    const std::uint64_t at = rng() % (total + 1);
    // Counted as the session shows them: inside a move after goto-time, the
    // move under way is not done yet (the first step finishes it).
    const std::uint64_t shown = session.view().steps;
    session.step(at > shown ? at - shown : 0);
    if (session.run().interpreter().steps() > at) session.reverseStep(session.run().interpreter().steps() - at);
    REQUIRE(session.run().interpreter().steps() == at);
    const rs::runtime::RunSnapshot before = session.run().snapshot();
    const std::uint64_t back = 1 + rng() % (at + 1);
    session.reverseStep(back);
    const std::uint64_t landed = session.run().interpreter().steps();
    REQUIRE(landed == at - std::min(back, at));
    Run fresh(spec);
    fresh.runUntil({.moreSteps = landed});
    REQUIRE(session.run().snapshot() == fresh.snapshot());
    session.step(at - landed);
    REQUIRE(session.run().snapshot() == before);

    const rs::vm::Micros t = static_cast<rs::vm::Micros>(rng() % static_cast<std::uint64_t>(end + 2));
    session.gotoTime(t);
    Run timed(spec);
    timed.runUntil({.time = t});
    INFO("goto-time " << t << " us of " << end);
    const std::uint64_t stood = session.run().interpreter().steps();
    if (stood + 1 == timed.interpreter().steps()) {  // t falls between two instructions: the session stands at t
      CHECK(session.run().rig().clock() == t);
      Run exact(spec);
      exact.runUntil({.moreSteps = stood});
      REQUIRE(session.run().snapshot() == exact.snapshot());
    } else {
      REQUIRE(session.run().snapshot() == timed.snapshot());
      if (!timed.finished()) CHECK(session.view().clock == t);  // inside the instruction under way: at t itself
    }
  }
}

}  // namespace

TEST_CASE("reverse then forward gives the same state, goto-time the state of a fresh run, random programs",
          "[debug][property]") {
  std::mt19937_64 rng(20261124);
  for (int p = 0; p < programCount(); ++p) {
    const std::size_t size = 1 + rng() % 300;
    INFO("program " << p << " of " << size << " instructions");
    checkProgram(debugtest::specOf(rs::bench::robotProgram(size).text, randomStimuli(rng)), rng);
  }
}

TEST_CASE("reverse then forward on a workcell: the objects the gripper carried come back too", "[debug][property]") {
  std::mt19937_64 rng(7);
  checkProgram(debugtest::specOnCell("gantry_pick.rsp", "gantry-cell"), rng);
}

TEST_CASE("reverse then forward on a cell with devices: belts, sensors, feeders and sinks come back too",
          "[debug][property][devices]") {
  // adept-cell's production loop: parts fed every 6 s, carried by two
  // belts, seen by a beam wired to input 1, taken by a sink; the state
  // compared holds the devices' (RigSnapshot::devices, pendingDevices).
  std::mt19937_64 rng(35);
  for (int i = 0; i < 3; ++i) checkProgram(debugtest::specOnCell("adept_production.rsp", "adept-cell"), rng);
}

TEST_CASE("set input is replayed: back before the change and forward again gives the same state", "[debug][property]") {
  std::mt19937_64 rng(99);
  for (int p = 0; p < std::max(4, programCount() / 3); ++p) {
    const rs::runtime::RunSpec spec = debugtest::specOf(rs::bench::robotProgram(20 + rng() % 100).text);
    Run whole(spec);
    whole.runToEnd();
    const std::uint64_t total = whole.interpreter().steps();
    DebugSession session(spec, {1 + rng() % 50, rs::debug::kDefaultSnapshotBudget});
    // Two changes by hand at random moments, the second after going back.
    session.step(rng() % (total / 2 + 1));
    const int input = static_cast<int>(1 + rng() % 8);
    REQUIRE_FALSE(session.setInput(input, true));
    REQUIRE((session.run().rig().machine().inputs() & (1u << (input - 1))) != 0);
    session.step(1 + rng() % (total / 2 + 1));
    if (session.run().finished()) session.reverseStep(1);
    session.reverseStep(rng() % (session.run().interpreter().steps() + 1));
    if (!session.run().finished()) REQUIRE_FALSE(session.setInput(static_cast<int>(1 + rng() % 8), rng() % 2 == 0));
    session.step(rng() % 200);
    for (int trial = 0; trial < 6; ++trial) {
      const std::uint64_t at = session.run().interpreter().steps();
      const rs::runtime::RunSnapshot before = session.run().snapshot();
      const std::uint64_t back = 1 + rng() % (at + 1);
      session.reverseStep(back);
      session.step(at - session.run().interpreter().steps());
      REQUIRE(session.run().interpreter().steps() == at);
      REQUIRE(session.run().snapshot() == before);
      session.step(rng() % 50);
    }
  }
}

TEST_CASE("snapshots over the memory budget: the interval doubles, memory stays bounded, backwards still exact",
          "[debug][property]") {
  // 600 loops of a handful of instructions: about 4,000 instructions.
  const rs::runtime::RunSpec spec = debugtest::specOf(
      "        SET N 0\nloop:   ADD N 1\n        MOVE 10 0 0 0 0\n        MOVE -10 0 0 0 0\n"
      "        JMPVAR N < 600 loop\n        END\n");
  constexpr std::size_t kBudget = 16 * 1024;
  DebugSession session(spec, {8, kBudget});
  session.resume();
  REQUIRE(session.lastStop().reason == rs::debug::StopReason::End);
  const std::uint64_t total = session.run().interpreter().steps();
  CHECK(session.timeline().interval() > 8);
  CHECK(session.timeline().snapshotMemory() <= kBudget);
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const std::uint64_t at = rng() % total;
    const std::uint64_t now = session.run().interpreter().steps();
    if (at < now) session.reverseStep(now - at);
    else session.step(at - now);
    REQUIRE(session.run().interpreter().steps() == at);
    Run fresh(spec);
    fresh.runUntil({.moreSteps = at});
    REQUIRE(session.run().snapshot() == fresh.snapshot());
    session.step(rng() % 100);
  }
  CHECK(session.timeline().snapshotMemory() <= kBudget);
}
