// The world's record of which objects it set a resting pose for
// (World::restMayDifferSince, runtime/cell/world.h): the sweep's places
// and the devices' part boxes look only at the objects it names, so an
// object it leaves out must be bit for bit where it was.
#include <catch2/catch.hpp>

#include "runtime/cell/world.h"
#include "../render/render_test_util.h"

TEST_CASE("the world names the objects whose resting pose it set since a revision", "[world][cell]") {
  const rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  REQUIRE(cell.objects.size() >= 3);
  rs::runtime::World world(cell);
  const std::uint64_t start = world.revision();
  for (std::size_t o = 0; o < cell.objects.size(); ++o) CHECK_FALSE(world.restMayDifferSince(o, start));

  Eigen::Isometry3d moved = world.restingPose(1);
  moved.translation().x() += 10;
  world.place(1, moved);
  CHECK(world.restMayDifferSince(1, start));
  CHECK_FALSE(world.restMayDifferSince(0, start));
  CHECK_FALSE(world.restMayDifferSince(2, start));
  // Since the place, nothing: the record is by revision, not "ever".
  CHECK_FALSE(world.restMayDifferSince(1, world.revision()));

  // A restore may set every pose: every object is named.
  const rs::runtime::World::State state = world.state();
  const std::uint64_t before = world.revision();
  world.restore(state);
  for (std::size_t o = 0; o < cell.objects.size(); ++o) CHECK(world.restMayDifferSince(o, before));
}
