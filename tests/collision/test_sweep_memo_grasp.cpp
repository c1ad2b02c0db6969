// The swept check's memory of moves across takes and let-goes: a loop that
// takes a block, puts it down, takes it again and carries it back must find
// the world bit for bit as it was one loop earlier, or no move of it is
// ever answered from memory (scara-pick's pick-and-place benchmark ran
// 372 times slower with collisions on: the held offset drifted by an ulp a
// take, and every resting place with it).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "../render/render_test_util.h"
#include "runtime/run/run.h"

namespace {

// bench/collision_programs.cpp's scara-pick pick-and-place, `loops` times:
// 13 moves a loop, a take and a let-go each way.
std::string pickAndPlace(int loops) {
  return fmt::format(R"(        SET N 0
loop:   MOVEP ABOVE
        MOVEP PICK
        MOVEP TAKE
        MOVEP LIFT0
        MOVEP LIFT
        MOVEP OVER
        MOVEP PLACE
        MOVEP DROP
        MOVEP RETAKE
        MOVEP OVERC
        MOVEP LIFTC
        MOVEP PICKC
        MOVEP RELEASE
        ADD N 1
        JMPVAR N < {} loop
        END
POINTS
ABOVE   AT -130 870 0          GRIP 0
PICK    AT -130 819 0          GRIP 0
TAKE    AT -130 819 0          GRIP 120
LIFT0   AT -130 824 0          GRIP 120
LIFT    AT -130 870 0          GRIP 120
OVER    AT -180 875 -45        GRIP 120
PLACE   AT -180 859 -45        GRIP 120
DROP    AT -180 859 -45        GRIP 0
RETAKE  AT -180 859 -45        GRIP 120
OVERC   AT -180 875 -45        GRIP 120
LIFTC   AT -130 870 0          GRIP 120
PICKC   AT -130 819 0          GRIP 120
RELEASE AT -130 819 0          GRIP 0
)",
                     loops);
}

}  // namespace

TEST_CASE("a pick-and-place loop is swept once: later loops come from memory", "[collision][runtime][memo]") {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  constexpr int kLoops = 12;
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(rendertest::compileText(pickAndPlace(kLoops), cell));
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.collisions = rs::runtime::CollisionMode::Error;
  rs::runtime::Run run(spec);
  // Two loops: the block goes from its placement to the place and back, so
  // the second loop's world is the first loop's with the block where the
  // first left it; from the third on, each loop's world is the one before.
  // SET, then 15 instructions a loop
  REQUIRE(run.runUntil({.moreSteps = 2 * 15 + 1}).reason == rs::vm::StopReason::Paused);
  const rs::runtime::CollisionWatch* watch = run.rig().collisionWatch();
  REQUIRE(watch);
  const std::uint64_t sweptInTwo = watch->moves() - watch->remembered();
  CHECK(watch->moves() == 2 * 13);
  const rs::runtime::RunSnapshot afterTwo = run.snapshot();
  REQUIRE(run.runToEnd().ok());
  CHECK(run.rig().collisions().empty());
  CHECK(watch->moves() == kLoops * 13);
  // Not one move after the second loop swept afresh (before the fix every
  // one was: moves - remembered grew by 13 a loop).
  CHECK(watch->moves() - watch->remembered() == sweptInTwo);
  // And the world is what a restore from the snapshot makes of it again.
  const rs::runtime::RunSnapshot atEnd = run.snapshot();
  run.restore(afterTwo);
  REQUIRE(run.runToEnd().ok());
  CHECK(run.snapshot() == atEnd);
}
