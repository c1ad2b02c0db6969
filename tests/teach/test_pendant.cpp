// The teach pendant's core (tools/teach/pendant.h) on the library's gantry cell,
// whose kinematics are simple enough to check by hand: motors X Z Y
// (prismatic, 0.1 mm per count; X ±5000 and Z ±3400 at 1000 counts/s, Y
// ±2000 at 800/s) and the gripper A (0..104, 200/s); the tool centre
// point is at (500 + X/10, 200 - Y/10, 400 + Z/10) in the world
// (examples/gantry_pick.rsp), and block 1 (object 1) is centred at
// (220, 50, 680): X -2800, Z 2800, Y 1500. The pendant checks every move
// for collisions: point OVER is 50 mm above that middle (Y 1000), so that
// the fingers, which reach 20 below the tool centre, pass 10 above the
// blocks' tops (y 70) on the way; the gripper closes 1 mm above the middle
// (Y 1490), as gantry_pick does (docs/teach.md, "Collisions").
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tests/teach/gantry_pendant.h"
#include "tools/teach/commands.h"
#include "tools/teach/keys.h"
#include "tools/teach/pendant.h"

namespace {

using rs::teach::Pendant;
using Values = std::vector<std::int32_t>;

const std::string kPendantProgram =
    "        MOVEP OVER              ; the block\n"
    "        END\n"
    "POINTS\n"
    "OVER   -2800  2800  1000    0\n";

struct Fixture : rs::testing::GantryPendant {
  Fixture() : GantryPendant("gantry.rsp", kPendantProgram) {}
};

void checkTcp(const rs::teach::PendantState& s, double x, double y, double z) {
  REQUIRE(s.tcp);
  CHECK((*s.tcp)[0] == Approx(x).margin(1e-9));
  CHECK((*s.tcp)[1] == Approx(y).margin(1e-9));
  CHECK((*s.tcp)[2] == Approx(z).margin(1e-9));
}

}  // namespace

