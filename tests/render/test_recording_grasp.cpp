// Grasps in a recorded run and in the animation page's model: the gantry
// pick-and-place of tests/runtime/test_grasp.cpp, checked by hand.
//
// Times: the gantry's motors X, Z (1000 units/s), Y (800 units/s) and the
// gripper A (200 units/s) move together; a step lasts as long as its
// slowest motor (SimMachine: ceil(|delta| · 1 s / speed), exact here).
// Poses: the tool centre point is (500 + X/10, 200 - Y/10, 400 + Z/10);
// the end-effector frame's axes are n = x_E = +x, a = z_E = -y, so
// y_E = z_E × x_E = +z; block 1 (object 1) is placed by a translation to
// its design origin (200, 30, 660).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "render_test_util.h"
#include "runtime/run/run_log.h"

using rs::runtime::RunLog;
using rs::vm::Micros;

namespace {

constexpr Micros kMs = 1'000;

const char* const kPickAndPlace =
    "MOVETO -2800 2800 1500 0\n"    // 0: X, Z 2800 (2.8 s), Y 1500 (1.875 s): 0 .. 2.8 s
    "MOVE 0 0 0 100\n"              // 1: A 100 (0.5 s): 2.8 .. 3.3 s, takes block 1 at 3.3 s
    "MOVETO -2800 2800 0 100\n"     // 2: Y 1500 (1.875 s): 3.3 .. 5.175 s
    "MOVETO 2300 -2200 0 100\n"     // 3: X 5100 (5.1 s), Z 5000 (5 s): 5.175 .. 10.275 s
    "MOVETO 2300 -2200 1500 100\n"  // 4: Y 1500: 10.275 .. 12.15 s
    "MOVE 0 0 0 -100\n"             // 5: A 100: 12.15 .. 12.65 s, lets go at 12.15 s
    "MOVETO 0 0 0 0\n"              // 6: X 2300 (2.3 s): 12.65 .. 14.95 s
    "END\n";

// The run's log, on the gantry cell (or, without grasps, on no workcell:
// the same motors, no world).
RunLog record(const std::string& program, bool withGrasps) {
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  // The gripper held at a block's middle grazes the pallet (a collision):
  // this test is about the log of grasps only.
  const auto run = rendertest::runOf(rendertest::compileText(program, cell), withGrasps ? &cell : nullptr, {}, true,
                                     rs::runtime::CollisionMode::Off);
  REQUIRE(run->runToEnd().ok());
  return *run->log();
}

void checkNear(const Eigen::Matrix4d& got, const Eigen::Matrix4d& want) {
  INFO("got\n" << got << "\nwant\n" << want);
  CHECK((got - want).norm() < 1e-9);
}

Eigen::Matrix4d translation(double x, double y, double z) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.col(3).head<3>() << x, y, z;
  return m;
}

// F_E_object for block 1 taken with the tool centre point at (220, 50, 680):
// R_E_world = R_world_E^T has the rows x_E = (1, 0, 0), y_E = (0, 0, 1),
// z_E = (0, -1, 0); the block's origin relative to the tool centre point is
// (200, 30, 660) - (220, 50, 680) = (-20, -20, -20), in frame E (-20, -20, 20).
Eigen::Matrix4d blockInHand() {
  Eigen::Matrix4d m;
  m << 1, 0, 0, -20,  //
      0, 0, 1, -20,   //
      0, -1, 0, 20,   //
      0, 0, 0, 1;
  return m;
}

}  // namespace

TEST_CASE("a recorded run keeps what the gripper took and let go, when and where", "[render][grasp]") {
  const RunLog rec = record(kPickAndPlace, true);
  REQUIRE(rec.steps.size() == 8);
  CHECK(rec.steps[1].end == 3300 * kMs);
  CHECK(rec.steps[5].start == 12150 * kMs);
  REQUIRE(rec.grasps.size() == 2);
  const rs::runtime::GraspEvent& take = rec.grasps[0].event;
  CHECK(rec.grasps[0].step == 1);
  CHECK(take.at == 3300 * kMs);  // the end of the closing move
  CHECK(take.object == 1);
  CHECK(take.held);
  checkNear(take.pose.matrix(), blockInHand());
  const rs::runtime::GraspEvent& release = rec.grasps[1].event;
  CHECK(rec.grasps[1].step == 5);
  CHECK(release.at == 12150 * kMs);  // the start of the opening move
  CHECK(release.object == 1);
  CHECK_FALSE(release.held);
  // Carried +150 up (y), +510 in x and -500 in z, then lowered 150: where
  // the block rests, translated only (the gantry never turns it).
  checkNear(release.pose.matrix(), translation(710, 30, 160));
}

