// The hooks a front end builds on: DebugSession::onStop hears of every stop,
// forwards and backwards, with the session standing at the stopped moment
// (what a live view of the workcell draws); setInterrupt pauses a long run.
#include <catch2/catch.hpp>

#include <vector>

#include "tests/debug/debug_test_util.h"
#include "tools/debug/debug_session.h"

using rs::debug::DebugSession;
using rs::debug::Stop;
using rs::debug::StopReason;

TEST_CASE("onStop hears every stop with the view of the stopped moment", "[debug][session]") {
  DebugSession session(debugtest::specOnCell("gantry_pick.rsp", "gantry-cell"));
  std::vector<std::pair<StopReason, rs::vm::Micros>> heard;
  std::vector<bool> held;
  session.onStop([&](const DebugSession& s, const Stop& stop) {
    const rs::runtime::RunView v = s.view();
    heard.emplace_back(stop.reason, v.clock);
    held.push_back(!v.objects.empty() && (v.objects[1].held || v.objects[2].held));
    CHECK(v.tcp.has_value());
  });
  REQUIRE(session.breakAtLabel("place").ok());
  const Stop first = session.resume();
  session.reverseStep(3);
  session.gotoTime(0);
  session.resume();
  REQUIRE(heard.size() == 4);
  CHECK(heard[0] == std::pair{StopReason::Breakpoint, first.reason == StopReason::Breakpoint ? session.run().rig().clock() : 0});
  CHECK(heard[1].first == StopReason::Step);
  CHECK(heard[1].second <= heard[0].second);
  CHECK(heard[2].first == StopReason::Time);
  CHECK(heard[3] == heard[0]);  // the same breakpoint, the same moment
  // At place the gripper holds the first block; two instructions before it
  // (the MOVETO over the pallet, the GOSUB) it still holds it.
  CHECK(held == std::vector<bool>{true, true, false, true});
}

TEST_CASE("setInterrupt pauses a long run between slices", "[debug][session]") {
  DebugSession session(debugtest::specOf("loop:   DELAY 0.001\n        GOTO loop\n"));
  int asked = 0;
  session.setInterrupt([&] { return ++asked == 3; });
  const Stop stop = session.resume();
  CHECK(stop.reason == StopReason::Pause);
  CHECK(asked == 3);
  // Three slices of the snapshot interval, at most.
  CHECK(session.run().interpreter().steps() <= 3 * rs::debug::kDefaultSnapshotInterval);
  CHECK(session.run().interpreter().steps() > 0);
}
