// Objects in the gripper (DESIGN.md "Objects", model/workcell/grasp.h),
// on the library's gantry cell, where everything can be checked by hand:
// the gantry's motors are Cartesian, 0.1 mm per unit, so its tool centre
// point is (500 + X/10, 200 - Y/10, 400 + Z/10) (stdlib/robots/gantry.rsd,
// stdlib/workcells/gantry-cell.rsd), and a block placed AT x y z occupies
// x..x+40, y..y+40, z-40..z. The cell's objects: 0 pallet, 1 block
// (x 200..240, y 30..70, z 660..700), 2 block (x 280..320), 3 pallet.
#include <catch2/catch.hpp>

#include <optional>
#include <vector>

#include "../render/render_test_util.h"
#include "model/workcell/grasp.h"
#include "runtime/render/moment.h"
#include "runtime/run/run.h"

namespace {

using rs::runtime::GraspEvent;

// After every step: the motors, what the step did to the hold, and where
// each object is then.
struct StepView {
  std::vector<std::int32_t> motors;
  std::optional<GraspEvent> change;
  std::vector<Eigen::Vector3d> corner;  // each object's design origin in the world
};

class Collect final : public rs::vm::StepObserver {
 public:
  explicit Collect(const rs::runtime::Run& run) : run_(run) {}
  bool afterStep(const rs::vm::Interpreter& vm, std::uint32_t) override {
    StepView v;
    const auto pos = vm.machine().positions();
    v.motors.assign(pos.begin(), pos.end());
    const rs::runtime::World& world = *run_.rig().world();
    if (world.eventCount() != seen_) v.change = world.lastEvent();
    seen_ = world.eventCount();
    for (std::size_t o = 0; o < world.cell().objects.size(); ++o)
      v.corner.push_back(world.objectPose(o, pos) * Eigen::Vector3d::Zero());
    steps.push_back(v);
    return false;
  }
  std::vector<StepView> steps;

 private:
  const rs::runtime::Run& run_;
  std::uint64_t seen_ = 0;
};

std::vector<StepView> run(const rs::workcell::Workcell& cell, const std::string& program) {
  // Grasping alone: these moves hold the gantry's gripper at a block's
  // middle, where its fingers graze the pallet as they close (a collision).
  const auto r = rendertest::runOf(rendertest::compileText(program, cell), &cell, {}, false, rs::runtime::CollisionMode::Off);
  REQUIRE(r->rig().world());
  Collect collect(*r);
  r->observe(collect);
  const rs::vm::RunOutcome outcome = r->runToEnd();
  REQUIRE(outcome.ok());
  return collect.steps;
}

// The block's placement origin is its design (0, 0, 0): world (x, y, z - 40)
// for a block placed AT x y z.
Eigen::Vector3d block1At(double dx, double dy, double dz) { return {200 + dx, 30 + dy, 660 + dz}; }

void checkGraspNear(const Eigen::Vector3d& got, const Eigen::Vector3d& want) {
  INFO("got (" << got.x() << ", " << got.y() << ", " << got.z() << ") want (" << want.x() << ", " << want.y()
               << ", " << want.z() << ")");
  CHECK((got - want).norm() < 1e-6);
}

}  // namespace

TEST_CASE("the tool centre point of the gantry is where the hand formula says", "[runtime][grasp]") {
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  rs::workcell::ToolTracker tool(cell.robots.front());
  const std::vector<std::int32_t> motors = {-2800, 2800, 1500, 0};
  const Eigen::Isometry3d F = tool.frame(motors);
  checkGraspNear(F.translation(), {220, 50, 680});
  // The approach vector (z of the end-effector frame) points down, n along +x.
  checkGraspNear(F.linear().col(2), {0, -1, 0});
  checkGraspNear(F.linear().col(0), {1, 0, 0});
}

