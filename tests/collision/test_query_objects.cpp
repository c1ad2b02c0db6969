// The objects a collision query checks (CollisionQuery::inCell,
// model/workcell/collision_model.h): a feeder's empty slots are out of the
// cell, and nothing collides with them; another robot's parts, listed after
// the cell's objects, are always checked.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "../render/render_test_util.h"
#include "model/workcell/collision_model.h"
#include "model/workcell/tool_tracker.h"

TEST_CASE("a collision query visits the listed objects of the cell, then every other one, in order", "[collision]") {
  const std::vector<std::size_t> listed = {0, 2, 5};
  rs::workcell::CollisionQuery q;
  const auto visited = [&](std::size_t count, std::size_t stopAt) {
    std::vector<std::size_t> seen;
    const bool stopped = q.anyObject(count, [&](std::size_t o) {
      seen.push_back(o);
      return o == stopAt;
    });
    CHECK(stopped == (std::find(seen.begin(), seen.end(), stopAt) != seen.end()));
    return seen;
  };
  CHECK(visited(4, 99) == std::vector<std::size_t>{0, 1, 2, 3});  // no list: every object
  q.inCell = &listed, q.cellObjects = 6;
  CHECK(visited(6, 99) == std::vector<std::size_t>{0, 2, 5});
  CHECK(visited(9, 99) == std::vector<std::size_t>{0, 2, 5, 6, 7, 8});  // 6..8: another robot's parts
  CHECK(visited(9, 2) == std::vector<std::size_t>{0, 2});                // stops at the first true
  CHECK(visited(9, 7) == std::vector<std::size_t>{0, 2, 5, 6, 7});
  CHECK(visited(3, 99) == std::vector<std::size_t>{0, 2});  // fewer objects than the list names
}

TEST_CASE("a carried block pushed into the pallet collides with it only while the pallet is in the cell", "[collision]") {
  // xr4-cell: the block (object 2) rests on the pallet (object 1), as in
  // tests/runtime/test_placing.cpp; carried 5 lower than it rests, it is in the pallet.
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  REQUIRE(cell.objects.size() >= 3);
  constexpr std::size_t kBlock = 2, kPallet = 1;
  rs::workcell::CollisionModel model(cell);
  rs::workcell::CollisionData data(model);
  rs::workcell::ToolTracker tool(cell.robots.front());
  const std::vector<std::int32_t> home(6, 0);
  std::vector<Eigen::Isometry3d> poses;
  for (const rs::workcell::PlacedObject& o : cell.objects) poses.push_back(o.F_world_design);
  rs::workcell::CollisionQuery q;
  q.objectPoses = poses;
  q.held = kBlock;
  q.heldOffset = tool.frame(home).inverse() * (Eigen::Translation3d(0, -5, 0) * cell.objects[kBlock].F_world_design);
  const auto palletContacts = [&] {
    int n = 0;
    for (const rs::workcell::Contact& c : data.allContacts(home, q))
      n += c.b.kind == rs::workcell::BodyKind::Object && c.b.index == static_cast<int>(kPallet);
    return n;
  };
  CHECK(palletContacts() == 1);
  std::vector<std::size_t> inCell;
  for (std::size_t o = 0; o < cell.objects.size(); ++o)
    if (o != kPallet) inCell.push_back(o);
  q.inCell = &inCell, q.cellObjects = cell.objects.size();
  CHECK(palletContacts() == 0);
  inCell.insert(inCell.begin() + static_cast<std::ptrdiff_t>(kPallet), kPallet);
  CHECK(palletContacts() == 1);
}
