// The world's record of which objects it set a resting pose for
// (World::restMayDifferSince, runtime/cell/world.h): the sweep's places
// and the devices' part boxes look only at the objects it names, so an
// object it leaves out must be bit for bit where it was.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

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

TEST_CASE("the world's log names the objects it set a rest for since a revision, in index order", "[world][cell]") {
  const rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  REQUIRE(cell.objects.size() >= 4);
  rs::runtime::World world(cell);
  const std::uint64_t start = world.revision();
  std::vector<std::size_t> named;
  REQUIRE(world.restChangedSince(start, named));
  CHECK(named.empty());

  const auto nudge = [&](std::size_t o) {
    Eigen::Isometry3d p = world.restingPose(o);
    p.translation().z() += 1;
    world.place(o, p);
  };
  nudge(3);
  nudge(1);
  const std::uint64_t middle = world.revision();
  nudge(3);
  REQUIRE(world.restChangedSince(start, named));
  CHECK(named == std::vector<std::size_t>{1, 3});  // each once, in index order
  REQUIRE(world.restChangedSince(middle, named));
  CHECK(named == std::vector<std::size_t>{3});
  // Checked against the per-object record.
  for (const std::uint64_t since : {start, middle, world.revision()}) {
    REQUIRE(world.restChangedSince(since, named));
    for (std::size_t o = 0; o < cell.objects.size(); ++o)
      CHECK(world.restMayDifferSince(o, since) == (std::find(named.begin(), named.end(), o) != named.end()));
  }

  // A restore may set every rest: the log does not go back past it.
  const std::uint64_t before = world.revision();
  world.restore(world.state());
  CHECK_FALSE(world.restChangedSince(before, named));
  REQUIRE(world.restChangedSince(world.revision(), named));
  CHECK(named.empty());

  // A long run: the log keeps its latest half, and says when it no longer reaches back.
  const std::uint64_t longAgo = world.revision();
  for (int i = 0; i < 5000; ++i) nudge(static_cast<std::size_t>(i % 2));
  CHECK_FALSE(world.restChangedSince(longAgo, named));
  const std::uint64_t recent = world.revision();
  nudge(2);
  REQUIRE(world.restChangedSince(recent, named));
  CHECK(named == std::vector<std::size_t>{2});
}
