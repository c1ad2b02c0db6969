// The one table of a stop's words (vm/stop_reason.h): every reason has
// each word, no two reasons share a run word, and the adapter's reasons
// are the Debug Adapter Protocol's own. The words themselves are the ones
// robotsim printed before the three enums became one (launch's table for
// runs, the debugger's own for its stops), checked against those by hand.
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <string_view>

#include "vm/stop_reason.h"

namespace {

using rs::vm::StopReason;

constexpr int kReasons = static_cast<int>(StopReason::Start) + 1;

StopReason reasonAt(int i) { return static_cast<StopReason>(i); }

}  // namespace

TEST_CASE("every stop reason has a run word, a debugger word and an adapter reason, and no two share a run word") {
  std::set<std::string_view> runWords;
  for (int i = 0; i < kReasons; ++i) {
    INFO("reason " << i);
    CHECK_FALSE(rs::vm::stopReasonName(reasonAt(i)).empty());
    CHECK_FALSE(rs::vm::debuggerName(reasonAt(i)).empty());
    CHECK_FALSE(rs::vm::adapterReason(reasonAt(i)).empty());
    CHECK(runWords.insert(rs::vm::stopReasonName(reasonAt(i))).second);
  }
}

TEST_CASE("a run's end is said as run, check and test said it, and the debugger lumps the limits") {
  CHECK(rs::vm::stopReasonName(StopReason::End) == "finished");
  CHECK(rs::vm::stopReasonName(StopReason::RuntimeError) == "runtime error");
  CHECK(rs::vm::stopReasonName(StopReason::Deadlock) == "deadlock");
  CHECK(rs::vm::stopReasonName(StopReason::StepLimit) == "step limit");
  CHECK(rs::vm::stopReasonName(StopReason::TimeLimit) == "time limit");
  CHECK(rs::vm::stopReasonName(StopReason::InstantLimit) == "clock standing still");
  CHECK(rs::vm::stopReasonName(StopReason::Paused) == "paused");
  CHECK(rs::vm::debuggerName(StopReason::End) == "end");
  CHECK(rs::vm::debuggerName(StopReason::RuntimeError) == "runtime error");
  for (StopReason r : {StopReason::StepLimit, StopReason::TimeLimit, StopReason::InstantLimit}) {
    CHECK(rs::vm::isLimit(r));
    CHECK(rs::vm::debuggerName(r) == "limit");
  }
  CHECK(rs::vm::debuggerName(StopReason::Breakpoint) == "breakpoint");
  CHECK(rs::vm::debuggerName(StopReason::Pause) == "pause");
}

TEST_CASE("the adapter's reasons are the protocol's, exception for a run that is over") {
  // The `stopped` event's reasons the Debug Adapter Protocol names.
  const std::set<std::string_view> protocol = {"step",  "breakpoint", "exception",           "pause",
                                               "entry", "goto",       "function breakpoint", "data breakpoint",
                                               "instruction breakpoint"};
  for (int i = 0; i < kReasons; ++i) {
    if (reasonAt(i) == StopReason::End) continue;  // the session ends: no `stopped` event
    INFO("reason " << i);
    CHECK(protocol.count(rs::vm::adapterReason(reasonAt(i))) == 1);
    CHECK((rs::vm::adapterReason(reasonAt(i)) == "exception") == rs::vm::isOver(reasonAt(i)));
  }
  CHECK(rs::vm::adapterReason(StopReason::Watch) == "data breakpoint");
  CHECK(rs::vm::adapterReason(StopReason::Time) == "goto");
  CHECK(rs::vm::adapterReason(StopReason::Start) == "step");
}
