// Parts and fixtures, and where a part rests (issue 35), run on the
// library's xr4-cell: 0 table (top y 750), 1 pallet (deck top y 780),
// 2 block (x 220..260, y 780..820, z -60..-20, centre (240, 800, -40)),
// 3 block (z 20..60). The gripper points down and takes block 2 with its
// tool centre point 10 below the block's top (y 810); its fingers reach
// 10.7 below the tool centre point and open 48 wide (rhino-xr4.rsd).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "../render/render_test_util.h"
#include "base/number_text.h"
#include "launch/run_diagnostics.h"
#include "model/workcell/collision_model.h"
#include "model/workcell/tool_tracker.h"
#include "runtime/run/placing.h"
#include "runtime/run/trace.h"

namespace {

const std::string kPlacingPoints =
    "POINTS\n"
    "ABOVE   AT 240 870 -40 APPROACH 0 -1 0 GRIP 0\n"
    "GRASP   AT 240 810 -40 APPROACH 0 -1 0 GRIP 0\n"
    "TAKE    AT 240 810 -40 APPROACH 0 -1 0 GRIP 115\n";

constexpr std::size_t kPlacingBlock = 2;  // object 3

// Take block 2, lift it `lift` straight up, open the gripper there.
std::string dropProgram(int lift) {
  return fmt::format(
      "; cell: xr4-cell\n"
      "        MOVEP ABOVE\n"
      "        APPRO 60\n"
      "        MOVEP TAKE\n"
      "        DEPART {}\n"
      "        MOVE 0 0 0 0 0 -115\n"
      "        END\n",
      lift) + kPlacingPoints;
}

// Stops just before the opening move (instruction 5) to see where the
// block is as it is let go.
class BeforeOpening final : public rs::vm::StepObserver {
 public:
  explicit BeforeOpening(const rs::runtime::Run& run) : run_(run) {}
  bool afterStep(const rs::vm::Interpreter& vm, std::uint32_t index) override {
    if (index == 3) {  // DEPART done
      const rs::runtime::World& w = *run_.rig().world();
      const Eigen::Isometry3d pose = w.objectPose(kPlacingBlock, vm.machine().positions());
      // The lowest of its corners (block.rsd: x, y, z 0..40), however the arm's counts turned it.
      bottom = INFINITY;
      for (int c = 0; c < 8; ++c)
        bottom = std::min(bottom, (pose * Eigen::Vector3d(c & 1 ? 40 : 0, c & 2 ? 40 : 0, c & 4 ? 40 : 0)).y());
    }
    return false;
  }
  double bottom = 0;

 private:
  const rs::runtime::Run& run_;
};

}  // namespace

TEST_CASE("a block let go 30 above the pallet drops onto it, and the run warns in the issue's words",
          "[runtime][placing]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  auto run = rendertest::runOf(rendertest::compileText(dropProgram(30), cell), &cell);
  BeforeOpening before(*run);
  run->observe(before);
  const rs::vm::RunOutcome outcome = run->runToEnd();
  INFO(outcome.message);
  REQUIRE(outcome.ok());
  CHECK(run->rig().collisions().empty());
  const rs::runtime::World& world = *run->rig().world();
  // The drop is how far the block's bottom was above the deck's top (780)
  // when it was let go: 30, give or take the arm's rounding to counts.
  const double drop = before.bottom - 780;
  CHECK(drop == Approx(30).margin(1));
  REQUIRE(world.restOf(kPlacingBlock));
  const rs::runtime::GraspEvent& e = *world.restOf(kPlacingBlock);
  CHECK(e.on == rs::workcell::Settled::On::Object);
  CHECK(e.support == 1);
  CHECK(e.drop == Approx(drop).margin(1e-9));
  CHECK(world.objectPose(kPlacingBlock, run->rig().motors()).translation().y() == Approx(780).margin(1e-9));
  CHECK(world.longDropCount() == 1);
  const std::vector<rs::diag::Diagnostic> w = rs::runtime::placingWarnings(*run, "drop.rsp");
  REQUIRE(w.size() == 1);
  CHECK(w[0].severity == rs::diag::Severity::Warning);
  CHECK(w[0].code == "part-dropped");
  CHECK(w[0].pos.line == 6);  // the MOVE that opens
  CHECK(w[0].message == fmt::format("block (object 3) dropped {} onto pallet (object 2): it was let go above it",
                                    rs::base::formatNumber(drop, 2)));
  // The run's diagnostics, which check and check --strict print, carry it.
  const auto said = rs::launch::runDiagnostics(*run, rs::runtime::CollisionMode::Error, "drop.rsp");
  CHECK(std::count_if(said.begin(), said.end(), [](const rs::diag::Diagnostic& d) { return d.code == "part-dropped"; }) == 1);
}

