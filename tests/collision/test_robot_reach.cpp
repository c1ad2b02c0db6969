// Issue 36: a robot that can never reach the moving one is left out of its
// swept check (runtime/run/robot_obstacles.h). The XR-4's reach bound must
// hold its farthest point at home: the wrist box's corner (258.1, 509, 25)
// from the base frame's origin (the design origin, stdlib/robots/rhino-xr4.rsd),
// sqrt(258.1^2 + 509^2 + 25^2) = 571.25 away.
#include <catch2/catch.hpp>

#include <optional>
#include <string>

#include "../render/render_test_util.h"
#include "compiler/description/library.h"
#include "model/workcell/collision_model.h"
#include "runtime/run/robot_obstacles.h"

namespace {

rs::workcell::Workcell twoXr4Apart(int x) {
  const rs::testing::TempDir dir;
  const std::string file = dir.write("two.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left\n  ROBOT rhino-xr4 AT " +
                                                    std::to_string(x) + " 750 0 AS right\nEND\n");
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> cell = library.workcell(file);
  REQUIRE(cell);
  return *cell;
}

}  // namespace

TEST_CASE("robot reach: a bound on every point of the arm, and robots out of each other's reach are no obstacles",
          "[collision][robots]") {
  const rs::workcell::Workcell near = twoXr4Apart(600);
  const rs::workcell::CollisionModel model(near, 0);
  CHECK(model.reach() >= 571.25);
  // Not much more: the frames' distances (260.4, 228.6, 228.6, 9.5, each
  // joint's D-H translation bounded as though straight) and each part's
  // reach from its frame add up to about 1050.
  CHECK(model.reach() < 1100);
  CHECK(model.baseOrigin().x() == Approx(0).margin(1e-9));
  CHECK(model.baseOrigin().y() == Approx(750).margin(1e-9));
  // No part in the cell: nothing carried adds to it.
  CHECK(rs::workcell::carriedReach(near) == 0);
  CHECK(rs::runtime::RobotObstacles(near, 0).any());
  // 3000 apart: more than twice the reach.
  const rs::workcell::Workcell far = twoXr4Apart(3000);
  CHECK_FALSE(rs::runtime::RobotObstacles(far, 0).any());
  CHECK_FALSE(rs::runtime::RobotObstacles(far, 1).any());
}