TEST_CASE("RESET lets go at its instant and puts the object back", "[render][grasp]") {
  const RunLog rec = record(
      "MOVE 0 0 0 100\n"              // 0: closes in the air (0.5 s): nothing
      "MOVETO -2800 2800 1500 100\n"  // 1: 0.5 .. 3.3 s, closed into block 1: not taken
      "MOVETO -2800 2800 1500 0\n"    // 2: opens, 3.3 .. 3.8 s: nothing to let go
      "MOVETO -2800 2800 1500 80\n"   // 3: closes, A 80 (0.4 s): 3.8 .. 4.2 s, taken at 4.2 s
      "MOVETO 0 2800 0 80\n"          // 4: X 2800 (2.8 s): 4.2 .. 7 s
      "RESET\n"                       // 5: at 7 s, everything back
      "END\n",
      true);
  REQUIRE(rec.grasps.size() == 2);
  CHECK(rec.grasps[0].step == 3);
  CHECK(rec.grasps[0].event.at == 4200 * kMs);
  CHECK(rec.grasps[0].event.object == 1);
  CHECK(rec.grasps[0].event.held);
  checkNear(rec.grasps[0].event.pose.matrix(), blockInHand());
  CHECK(rec.grasps[1].step == 5);
  CHECK(rec.grasps[1].event.at == 7000 * kMs);
  CHECK(rec.grasps[1].event.object == 1);
  CHECK_FALSE(rec.grasps[1].event.held);
  checkNear(rec.grasps[1].event.pose.matrix(), translation(200, 30, 660));  // its placement
}

TEST_CASE("a run without a workcell logs no grasps", "[render][grasp]") {
  const RunLog rec = record(kPickAndPlace, false);
  CHECK(rec.steps.size() == 8);
  CHECK(rec.grasps.empty());
}

// The page's poses apply to the object's pts (world coordinates at its
// placement P = translation (200, 30, 660)): a take's F_E_object · P⁻¹,
// a let-go's F_world_object · P⁻¹.
TEST_CASE("animate puts the grasps in the page's model", "[render][grasp][cli]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("pick.rsp", kPickAndPlace);
  const auto r = rs::testing::runCli(
      {"animate", program, "--cell", "gantry-cell", "-o", dir.file("pick.html"), "--collisions=off"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string html = rs::testing::readBytes(dir.file("pick.html"));
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const std::size_t a = html.find(open);
  REQUIRE(a != std::string::npos);
  const std::size_t b = html.find("</script>", a);
  const nlohmann::json grasps =
      nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()))["run"]["grasps"];
  CHECK(grasps["step"] == nlohmann::json::array({1, 5}));
  CHECK(grasps["at"] == nlohmann::json::array({3'300'000, 12'150'000}));
  CHECK(grasps["object"] == nlohmann::json::array({1, 1}));
  CHECK(grasps["held"] == nlohmann::json::array({true, false}));
  // F_E_world: rotation R^T (columns (1, 0, 0), (0, 0, -1), (0, 1, 0)),
  // origin R^T · -(220, 50, 680) = (-220, -680, 50); then the shift by
  // (510, 0, -500).
  const std::vector<double> want = {1, 0, 0, 0, 0, -1, 0, 1, 0, -220, -680, 50,  //
                                    1, 0, 0, 0, 1, 0,  0, 0, 1, 510,  0,    -500};
  const auto got = grasps["pose"].get<std::vector<double>>();
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    INFO("pose number " << i);
    CHECK(got[i] == Approx(want[i]).margin(1e-9));
  }
}