TEST_CASE("a closing gripper takes the block at its tool centre point and carries it", "[runtime][grasp]") {
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  const std::vector<StepView> s = run(cell,
                                      "MOVETO -2800 2800 1500 0\n"    // TCP (220, 50, 680): block 1's centre
                                      "MOVE 0 0 0 100\n"              // close
                                      "MOVETO -2800 2800 0 100\n"     // lift 150: TCP y 200
                                      "MOVETO 2300 -2200 0 100\n"     // carry: TCP (730, 200, 180)
                                      "MOVETO 2300 -2200 1500 100\n"  // lower: TCP (730, 50, 180)
                                      "MOVE 0 0 0 -100\n"             // open
                                      "MOVETO 0 0 0 0\n"              // away
                                      "END\n");
  REQUIRE(s.size() == 8);
  CHECK_FALSE(s[0].change);
  checkGraspNear(s[0].corner[1], block1At(0, 0, 0));
  REQUIRE(s[1].change);
  CHECK(s[1].change->object == 1);
  CHECK(s[1].change->held);
  checkGraspNear(s[1].corner[1], block1At(0, 0, 0));  // taking it does not move it
  checkGraspNear(s[2].corner[1], block1At(0, 150, 0));
  checkGraspNear(s[3].corner[1], block1At(510, 150, -500));
  checkGraspNear(s[4].corner[1], block1At(510, 0, -500));
  REQUIRE(s[5].change);
  CHECK(s[5].change->object == 1);
  CHECK_FALSE(s[5].change->held);
  checkGraspNear(s[6].corner[1], block1At(510, 0, -500));  // it stays where it was let go
  // Nothing else moved.
  for (const StepView& v : s) {
    checkGraspNear(v.corner[0], s[0].corner[0]);
    checkGraspNear(v.corner[2], s[0].corner[2]);
    checkGraspNear(v.corner[3], s[0].corner[3]);
  }
}

TEST_CASE("an empty gripper, a closed gripper pushed into a block, and RESET", "[runtime][grasp]") {
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  const std::vector<StepView> s = run(cell,
                                      "MOVE 0 0 0 100\n"             // closes at home, in the air: nothing
                                      "MOVETO -2800 2800 1500 100\n"  // closed, into block 1: not taken
                                      "MOVETO -2800 2800 1500 0\n"    // opens: holds nothing to let go
                                      "MOVETO -2800 2800 1500 80\n"  // closes there: taken
                                      "MOVETO 0 2800 0 80\n"         // carried: +280 x, +150 y
                                      "RESET\n"                      // everything back
                                      "MOVE 0 0 0 80\n"              // closes at home: nothing
                                      "MOVETO -2800 2800 1500 80\n"  // comes closed: nothing
                                      "END\n");
  REQUIRE(s.size() == 9);
  CHECK_FALSE(s[0].change);
  CHECK_FALSE(s[1].change);
  CHECK_FALSE(s[2].change);
  REQUIRE(s[3].change);
  CHECK(s[3].change->object == 1);
  checkGraspNear(s[4].corner[1], block1At(280, 150, 0));
  REQUIRE(s[5].change);  // RESET lets go
  CHECK_FALSE(s[5].change->held);
  checkGraspNear(s[5].corner[1], block1At(0, 0, 0));
  CHECK_FALSE(s[6].change);
  CHECK_FALSE(s[7].change);
  checkGraspNear(s[7].corner[1], block1At(0, 0, 0));
}

TEST_CASE("opening while moving lets go where the move starts, nested boxes give the smaller", "[runtime][grasp]") {
  rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  // A fifth object: a crate around block 1 (x 150..290, y 0..120, z 620..740).
  rs::workcell::PlacedObject crate;
  crate.shape.name = "crate";
  crate.shape.segments.push_back({{150, 0, 620}, {290, 120, 740}, rs::workcell::Color::White});
  crate.kind = rs::workcell::ObjectKind::Part;  // to be taken (an object is a fixture unless it says PART)
  cell.objects.push_back(crate);
  const std::vector<StepView> s = run(cell,
                                      "MOVETO -2800 2800 1500 0\n"
                                      "MOVE 0 0 0 100\n"          // inside block 1 and the crate: the block
                                      "MOVE 1000 0 -1000 -100\n"  // opens while moving: let go at the start
                                      "MOVETO -2500 2800 1000 100\n"  // TCP (250, 100, 680): the crate only
                                      "MOVE 0 0 -1000 0\n"            // lift the crate by 100
                                      "END\n");
  REQUIRE(s.size() == 6);
  REQUIRE(s[1].change);
  CHECK(s[1].change->object == 1);
  REQUIRE(s[2].change);
  CHECK_FALSE(s[2].change->held);
  checkGraspNear(s[2].corner[1], block1At(0, 0, 0));
  REQUIRE(s[3].change);
  CHECK(s[3].change->object == 4);
  CHECK_FALSE(s[4].change);
  // The crate is drawn in world coordinates (identity placement): its
  // origin moves with the lift, from (0, 0, 0) to (0, 100, 0).
  checkGraspNear(s[3].corner[4], {0, 0, 0});
  checkGraspNear(s[4].corner[4], {0, 100, 0});
  checkGraspNear(s[4].corner[1], block1At(0, 0, 0));
}