TEST_CASE("a block put back down where it was taken settles on the pallet with no drop and no warning",
          "[runtime][placing]") {
  // MOVES TAKE goes back to the counts it was taken at: its bottom on the deck.
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const std::string program =
      "; cell: xr4-cell\n"
      "        MOVEP ABOVE\n"
      "        APPRO 60\n"
      "        MOVEP TAKE\n"
      "        DEPART 50\n"
      "        MOVES TAKE\n"
      "        MOVEP GRASP\n"
      "        DEPART 60\n"
      "        END\n" + kPlacingPoints;
  auto run = rendertest::runOf(rendertest::compileText(program, cell), &cell);
  const rs::vm::RunOutcome outcome = run->runToEnd();
  INFO(outcome.message);
  REQUIRE(outcome.ok());
  CHECK(run->rig().collisions().empty());
  const rs::runtime::World& world = *run->rig().world();
  REQUIRE(world.restOf(kPlacingBlock));
  CHECK(world.restOf(kPlacingBlock)->support == 1);
  CHECK(std::abs(world.restOf(kPlacingBlock)->drop) < 1e-6);  // put back at the counts it was taken at
  CHECK(world.longDropCount() == 0);
  CHECK(rs::runtime::placingWarnings(*run, "put.rsp").empty());
}

TEST_CASE("a gripper closing round a fixture takes nothing and says so", "[runtime][placing]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  // The tool centre point in the table's box (x -400..400, y 0..750, z
  // -250..250), under its top, clear of the pallet: only the table (a
  // fixture) holds it. The fingers are in the table top: collisions off.
  const std::string program =
      "; cell: xr4-cell\n"
      "        MOVEP LOW\n"
      "        MOVE 0 0 0 0 0 115\n"
      "        MOVEP HIGH\n"
      "        END\n"
      "POINTS\n"
      "LOW     AT 0 745 200 APPROACH 0 -1 0 GRIP 0\n"
      "HIGH    AT 0 900 200 APPROACH 0 -1 0\n";
  auto run = rendertest::runOf(rendertest::compileText(program, cell), &cell, {}, false,
                               rs::runtime::CollisionMode::Off);
  std::ostringstream trace;
  rs::runtime::TraceWriter writer(trace, rs::runtime::TraceFormat::Text, *run);
  run->observe(writer);
  REQUIRE(run->runToEnd().ok());
  const rs::runtime::World& world = *run->rig().world();
  CHECK(world.takeCount() == 0);
  CHECK(!world.held());
  CHECK(world.fixtureCloseCount() == 1);
  CHECK(world.lastEmptyClose().fixture == std::optional<std::size_t>(0));
  // The table did not move.
  CHECK(world.objectPose(0, run->rig().motors()).matrix() == cell.objects[0].F_world_design.matrix());
  CHECK_THAT(trace.str(), Catch::Contains("closes round table (object 1), a fixture: takes nothing"));
  const std::vector<rs::diag::Diagnostic> w = rs::runtime::placingWarnings(*run, "fixture.rsp");
  REQUIRE(w.size() == 1);
  CHECK(w[0].code == "gripper-closed-on-fixture");
  CHECK(w[0].pos.line == 3);
  CHECK_THAT(w[0].message, Catch::Contains("table (object 1), a fixture"));
}

