// The devices' wakes do not pile up (issue 35's speed point): a plan of the
// belts' motion schedules the next time anything may happen, and a later
// plan makes that wake stale. Before, every stale wake planned again and
// kept its own chain going, one more chain with every change: the run
// below scheduled 63,110 events by its 100th block and 243,884 by its
// 200th, its CPU time growing with the square of its length. Counted here
// in events, not timed.
//
// By hand: in adept-cell's production loop the events of a 6 s cycle are
// a feed, a beam's two edges and its wire's two changes, a sink's take, the
// belt's start and stop, and the robot's moves and waits (about 12 an
// instruction that waits on the clock, 13 instructions a cycle): a few
// hundred at most. So 100 cycles (600 s) schedule well under 100,000
// events, and the queue never holds more than a handful.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <string>

#include "../render/render_test_util.h"
#include "bench/adept_hour.h"
#include "compiler/description/library.h"
#include "runtime/run/run.h"

TEST_CASE("devices: a long production run schedules events in proportion to its length, its queue stays small",
          "[cell][devices]") {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const auto cell = library.workcell("adept-cell");
  REQUIRE(cell);
  const std::string program = rs::bench::adeptHourProgram(200);  // the example, 200 blocks
  const auto run = rendertest::runOf(rendertest::compileText(program, *cell), &*cell, {}, false,
                                     rs::runtime::CollisionMode::Off);
  std::size_t longest = 0;
  std::uint64_t at100 = 0;
  while (!run->finished()) {
    run->runUntil({.moreSteps = 13});
    longest = std::max(longest, run->rig().running().clock().state().queue.size());
    if (at100 == 0 && run->rig().devices()->taken(0) >= 100) at100 = run->rig().running().clock().state().nextSeq;
  }
  REQUIRE(run->outcome()->ok());
  const std::uint64_t at200 = run->rig().running().clock().state().nextSeq;
  INFO("events scheduled: " << at100 << " by the 100th block taken, " << at200 << " by the end");
  // The last block reaches the sink 4.661 s after its beam; the loop's last
  // cycle, HRDHOME and DELAY 4 end the run 5.306 s after it (the example's
  // count by hand): the sink has taken all 200.
  CHECK(run->rig().devices()->taken(0) == 200);
  CHECK(at100 > 0);
  CHECK(at100 < 100'000);
  // Twice the blocks, about twice the events (not four times).
  CHECK(at200 < 3 * at100);
  CHECK(longest <= 16);
}