TEST_CASE("a still of a moment shows the block where the gripper has it then", "[runtime][grasp][render]") {
  // examples/gantry_pick.rsp; its timeline is derived in tests/examples/test_examples.cpp:
  //   4.6625 .. 5.1625  close on block 1 (taken at 5.1625, TCP (220, 51, 680))
  //   5.1625 .. 7.025   up: Y 1490 -> 0 at 800 u/s
  //   7.025  .. 12.025  MOVETO 1700 -2200 0 100: X -2800 -> 1700, Z 2800 -> -2200, both 1000 u/s
  //  13.8875 .. 14.3875 open (let go at 13.8875, TCP (670, 51, 180))
  // The block's design origin is its corner (x, y, z - 40) = TCP - (20, 21, 20) while held.
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  const rs::vm::Image image = rendertest::compile(rendertest::kSourceDir + "/examples/gantry_pick.rsp", cell);
  const auto blockAt = [&](double seconds) {
    const rs::render::Moment m =
        rs::render::momentOf(*rendertest::runOf(image, &cell), static_cast<rs::vm::Micros>(seconds * 1e6));
    REQUIRE(m.reached);
    REQUIRE(m.objects.size() == 4);
    checkGraspNear(m.objects[2] * Eigen::Vector3d::Zero(), {280, 30, 660});  // block 2 has not moved yet
    return Eigen::Vector3d(m.objects[1] * Eigen::Vector3d::Zero());
  };
  checkGraspNear(blockAt(5.0), block1At(0, 0, 0));    // closing: not taken yet
  checkGraspNear(blockAt(6.0), {200, 97, 660});       // 0.8375 s up: Y 820, TCP y 118
  checkGraspNear(blockAt(10.0), {497.5, 179, 362.5}); // 2.975 s along: X 175, Z -175: TCP (517.5, 200, 382.5)
  checkGraspNear(blockAt(14.0), {650, 30, 160});      // opening: let go at its start
  // Without a cell the moment has no objects.
  CHECK(rs::render::momentOf(*rendertest::runOf(image, nullptr), 10'000'000).objects.empty());
}

TEST_CASE("what is out of the cell is never taken and holds up nothing let go", "[runtime][grasp]") {
  // A feeder's empty slot is out of the cell (PlacedObject::inCell); here
  // block 1 and then pallet 0 stand in for one. Block 1 rests on pallet 0
  // (its bottom at y 30, the pallet's top); the floor is at y 0.
  rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  REQUIRE(cell.floor);
  cell.objects[1].inCell = false;
  rs::workcell::Grasping g(cell);
  CHECK(g.inCell() == std::vector<std::size_t>{0, 2, 3});
  const std::vector<std::int32_t> open = {-2800, 2800, 1500, 0}, closed = {-2800, 2800, 1500, 100};
  CHECK_FALSE(g.step(open, closed));  // at block 1's centre: nothing to take
  CHECK_FALSE(g.held());
  g.setInCell(1, true);
  CHECK(g.inCell() == std::vector<std::size_t>{0, 1, 2, 3});
  const auto take = g.step(open, closed);
  REQUIRE(take);
  CHECK(take->object == 1);
  CHECK(take->held);

  // Let go where it was taken: on the pallet while the pallet is in the
  // cell; onto the floor, 30 below, while it is not.
  const rs::workcell::Grasping::State holding = g.state();
  const auto onPallet = g.step(closed, open);
  REQUIRE(onPallet);
  CHECK(onPallet->settled.on == rs::workcell::Settled::On::Object);
  CHECK(onPallet->settled.support == 0);
  CHECK(onPallet->settled.drop == Approx(0).margin(1e-9));
  g.restore(holding);
  g.setInCell(0, false);
  const rs::workcell::Grasping::State palletOut = g.state();
  const auto onFloor = g.step(closed, open);
  REQUIRE(onFloor);
  CHECK(onFloor->settled.on == rs::workcell::Settled::On::Floor);
  CHECK(onFloor->settled.drop == Approx(30).margin(1e-9));

  // In the cell or not is part of the state: a restore brings it back, RESET
  // puts every object back as the cell places it.
  g.setInCell(0, true);
  g.restore(palletOut);
  CHECK(g.inCell() == std::vector<std::size_t>{1, 2, 3});
  CHECK_FALSE(g.state() == holding);
  g.reset();
  CHECK(g.inCell() == std::vector<std::size_t>{0, 2, 3});
}