TEST_CASE("a carried block put 0.16 into the pallet rests on it, 0.6 into it collides", "[runtime][placing]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  rs::workcell::CollisionModel model(cell);
  rs::workcell::CollisionData data(model);
  rs::workcell::ToolTracker tool(cell.robots.front());
  const std::vector<std::int32_t> home(6, 0);
  const Eigen::Isometry3d F_world_E = tool.frame(home);
  std::vector<Eigen::Isometry3d> poses;
  for (const rs::workcell::PlacedObject& o : cell.objects) poses.push_back(o.F_world_design);
  const auto blockContacts = [&](double down) {
    rs::workcell::CollisionQuery q;
    q.objectPoses = poses;
    q.held = kPlacingBlock;
    // Carried where it stands, `down` lower.
    q.heldOffset = F_world_E.inverse() * (Eigen::Translation3d(0, -down, 0) * cell.objects[kPlacingBlock].F_world_design);
    int n = 0;
    for (const rs::workcell::Contact& c : data.allContacts(home, q))
      if (c.a.kind == rs::workcell::BodyKind::Object && c.a.index == static_cast<int>(kPlacingBlock)) {
        CHECK(c.b.kind == rs::workcell::BodyKind::Object);
        CHECK(c.b.index == 1);  // the pallet
        ++n;
      }
    return n;
  };
  CHECK(blockContacts(0) == 0);     // touching: resting on it
  CHECK(blockContacts(0.16) == 0);  // within the rest tolerance (0.5)
  CHECK(blockContacts(0.45) == 0);
  CHECK(blockContacts(0.6) == 1);   // pushed into it
}

namespace {

// The verdict of going down from ABOVE (60 over the grasp) to the grasp
// with `appro` (one APPRO or several), then closing: the collisions' first
// contact as text, or "" for none.
std::string approVerdict(const rs::workcell::Workcell& cell, const std::string& appro) {
  const std::string program = "; cell: xr4-cell\n        MOVEP ABOVE\n" + appro +
                              "        MOVEP TAKE\n        END\n" + kPlacingPoints;
  auto run = rendertest::runOf(rendertest::compileText(program, cell), &cell, {}, false,
                               rs::runtime::CollisionMode::Warn);
  REQUIRE(run->runToEnd().ok());
  const auto events = run->rig().collisions();
  if (events.empty()) {
    CHECK(run->rig().world()->held() == std::optional<std::size_t>(kPlacingBlock));
    return "";
  }
  return run->rig().collisionWatch()->describe(events.front().contact);
}

// Block 2 made 1.5 times as wide in x and z about its centre (60 wide):
// wider than the XR-4's fingers open (48).
rs::workcell::Workcell withWideBlock() {
  rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  rs::workcell::Shape& s = cell.objects[kPlacingBlock].shape;
  const auto widen = [](Eigen::Vector3d& p) { p.x() = 20 + 1.5 * (p.x() - 20), p.z() = 20 + 1.5 * (p.z() - 20); };
  for (rs::workcell::Segment& seg : s.segments) widen(seg.a), widen(seg.b);
  for (rs::workcell::ConvexPiece& piece : s.collision)
    for (Eigen::Vector3d& p : piece.points) widen(p);
  return cell;
}

}  // namespace

TEST_CASE("honest grasping: APPRO 60 and APPRO 45 then APPRO 15 get the same verdict", "[runtime][placing][collision]") {
  const std::string oneMove = "        APPRO 60\n";
  const std::string twoMoves = "        APPRO 45\n        APPRO 15\n";
  // The library's block between fingers that open 48 wide: both clear it.
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  CHECK(approVerdict(cell, oneMove).empty());
  CHECK(approVerdict(cell, twoMoves).empty());
  // A block 60 wide: a finger comes down onto it either way. (Before, the
  // part holding the tool centre point at a move's end was exempt: APPRO
  // 60 passed, and APPRO 45, which ends 5 above the block's top with the
  // fingertips 5.7 into it, collided.)
  const rs::workcell::Workcell wide = withWideBlock();
  const std::string one = approVerdict(wide, oneMove), two = approVerdict(wide, twoMoves);
  CHECK_THAT(one, Catch::Contains("hits object 3 (block)"));
  CHECK_THAT(one, Catch::Contains("finger"));
  CHECK(one == two);
}
