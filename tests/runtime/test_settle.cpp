// Where a released part settles (model/workcell/settle.h), computed by
// hand from the library's drawings: xr4-cell (stdlib/workcells/xr4-cell.rsd)
// has 0 table (x -400..400, z -250..250, top y 750), 1 pallet (x 150..390,
// z -80..80, deck top y 780), 2 block (x 220..260, y 780..820, z -60..-20),
// 3 block (z 20..60); a block is a 40 cube (stdlib/objects/block.rsd).
#include <catch2/catch.hpp>

#include <vector>

#include "../render/render_test_util.h"
#include "model/workcell/settle.h"

namespace {

using rs::workcell::Settled;

std::vector<Eigen::Isometry3d> settlePoses(const rs::workcell::Workcell& cell) {
  std::vector<Eigen::Isometry3d> poses;
  for (const rs::workcell::PlacedObject& o : cell.objects) poses.push_back(o.F_world_design);
  return poses;
}

// Block 2 moved by (dx, dy, dz) from where the cell placed it.
Eigen::Isometry3d block2Moved(const rs::workcell::Workcell& cell, double dx, double dy, double dz) {
  return Eigen::Translation3d(dx, dy, dz) * cell.objects[2].F_world_design;
}

}  // namespace

TEST_CASE("settle: a block let go 29.7 above the pallet's deck drops 29.7 onto the pallet", "[runtime][settle]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const Settled s = rs::workcell::settle(cell, settlePoses(cell), 2, block2Moved(cell, 0, 29.7, 0));
  CHECK(s.on == Settled::On::Object);
  CHECK(s.support == 1);
  CHECK(s.drop == Approx(29.7));
  // Back where it stood: its bottom on the deck top, y 780.
  CHECK((s.pose.translation() - cell.objects[2].F_world_design.translation()).norm() < 1e-9);
}

TEST_CASE("settle: let go resting on its support, a part stays bit for bit where it is", "[runtime][settle]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const Settled s = rs::workcell::settle(cell, settlePoses(cell), 2, cell.objects[2].F_world_design);
  CHECK(s.on == Settled::On::Object);
  CHECK(s.support == 1);
  CHECK(s.drop == 0);
  CHECK(s.pose.matrix() == cell.objects[2].F_world_design.matrix());
}

TEST_CASE("settle: a block let go 0.16 into the pallet is lifted onto it, 0.6 into it is not", "[runtime][settle]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const Settled in = rs::workcell::settle(cell, settlePoses(cell), 2, block2Moved(cell, 0, -0.16, 0));
  CHECK(in.on == Settled::On::Object);
  CHECK(in.support == 1);
  CHECK(in.drop == Approx(-0.16));
  CHECK(in.pose.translation().y() == Approx(cell.objects[2].F_world_design.translation().y()));
  // 0.6 in, more than the rest tolerance (0.5; a carried part that deep has
  // collided on the way): still lifted out onto the deck, whose top is
  // below the block's middle.
  const Settled deep = rs::workcell::settle(cell, settlePoses(cell), 2, block2Moved(cell, 0, -0.6, 0));
  CHECK(deep.on == Settled::On::Object);
  CHECK(deep.support == 1);
  CHECK(deep.drop == Approx(-0.6));
}

TEST_CASE("settle: over the bare table a block drops onto the table, beside it onto the floor", "[runtime][settle]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  // Centre x -380, z -230 (the free spot), bottom at y 800: 50 above the top (750).
  const Settled table = rs::workcell::settle(cell, settlePoses(cell), 2, block2Moved(cell, -620, 20, -190));
  CHECK(table.on == Settled::On::Object);
  CHECK(table.support == 0);
  CHECK(table.drop == Approx(50));
  // x 620..660, beyond the table's 400: down to the floor (y 0) from 800.
  const Settled floor = rs::workcell::settle(cell, settlePoses(cell), 2, block2Moved(cell, 400, 20, 0));
  CHECK(floor.on == Settled::On::Floor);
  CHECK(floor.drop == Approx(800));
  CHECK(floor.pose.translation().y() == Approx(0));
}

TEST_CASE("settle: a block let go over another block lands on it", "[runtime][settle]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  // Over block 3 (z 20..60, top y 820), its bottom at 830.
  const Settled s = rs::workcell::settle(cell, settlePoses(cell), 2, block2Moved(cell, 0, 50, 80));
  CHECK(s.on == Settled::On::Object);
  CHECK(s.support == 3);
  CHECK(s.drop == Approx(10));
}

TEST_CASE("settle: over a conveyor a block lands on its belt, with FLOOR NONE and nothing under it it stays",
          "[runtime][settle]") {
  rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  // adept-cell: 0 infeed conveyor (belt top y 500), 1 block AT 0 500 620.
  REQUIRE(cell.objects[0].belt);
  const Eigen::Isometry3d up = Eigen::Translation3d(0, 12.5, 0) * cell.objects[1].F_world_design;
  const Settled s = rs::workcell::settle(cell, settlePoses(cell), 1, up);
  CHECK(s.on == Settled::On::Belt);
  CHECK(s.support == 0);
  CHECK(s.drop == Approx(12.5));
  // Far beside the conveyors, no floor: nothing under it.
  cell.floor.reset();
  const Eigen::Isometry3d aside = Eigen::Translation3d(3000, 100, 0) * cell.objects[1].F_world_design;
  const Settled none = rs::workcell::settle(cell, settlePoses(cell), 1, aside);
  CHECK(none.on == Settled::On::Nothing);
  CHECK(none.drop == 0);
  CHECK(none.pose.matrix() == aside.matrix());
}

// settle's reach (settleReach): passing over the objects too far aside to
// hold the part up changes no answer. Against the same call without it, for
// let-gos over the whole cell (on the table, the pallet, a block, beside
// them, over nothing), each object's reach checked by its pieces' points.
TEST_CASE("settle: the objects' reach passes over only what could not hold the part up", "[runtime][settle]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const std::vector<Eigen::Isometry3d> poses = settlePoses(cell);
  std::vector<double> reach;
  for (const rs::workcell::PlacedObject& o : cell.objects) {
    reach.push_back(rs::workcell::settleReach(o));
    for (const rs::workcell::ConvexPiece& piece : o.shape.collision)
      for (const Eigen::Vector3d& p : piece.points) CHECK(p.norm() <= reach.back());
  }
  int compared = 0, onSomething = 0;
  for (double dx = -700; dx <= 300; dx += 37)
    for (double dz = -400; dz <= 300; dz += 41) {
      const Eigen::Isometry3d at = block2Moved(cell, dx, 15, dz);
      const Settled plain = rs::workcell::settle(cell, poses, 2, at);
      const Settled quick = rs::workcell::settle(cell, poses, 2, at, std::nullopt, reach);
      CAPTURE(dx, dz);
      CHECK(quick == plain);
      ++compared;
      onSomething += plain.on == Settled::On::Object;
    }
  CHECK(compared > 400);
  CHECK(onSomething > 20);  // the let-gos land on the table, the pallet, a block: the check can fail
}