TEST_CASE("pendant: jogs at motor speed, stops at a range's end, refuses a target outside it", "[teach]") {
  Fixture f;
  Pendant& p = *f.pendant;
  CHECK(p.state().encoders == Values{0, 0, 0, 0});
  checkTcp(p.state(), 500, 200, 400);
  REQUIRE(p.jog(0, 100).ok);
  CHECK(p.state().encoders == Values{100, 0, 0, 0});
  CHECK(p.state().clock == 100'000);  // 100 counts at 1000 counts/s
  checkTcp(p.state(), 510, 200, 400);
  const rs::teach::Outcome far = p.jog(0, 10000);
  CHECK(far.ok);
  CHECK(far.message == "motor X stopped at the end of its range, 5000");
  CHECK(p.state().encoders == Values{5000, 0, 0, 0});
  const rs::teach::Outcome beyond = p.jog(0, 1);
  CHECK_FALSE(beyond.ok);
  CHECK(beyond.message == "motor X is at the end of its range (5000)");
  const rs::teach::Outcome set = p.setMotor(2, 2001);
  CHECK_FALSE(set.ok);
  CHECK(set.message == "motor Y: 2001 is outside its range -2000..2000: nothing moved");
  CHECK(p.state().encoders == Values{5000, 0, 0, 0});
  CHECK(p.state().failed);
  CHECK(p.state().message == set.message);
  CHECK_FALSE(p.jog(7, 1).ok);
}

TEST_CASE("pendant: go to a point moves at motor speed, its motion time-stepped", "[teach]") {
  Fixture f;
  Pendant& p = *f.pendant;
  const rs::teach::Outcome o = p.goTo("over");
  REQUIRE(o.ok);
  CHECK(o.message == "went to OVER (2.800 s)");  // X and Z: 2800 counts at 1000/s; Y 1000 at 800/s: 1.25 s
  const rs::teach::PendantState s = p.state();
  CHECK(s.encoders == Values{-2800, 2800, 1000, 0});
  checkTcp(s, 220, 100, 680);
  REQUIRE(s.motion.size() == 71);  // every 40 ms from 0 to 2.8 s
  CHECK(s.motion[0].encoders == Values{0, 0, 0, 0});
  CHECK(s.motion[25].at == 1'000'000);
  CHECK(s.motion[25].encoders == Values{-1000, 1000, 800, 0});
  CHECK(s.motion[50].encoders == Values{-2000, 2000, 1000, 0});  // Y arrived at 1.25 s
  CHECK(s.motion.back().encoders == s.encoders);
  CHECK_FALSE(p.goTo("nowhere").ok);
  CHECK(p.state().motion.empty());
}

TEST_CASE("pendant: the gripper takes and carries a block as in a run, reset puts it back", "[teach]") {
  Fixture f;
  Pendant& p = *f.pendant;
  REQUIRE(p.goTo("OVER").ok);
  REQUIRE(p.moveTo(Values{-2800, 2800, 1490, 0}).ok);  // straight down, the open fingers round the block
  CHECK(p.state().gripper == rs::teach::GripperState::Open);
  const rs::teach::Outcome closed = p.gripper(true);
  REQUIRE(closed.ok);
  CHECK(closed.message == "gripper closed: holds block");
  rs::teach::PendantState s = p.state();
  CHECK(s.gripper == rs::teach::GripperState::Closed);
  CHECK(s.encoders[3] == 104);
  REQUIRE(s.objects.size() == 4);
  CHECK(s.objects[1].held);
  const Eigen::Vector3d placed = f.cell->objects[1].F_world_design.translation();
  REQUIRE(p.jog(2, -1000).ok);  // 100 mm up: the block goes with it
  s = p.state();
  CHECK((s.objects[1].pose.translation() - placed - Eigen::Vector3d(0, 100, 0)).norm() < 1e-9);
  CHECK(s.objects[1].moved);
  CHECK_FALSE(s.objects[2].moved);
  REQUIRE(p.gripper(false).ok);
  CHECK_FALSE(p.state().objects[1].held);
  REQUIRE(p.toggleInput(3).ok);
  CHECK(p.state().inputs == 0b100);
  REQUIRE(p.setOutput(8, true).ok);
  CHECK(p.state().outputs == 0x80);
  REQUIRE(p.resetCell().ok);
  s = p.state();
  CHECK(s.encoders == Values{0, 0, 0, 0});
  CHECK(s.objects[1].pose.matrix() == f.cell->objects[1].F_world_design.matrix());
  CHECK_FALSE(s.objects[1].moved);
  CHECK(s.inputs == 0);
  CHECK(s.outputs == 0);
  CHECK_FALSE(p.readPosition().ok);  // no device
}

TEST_CASE("pendant: a move that would collide is refused, naming the parts, and nothing moves", "[teach][collision]") {
  Fixture f;
  Pendant& p = *f.pendant;
  REQUIRE(p.goTo("OVER").ok);
  // Down to the block's middle (y 50): the open fingers' tips, 20 below the tool centre, rest on the
  // pallet's top (y 30), touching it, which is no collision.
  REQUIRE(p.moveTo(Values{-2800, 2800, 1500, 0}).ok);
  const rs::teach::PendantState before = p.state();
  // Closing swings each finger about its pivot 70 above the tool centre: its outer lower corner, 4 out
  // and 90 down from the pivot (stdlib/robots/gantry.rsd), passes straight below it, sqrt(4² + 90²) =
  // 90.09 down: 0.09 into the pallet, deeper than the 0.02 contact tolerance.
  const rs::teach::Outcome close = p.gripper(true);
  CHECK_FALSE(close.ok);
  CHECK_FALSE(close.badRequest);
  CHECK(close.message.find("refused: the move to -2800 2800 1500 104 collides ") == 0);
  // How deep, at the first check that saw it: past the 0.02 the pieces are made smaller by, at most the 0.09.
  const std::size_t deep = close.message.find(" hits object 1 (pallet), ");
  REQUIRE(deep != std::string::npos);
  const double depth = std::stod(close.message.substr(deep + std::string(" hits object 1 (pallet), ").size()));
  CHECK(depth >= 0.02);
  CHECK(depth <= 0.09);
  CHECK(close.message.find(" deep; nothing moved") != std::string::npos);
  CHECK(close.message.find("finger") != std::string::npos);
  const rs::teach::PendantState after = p.state();
  CHECK(after.failed);
  CHECK(after.message == close.message);
  CHECK(after.encoders == before.encoders);  // the gripper still open
  CHECK(after.clock == before.clock);        // and no time went by
  CHECK_FALSE(after.objects[1].held);  // block 1 (objects are numbered from 1 in messages, from 0 here)
  CHECK(after.motion.empty());
  // 1 mm higher the fingers clear the pallet: the gripper closes and takes the block.
  REQUIRE(p.jog(2, -10).ok);
  const rs::teach::Outcome closed = p.gripper(true);
  CHECK(closed.ok);
  CHECK(closed.message == "gripper closed: holds block");
  // Carried 100 mm along x, block 1 (x 200..240) would run into block 2 (x 280..320).
  const rs::teach::Outcome carry = p.jog(0, 1000);
  CHECK_FALSE(carry.ok);
  // The closed fingers, ahead of the block they hold, meet block 2 first (no part is exempt when
  // the gripper neither closes nor opens).
  CHECK(carry.message.find(" hits object 3 (block)") != std::string::npos);
  CHECK(p.state().encoders == Values{-2800, 2800, 1490, 104});
}

TEST_CASE("pendant: teach, re-teach, rename and delete write the program", "[teach]") {
  Fixture f;
  Pendant& p = *f.pendant;
  REQUIRE(p.jog(0, 250).ok);
  REQUIRE(p.jog(2, -40).ok);
  const rs::teach::Outcome taught = p.teach("P1");
  REQUIRE(taught.ok);
  // OVER's values end at columns 12, 18, 24 and 29: "P1" + 7 spaces + "250" ends at 12.
  CHECK(f.text() == kPendantProgram + "P1       250     0   -40    0\n");
  REQUIRE(p.gripper(true).ok);
  REQUIRE(p.reteach("p1").ok);
  CHECK(f.text() == kPendantProgram + "P1       250     0   -40  104\n");
  REQUIRE(p.rename("P1", "GRIP").ok);
  CHECK(f.text() == kPendantProgram + "GRIP     250     0   -40  104\n");
  CHECK_FALSE(p.teach("grip").ok);
  CHECK_FALSE(p.teach("END").ok);
  REQUIRE(p.remove("OVER").ok);
  CHECK(f.text() == "        MOVEP OVER              ; the block\n        END\nPOINTS\nGRIP     250     0   -40  104\n");
  const rs::teach::PendantState s = p.state();
  REQUIRE(s.points.size() == 1);
  CHECK(s.points[0].name == "GRIP");
  CHECK(s.points[0].values == Values{250, 0, -40, 104});
  CHECK(s.points[0].line == 4u);
  // Edited elsewhere meanwhile: refused, said so, the file as they left it.
  f.dir.write("gantry.rsp", kPendantProgram);
  const rs::teach::Outcome refused = p.teach("LATE");
  CHECK_FALSE(refused.ok);
  CHECK(refused.message.find("changed on disk") != std::string::npos);
  CHECK(f.text() == kPendantProgram);
  REQUIRE(p.reload().ok);
  REQUIRE(p.teach("LATE").ok);
  CHECK(f.text() == kPendantProgram + "LATE     250     0   -40  104\n");
}

TEST_CASE("pendant: commands as the page sends them, malformed ones refused as bad requests", "[teach]") {
  Fixture f;
  Pendant& p = *f.pendant;
  using nlohmann::json;
  CHECK(rs::teach::applyCommand(p, json{{"op", "jog"}, {"motor", 1}, {"delta", 30}}).ok);
  CHECK(rs::teach::applyCommand(p, json{{"op", "set"}, {"motor", 0}, {"value", -5}}).ok);
  CHECK(p.state().encoders == Values{-5, 30, 0, 0});
  CHECK(rs::teach::applyCommand(p, json{{"op", "teach"}, {"name", "A1"}}).ok);
  CHECK(rs::teach::applyCommand(p, json{{"op", "goTo"}, {"name", "OVER"}}).ok);
  CHECK(rs::teach::applyCommand(p, json{{"op", "input"}, {"line", 8}}).ok);
  CHECK(p.state().inputs == 0x80);
  for (const json& badRequest :
       {json::array(), json{{"op", 3}}, json{{"op", "fly"}}, json{{"op", "jog"}, {"motor", "X"}, {"delta", 1}},
        json{{"op", "jog"}, {"motor", 0}, {"delta", 1e12}}, json{{"op", "teach"}}, json{{"op", "input"}, {"line", 9}},
        json{{"op", "jog"}, {"motor", -1}, {"delta", 1}}, json{{"op", "moveTo"}, {"values", {1, "a"}}}}) {
    const rs::teach::Outcome o = rs::teach::applyCommand(p, badRequest);
    INFO(badRequest.dump());
    CHECK_FALSE(o.ok);
    CHECK(o.badRequest);
  }
  // A refusal that is not the request's fault is no bad request.
  const rs::teach::Outcome refused = rs::teach::applyCommand(p, json{{"op", "goTo"}, {"name", "NONE"}});
  CHECK_FALSE(refused.ok);
  CHECK_FALSE(refused.badRequest);
}

TEST_CASE("pendant: the state as JSON", "[teach]") {
  Fixture f;
  Pendant& p = *f.pendant;
  REQUIRE(p.toggleInput(2).ok);
  const auto j = rs::teach::pendantJson(p.state(), p.placements());
  CHECK(j["cell"] == "gantry-cell");
  CHECK(j["motors"].size() == 4);
  CHECK(j["motors"][3]["kind"] == "gripper");
  CHECK(j["inputs"] == nlohmann::ordered_json({false, true, false, false, false, false, false, false}));
  CHECK(j["gripper"] == "open");
  CHECK(j["points"][0]["name"] == "OVER");
  CHECK(j["points"][0]["line"] == 4);
  // Objects at their placement: the identity takes their drawing nowhere.
  CHECK(j["objects"][0]["pose"] == nlohmann::ordered_json({1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0}));
  CHECK(j["fileHash"].get<std::string>().size() == 16);
  CHECK(j["tcp"] == nlohmann::ordered_json({500.0, 200.0, 400.0}));
}

TEST_CASE("pendant keys: one table, every key once", "[teach]") {
  std::set<std::string_view> keys;
  for (const rs::teach::KeyBinding& k : rs::teach::kKeys) CHECK(keys.insert(k.key).second);
  CHECK(rs::teach::keyBinding("t")->action == rs::teach::KeyAction::Teach);
  CHECK_FALSE(rs::teach::keyBinding("Z"));
  CHECK(rs::teach::keysJson().size() == rs::teach::kKeys.size());
}
