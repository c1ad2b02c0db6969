// The robot a run drives (Workcell::drivenRobot): the one place that says
// which of a cell's robots programs are compiled for, runs move and the
// world and the collision watch follow. For now the first placed.
#include <catch2/catch.hpp>

#include <utility>

#include "model/workcell/model.h"

TEST_CASE("the driven robot is the first placed, and none in a cell without robots", "[models]") {
  rs::workcell::Workcell cell;
  CHECK(cell.drivenRobot() == nullptr);
  CHECK(std::as_const(cell).drivenRobot() == nullptr);

  cell.robots.resize(2);
  cell.robots[0].robot.name = "first";
  cell.robots[1].robot.name = "second";
  REQUIRE(cell.drivenRobot() != nullptr);
  CHECK(cell.drivenRobot() == &cell.robots[cell.drivenRobotIndex()]);
  CHECK(cell.drivenRobot()->robot.name == "first");
  CHECK(std::as_const(cell).drivenRobot()->robot.name == "first");
}
