// The held-out case of issue 24: on every library workcell whose robot has
// five or six axes, a program takes a block off its pallet and lifts it
// straight up 50 length units, with collisions checked at their default
// (an error). With joint moves alone this failed on xr4-cell: the tool
// swung along a curve and the block hit the pallet 4 ms into a 10 mm lift.
//
// The program is written from the cell: the block a pallet carries, its
// centre (cx, cy, cz) and top; the tool pointing down, a joint move to 60
// above the grasp, a straight line down to it, the gripper closed there
// (a joint move that moves only the gripper), then DEPART 50.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include <fmt/format.h>

#include "../render/render_test_util.h"
#include "model/workcell/support.h"
#include "runtime/run/run.h"

namespace {

// Pause once this many instructions have run.
rs::runtime::RunUntil liftStepsUntil(std::uint64_t steps) {
  rs::runtime::RunUntil until;
  until.steps = steps;
  return until;
}

struct LiftCase {
  std::size_t block = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double top = 0;
};

// The first block that stands on a pallet.
LiftCase blockOnPallet(const rs::workcell::Workcell& cell) {
  for (std::size_t o = 0; o < cell.objects.size(); ++o) {
    const rs::workcell::PlacedObject& obj = cell.objects[o];
    if (obj.shape.name != "block") continue;
    const Eigen::AlignedBox3d box = rs::workcell::worldBoxOf(obj.shape, obj.F_world_design);
    const rs::workcell::Support s = rs::workcell::supportOf(box, cell.objects, o);
    if (s.kind != rs::workcell::Support::Kind::Object || cell.objects[s.object].shape.name != "pallet") continue;
    return {o, box.center(), box.max().y()};
  }
  FAIL("no block on a pallet in " << cell.name);
  return {};
}

void liftsStraightUp(const std::string& cellName) {
  const rs::workcell::Workcell cell = rendertest::cell(cellName);
  const LiftCase lift = blockOnPallet(cell);
  const rs::workcell::Robot& robot = cell.robots.front().robot;
  REQUIRE(robot.hasGripper);
  // The tool centre point 10 below the block's top, in its middle.
  const double x = lift.centre.x(), y = lift.top - 10, z = lift.centre.z();
  const std::string program = fmt::format(
      "; cell: {0}\n"
      "        MOVEP ABOVE\n"
      "        MOVES GRASP\n"
      "        MOVEP TAKE\n"
      "        DEPART 50\n"
      "        END\n"
      "POINTS\n"
      "ABOVE AT {1} {2} {3} APPROACH 0 -1 0 GRIP {5}\n"
      "GRASP AT {1} {4} {3} APPROACH 0 -1 0\n"
      "TAKE  AT {1} {4} {3} APPROACH 0 -1 0 GRIP {6}\n",
      cellName, x, y + 60, z, y, robot.gripper.min, robot.gripper.max);
  INFO(program);
  auto run = rendertest::runOf(rendertest::compileText(program, cell), &cell);
  const Eigen::Isometry3d before = run->rig().world()->objectPose(lift.block, run->rig().motors());
  REQUIRE(run->runUntil(liftStepsUntil(3)).paused());
  REQUIRE(run->rig().world()->held() == std::optional<std::size_t>(lift.block));
  const auto grasped = run->rig().tcp();
  const rs::vm::RunOutcome outcome = run->runToEnd();
  INFO(outcome.message);
  REQUIRE(outcome.ok());
  CHECK(run->rig().collisions().empty());
  const Eigen::Isometry3d after = run->rig().world()->objectPose(lift.block, run->rig().motors());
  const Eigen::Vector3d moved = after.translation() - before.translation();
  INFO("block moved by (" << moved.x() << ", " << moved.y() << ", " << moved.z() << ")");
  // Up 50, within the line's bound and the encoders' whole counts.
  CHECK(std::abs(moved.y() - 50) < 1.5);
  CHECK(std::abs(moved.x()) < 1.5);
  CHECK(std::abs(moved.z()) < 1.5);
  const auto lifted = run->rig().tcp();
  CHECK(std::abs((*lifted)[1] - (*grasped)[1] - 50) < 1.5);
}

}  // namespace

TEST_CASE("the library's workcells with a five- or six-axis arm are the five lifted below", "[runtime][straight]") {
  std::set<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(rendertest::kSourceDir + "/stdlib/workcells")) {
    if (entry.path().extension() != ".rsd") continue;
    const rs::workcell::Workcell cell = rendertest::cell(entry.path().stem().string());
    if (cell.robots.front().robot.joints.size() >= 5) found.insert(entry.path().stem().string());
  }
  CHECK(found == std::set<std::string>{"irb120-cell", "puma-cell", "rv-m1-cell", "scorobot-cell", "xr4-cell"});
}

TEST_CASE("xr4-cell: a block taken off its pallet and lifted straight up 50", "[runtime][straight][lift]") {
  liftsStraightUp("xr4-cell");
}
TEST_CASE("rv-m1-cell: a block taken off its pallet and lifted straight up 50", "[runtime][straight][lift]") {
  liftsStraightUp("rv-m1-cell");
}
TEST_CASE("scorobot-cell: a block taken off its pallet and lifted straight up 50", "[runtime][straight][lift]") {
  liftsStraightUp("scorobot-cell");
}
TEST_CASE("puma-cell: a block taken off its pallet and lifted straight up 50", "[runtime][straight][lift]") {
  liftsStraightUp("puma-cell");
}
TEST_CASE("irb120-cell: a block taken off its pallet and lifted straight up 50", "[runtime][straight][lift]") {
  liftsStraightUp("irb120-cell");
}
