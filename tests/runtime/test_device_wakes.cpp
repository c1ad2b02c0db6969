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
#include "compiler/description/library.h"
#include "runtime/run/run.h"

TEST_CASE("devices: a long production run schedules events in proportion to its length, its queue stays small",
          "[cell][devices]") {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const auto cell = library.workcell("adept-cell");
  REQUIRE(cell);
  const std::string program =
      "        SET PARTS 0\n"
      "next:   OUTSIG 1 ON\n"
      "        WAITFOR 1 ON\n"
      "        OUTSIG 1 OFF\n"
      "        MOVEP PICK\n"
      "        MOVE 0 0 5900 0 0\n"
      "        MOVE 0 0 0 0 80\n"
      "        MOVE 0 0 -5900 0 0\n"
      "        MOVEP PLACE\n"
      "        MOVE 0 0 5900 0 0\n"
      "        MOVE 0 0 0 0 -80\n"
      "        MOVE 0 0 -5900 0 0\n"
      "        ADD PARTS 1\n"
      "        JMPVAR PARTS < 200 next\n"
      "        END\n"
      "POINTS\n"
      "PICK -3320 -6844 0 -10164 0\n"
      "PLACE 3320 6844 0 1164 80\n";
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
  CHECK(run->rig().devices()->taken(0) == 199);  // the last still rides the outfeed at END
  CHECK(at100 > 0);
  CHECK(at100 < 100'000);
  // Twice the blocks, about twice the events (not four times).
  CHECK(at200 < 3 * at100);
  CHECK(longest <= 16);
}
