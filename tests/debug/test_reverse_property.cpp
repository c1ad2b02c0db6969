// The property behind stepping backwards (debug/timeline.h): for random
// programs, random stimuli and random moments of their runs, stepping back
// N instructions and forward N again gives a state byte-identical to the
// one before (RunSnapshot: interpreter, machine, input schedule, world),
// stepping back lands on the state a fresh run reaches after as many
// instructions, and goto-time T gives the state of a fresh run paused at T
// (Run::runUntilTime). Small snapshot intervals make the re-execution
// start from many different snapshots. CI runs a modest count;
// ROBOTSIM_DEBUG_PROPERTY_RUNS=N runs N programs (e.g. 500).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <random>

#include "bench/generate.h"
#include "debug/session.h"
#include "tests/debug/debug_test_util.h"

namespace {

using rs::debug::Session;
using rs::runtime::Run;

int programCount() {
  const char* env = std::getenv("ROBOTSIM_DEBUG_PROPERTY_RUNS");
  return env ? std::max(1, std::atoi(env)) : 12;
}

// Timed changes on random inputs at random times within the first 30 s:
// WAITFOR and JMPIN in the generated programs then take other branches.
rs::runtime::Stimuli randomStimuli(std::mt19937_64& rng) {
  rs::runtime::Stimuli s;
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
  const rs::vm::Micros end = whole.clock();
  Session session(spec, {1 + rng() % 200, rs::debug::kDefaultSnapshotBudget});
  for (int trial = 0; trial < 8; ++trial) {
    const std::uint64_t at = rng() % (total + 1);
    session.step(at > session.run().interpreter().steps() ? at - session.run().interpreter().steps() : 0);
    if (session.run().interpreter().steps() > at) session.reverseStep(session.run().interpreter().steps() - at);
    REQUIRE(session.run().interpreter().steps() == at);
    const rs::runtime::RunSnapshot before = session.run().snapshot();
    const std::uint64_t back = 1 + rng() % (at + 1);
    session.reverseStep(back);
    const std::uint64_t landed = session.run().interpreter().steps();
    REQUIRE(landed == at - std::min(back, at));
    Run fresh(spec);
    fresh.step(landed);
    REQUIRE(session.run().snapshot() == fresh.snapshot());
    session.step(at - landed);
    REQUIRE(session.run().snapshot() == before);

    const rs::vm::Micros t = static_cast<rs::vm::Micros>(rng() % static_cast<std::uint64_t>(end + 2));
    session.gotoTime(t);
    Run timed(spec);
    timed.runUntilTime(t);
    INFO("goto-time " << t << " us of " << end);
    REQUIRE(session.run().snapshot() == timed.snapshot());
  }
}

}  // namespace

TEST_CASE("reverse then forward gives the same state, goto-time the state of a fresh run, random programs",
          "[debug][property]") {
  std::mt19937_64 rng(20261124);
  for (int p = 0; p < programCount(); ++p) {
    const std::size_t size = 1 + rng() % 120;
    INFO("program " << p << " of " << size << " instructions");
    checkProgram(debugtest::specOf(rs::bench::robotProgram(size).text, randomStimuli(rng)), rng);
  }
}

TEST_CASE("reverse then forward on a workcell: the objects the gripper carried come back too", "[debug][property]") {
  std::mt19937_64 rng(7);
  checkProgram(debugtest::specOnCell("gantry_pick.rsp", "gantry-cell"), rng);
}
