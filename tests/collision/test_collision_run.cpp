// Collisions in the run layer: a snapshot keeps the ones found so far, so a
// restored run (back or forwards) has them and finds the later ones again,
// at the same times; and a run on a cell with collisions off has no
// checker at all.
#include <catch2/catch.hpp>

#include "../render/render_test_util.h"
#include "runtime/run/run.h"

namespace {

std::vector<std::pair<rs::vm::Micros, std::uint32_t>> found(const rs::runtime::Run& run) {
  std::vector<std::pair<rs::vm::Micros, std::uint32_t>> out;
  for (const rs::runtime::CollisionEvent& e : run.rig().collisions()) out.emplace_back(e.at, e.instruction);
  return out;
}

}  // namespace

TEST_CASE("a restored run finds the same collisions again", "[collision][runtime]") {
  // The gantry driven through the floor twice: Y down to 2000 and back up,
  // then down again (tests/collision/test_collision_geometry.cpp works out
  // the first time: from 2.25125 s, before 2.26375 s).
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  const rs::vm::Image image =
      rendertest::compileText("        MOVETO 0 0 2000 0\n        MOVETO 0 0 0 0\n        MOVETO 0 0 2000 0\n        END\n", cell);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.collisions = rs::runtime::CollisionMode::Warn;
  rs::runtime::Run run(spec);
  run.runUntil({.moreSteps = 1});
  const rs::runtime::RunSnapshot after1 = run.snapshot();
  CHECK(after1.rig.collisions.size() == 1);
  REQUIRE(run.runToEnd().ok());
  const auto all = found(run);
  REQUIRE(all.size() == 3);
  CHECK(all[0].second == 0);
  CHECK(all[0].first >= 2'251'250);
  CHECK(all[0].first < 2'263'750);
  CHECK(all[1] == std::pair<rs::vm::Micros, std::uint32_t>{2'500'000, 1});  // starts below: at once
  // The third move is the first one again, 5 s later: checked at the same times.
  CHECK(all[2] == std::pair<rs::vm::Micros, std::uint32_t>{all[0].first + 5'000'000, 2});
  run.restore(after1);
  CHECK(found(run).size() == 1);
  REQUIRE(run.runToEnd().ok());
  CHECK(found(run) == all);
  // Forwards too, as a debugger does when it jumps to a later snapshot
  // from an earlier moment: the collisions found by then come back.
  const rs::runtime::RunSnapshot atEnd = run.snapshot();
  run.restore(after1);
  run.restore(atEnd);
  CHECK(found(run) == all);
  CHECK(run.snapshot() == atEnd);

  spec.collisions = rs::runtime::CollisionMode::Off;
  rs::runtime::Run unchecked(spec);
  REQUIRE(unchecked.runToEnd().ok());
  CHECK(unchecked.rig().collisionWatch() == nullptr);
  CHECK(unchecked.rig().collisions().empty());
}

TEST_CASE("a collision carries the instruction that moved, run in one go or step by step", "[collision][runtime]") {
  // Twice round a loop: down through the floor (instruction 1, from
  // 2.25125 s as above) and back up from below it (instruction 2, at once),
  // with instructions that do not move in between.
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  const rs::vm::Image image = rendertest::compileText(
      "        SET N 0\n"
      "loop:   MOVETO 0 0 2000 0\n"
      "        MOVETO 0 0 0 0\n"
      "        ADD N 1\n"
      "        JMPVAR N < 2 loop\n"
      "        END\n",
      cell);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.collisions = rs::runtime::CollisionMode::Warn;
  rs::runtime::Run whole(spec);
  REQUIRE(whole.runToEnd().ok());
  const auto all = found(whole);
  REQUIRE(all.size() == 4);
  CHECK(all[0].second == 1);
  CHECK(all[1].second == 2);
  CHECK(all[2].second == 1);
  CHECK(all[3].second == 2);

  rs::runtime::Run stepped(spec);
  for (int i = 0; i < 100 && !stepped.finished(); ++i) stepped.runUntil({.moreSteps = 1});
  REQUIRE(stepped.finished());
  CHECK(found(stepped) == all);

  // In error mode the first collision stops the run at its instruction.
  spec.collisions = rs::runtime::CollisionMode::Error;
  rs::runtime::Run stopped(spec);
  const rs::vm::RunOutcome outcome = stopped.runToEnd();
  CHECK(outcome.reason == rs::vm::StopReason::RuntimeError);
  CHECK(outcome.index == 1);
  REQUIRE(found(stopped).size() == 1);
  CHECK(found(stopped)[0] == all[0]);
}
