// Issue 36, the cell run's pauses (CellRun::runUntil): a run paused after
// every step, at every step count or every tenth of a second, and then
// gone on, ends exactly as one that never paused (what the debugger of a
// cell rests on: it re-runs the cell to the moment it goes back to).
#include <catch2/catch.hpp>

#include <string>

#include "runtime/run/cell_run.h"
#include "tests/runtime/cell_spec_support.h"

namespace cell_run_pause_test {

rs::runtime::CellRunSpec interlock() {
  return rs::testing::cellRunSpecOf(std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/interlock.rsd");
}

// Everything a run's end shows of each robot.
struct End {
  rs::vm::StopReason reason;
  rs::vm::Micros clock;
  std::vector<std::uint64_t> steps;
  std::vector<rs::vm::Micros> times;
  std::vector<std::vector<std::int32_t>> motors, variables;
  std::vector<rs::vm::IoMask> inputs, outputs;
  bool operator==(const End&) const = default;
};

End endOf(const rs::runtime::CellRun& cell, const rs::vm::RunOutcome& outcome) {
  End e{outcome.reason, cell.clock(), {}, {}, {}, {}, {}, {}};
  for (std::size_t p = 0; p < cell.size(); ++p) {
    const rs::runtime::Run& r = cell.robot(p);
    e.steps.push_back(r.interpreter().steps());
    e.times.push_back(cell.endTime(p));
    const auto m = r.rig().motors();
    e.motors.emplace_back(m.begin(), m.end());
    const auto v = r.interpreter().variables();
    e.variables.emplace_back(v.begin(), v.end());
    e.inputs.push_back(r.rig().machine().inputs());
    e.outputs.push_back(r.rig().machine().outputs());
  }
  return e;
}

}  // namespace cell_run_pause_test

using namespace cell_run_pause_test;

TEST_CASE("cell run pause: pausing after every step, count or tenth of a second changes nothing", "[cell-run][cell-debug]") {
  const rs::runtime::CellRunSpec spec = interlock();
  rs::runtime::CellRun whole(spec);
  const End expected = endOf(whole, whole.runToEnd());
  // By hand (tests/cli/test_cell_run.cpp): the cell ends at 8.5 s.
  CHECK(expected.reason == rs::vm::StopReason::End);
  CHECK(expected.clock == 8'500'000);

  rs::runtime::CellRun stepped(spec);
  std::vector<std::size_t> order;
  rs::runtime::CellUntil every;
  every.afterStep = [&order](const rs::runtime::CellRun&, std::size_t p) {
    order.push_back(p);
    return true;
  };
  rs::vm::RunOutcome o;
  std::size_t pauses = 0;
  while ((o = stepped.runUntil(every)).paused()) ++pauses;
  CHECK(endOf(stepped, o) == expected);
  CHECK(pauses == order.size());
  CHECK(order.size() == expected.steps[0] + expected.steps[1]);
  CHECK(order.front() == 0);  // left is first in the cell's order

  rs::runtime::CellRun counted(spec);
  for (std::uint64_t k = 1; !counted.finished(); ++k) {
    rs::runtime::CellUntil at;
    at.steps = k;
    o = counted.runUntil(at);
    if (o.paused()) CHECK(counted.steps() == k);
  }
  CHECK(endOf(counted, o) == expected);

  rs::runtime::CellRun timed(spec);
  for (rs::vm::Micros t = 0; !timed.finished(); t += 100'000) {
    rs::runtime::CellUntil at;
    at.time = t;
    o = timed.runUntil(at);
    if (o.paused()) CHECK(timed.clock() <= t);
  }
  CHECK(endOf(timed, o) == expected);
}
