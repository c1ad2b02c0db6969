// The pendant's world and tool jogs (tools/teach/pendant.h, jogCartesian;
// model/workcell/cartesian_jog.h). Every pose is checked with `robotsim
// where`, forward kinematics from the encoder counts that does not use the
// jog code or the inverse kinematics; every refusal leaves the motors and
// the clock as they were and names its limit.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "../render/render_test_util.h"
#include "base/file_io.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/teach/commands.h"
#include "tools/teach/pendant.h"

namespace {

using rs::teach::Pendant;
using rs::workcell::JogFrame;
using JogValues = std::vector<std::int32_t>;

struct JogFixture {
  explicit JogFixture(const std::string& cellName)
      : cellName(cellName),
        path(dir.write("jog.rsp", "        END\nPOINTS\n")),
        cell(std::make_shared<const rs::workcell::Workcell>(rendertest::cell(cellName))) {
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    pendant = std::make_unique<Pendant>(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
  }
  std::string cellName;
  rs::testing::TempDir dir;
  std::string path;
  std::shared_ptr<const rs::workcell::Workcell> cell;
  std::unique_ptr<Pendant> pendant;
};

// The tool's pose at `encoders` by `robotsim where` (world coordinates).
struct WherePose {
  Eigen::Vector3d position;
  Eigen::Matrix3d rotation;
};
WherePose whereAt(const std::string& cell, const JogValues& encoders) {
  std::string list;
  for (std::size_t i = 0; i < encoders.size(); ++i) list += (i ? "," : "") + std::to_string(encoders[i]);
  const auto r = rs::testing::runCli({"where", cell, "--encoders", list, "--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  WherePose p;
  for (int i = 0; i < 3; ++i) {
    p.position[i] = j["position"][static_cast<std::size_t>(i)].get<double>();
    for (int k = 0; k < 3; ++k)
      p.rotation(i, k) = j["matrix"][static_cast<std::size_t>(i)][static_cast<std::size_t>(k)].get<double>();
  }
  return p;
}

// Encoder counts for a pose, from `robotsim ik` (the arm put somewhere away from its singular home).
JogValues ikEncoders(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"ik", "--json"};
  all.insert(all.end(), args.begin(), args.end());
  const auto r = rs::testing::runCli(all);
  INFO(r.err);
  REQUIRE(r.code == 0);
  JogValues e;
  const auto j = nlohmann::ordered_json::parse(r.out);  // kept: items() of a temporary's member would dangle
  for (const auto& [letter, v] : j["encoders"].items()) e.push_back(v.get<int>());
  return e;
}

// The arm's motors and clock are as they were, the state names the limit.
void checkRefused(const Pendant& p, const rs::teach::Outcome& o, const JogValues& before, std::int64_t clock,
                  const std::string& limit) {
  INFO(o.message);
  CHECK_FALSE(o.ok);
  CHECK_FALSE(o.badRequest);
  CHECK(p.state().encoders == before);
  CHECK(p.state().clock == clock);
  CHECK(p.state().limit == limit);
  CHECK(o.message.find("refused (" + limit + ")") != std::string::npos);
  CHECK(o.message.find("nothing moved") != std::string::npos);
}

// The PUMA reaching back, away from its table, the tool pointing down: away from its home, where the arm
// stands singular, and a move from home that sweeps nothing (towards the table the forearm would cut its edge).
JogValues pumaReachingBack() {
  return ikEncoders({"puma-cell", "--approach", "0,-1,0", "--normal", "1,0,0", "--", "-500", "950", "300"});
}

double largestTurn(const JogValues& a, const JogValues& b) {
  double most = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    most = std::max(most, std::abs(a[i] - b[i]) * 0.1);  // 0.1 degree a count
  return most;
}

}  // namespace

TEST_CASE("world jog: ten steps of +10 along X move the tool 100 along the world's X, orientation kept",
          "[teach][jog]") {
  JogFixture f("puma-cell");
  Pendant& p = *f.pendant;
  const JogValues start = pumaReachingBack();
  {
    const rs::teach::Outcome there = p.moveTo(start);
    INFO(there.message);
    REQUIRE(there.ok);
  }
  const WherePose before = whereAt("puma-cell", start);
  for (int k = 0; k < 10; ++k) {
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "X", 10);
    INFO(o.message);
    REQUIRE(o.ok);
  }
  const JogValues end = p.state().encoders;
  const WherePose after = whereAt("puma-cell", end);
  // Forward kinematics of the counts: 100 along X, nothing across, within what 0.1-degree counts allow
  // (about 1 length unit at this reach), and no drift from ten roundings.
  CHECK(after.position.x() - before.position.x() == Approx(100).margin(1.0));
  CHECK(after.position.y() == Approx(before.position.y()).margin(1.0));
  CHECK(after.position.z() == Approx(before.position.z()).margin(1.0));
  CHECK((after.rotation - before.rotation).cwiseAbs().maxCoeff() < 0.01);
  // One configuration: no joint swung round (an elbow or wrist flip turns joints by tens of degrees).
  CHECK(largestTurn(start, end) < 15);
  CHECK((start[4] > 0) == (end[4] > 0));  // joint 5, the wrist's bend, keeps its side
  CHECK(p.state().limit.empty());
  CHECK(p.state().message.rfind("world jog X +10 length units: tool centre point at ", 0) == 0);
}

TEST_CASE("tool jog: +10 along the tool's z moves along the approach, a turn about the world's Y keeps the point",
          "[teach][jog]") {
  JogFixture f("puma-cell");
  Pendant& p = *f.pendant;
  const JogValues start = pumaReachingBack();
  {
    const rs::teach::Outcome there = p.moveTo(start);
    INFO(there.message);
    REQUIRE(there.ok);
  }
  const WherePose before = whereAt("puma-cell", start);
  for (int k = 0; k < 5; ++k) REQUIRE(p.jogCartesian(JogFrame::Tool, "Z", 10).ok);
  const WherePose down = whereAt("puma-cell", p.state().encoders);
  const Eigen::Vector3d moved = down.position - before.position;
  CHECK((moved - 50.0 * before.rotation.col(2)).norm() < 1.0);  // the approach points down: y falls by 50
  CHECK(moved.y() == Approx(-50).margin(1.0));
  // A turn of 5 degrees about the world's Y (up), twice: the point stays, the tool turns 10 degrees about Y.
  REQUIRE(p.jogCartesian(JogFrame::World, "RY", 5).ok);
  REQUIRE(p.jogCartesian(JogFrame::World, "RY", 5).ok);
  const WherePose turned = whereAt("puma-cell", p.state().encoders);
  CHECK((turned.position - down.position).norm() < 1.0);
  const Eigen::Matrix3d wanted =
      Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix() * down.rotation;
  CHECK((turned.rotation - wanted).cwiseAbs().maxCoeff() < 0.01);
}

TEST_CASE("world jog on a five-axis arm: X, Y, Z, pitch and roll", "[teach][jog]") {
  JogFixture f("xr4-cell");
  Pendant& p = *f.pendant;
  std::vector<std::string> names;
  for (const auto& a : p.state().worldAxes) names.push_back(a.name);
  CHECK(names == std::vector<std::string>{"X", "Y", "Z", "PITCH", "ROLL"});
  const JogValues home = p.state().encoders;
  const WherePose before = whereAt("xr4-cell", home);
  REQUIRE(p.jogCartesian(JogFrame::World, "Z", 10).ok);
  REQUIRE(p.jogCartesian(JogFrame::World, "Y", 10).ok);
  const WherePose after = whereAt("xr4-cell", p.state().encoders);
  CHECK((after.position - before.position - Eigen::Vector3d(0, 10, 10)).norm() < 1.0);
  // Pitch turns the approach within the arm's plane about the tool centre point.
  REQUIRE(p.jogCartesian(JogFrame::World, "PITCH", 5).ok);
  const WherePose pitched = whereAt("xr4-cell", p.state().encoders);
  CHECK((pitched.position - after.position).norm() < 1.0);
  CHECK(std::acos(std::clamp(pitched.rotation.col(2).dot(after.rotation.col(2)), -1.0, 1.0)) * 180 / M_PI ==
        Approx(5).margin(0.5));
}

TEST_CASE("a cartesian jog refused at each limit moves nothing and names it", "[teach][jog]") {
  JogFixture f("puma-cell");
  Pendant& p = *f.pendant;
  SECTION("singularity: at home the PUMA stands straight up") {
    const JogValues home = p.state().encoders;
    checkRefused(p, p.jogCartesian(JogFrame::World, "X", 10), home, p.state().clock, "singularity");
  }
  const JogValues start = pumaReachingBack();
  {
    const rs::teach::Outcome there = p.moveTo(start);
    INFO(there.message);
    REQUIRE(there.ok);
  }
  const std::int64_t clock = p.state().clock;
  SECTION("reach") {
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "Y", 1000);  // 1290 above the shoulder
    checkRefused(p, o, start, clock, "reach");
    CHECK(o.message.find("out of the arm's reach") != std::string::npos);
  }
  SECTION("an axis the arm does not have is a bad request") {
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "PITCH", 5);
    CHECK_FALSE(o.ok);
    CHECK(o.badRequest);
    CHECK(o.message == "robot puma560 has no world jog axis PITCH (it has X Y Z RX RY RZ)");
    CHECK(p.state().encoders == start);
  }
}

TEST_CASE("a cartesian jog past a motor's range is refused, nothing moved, and names it", "[teach][jog]") {
  // The gantry's X: 0.1 length units a count, range -5000..5000, so the tool centre point's x goes from 0 to
  // 1000 (500 at home): five steps of +100 reach the end, the sixth would need 6000 counts.
  JogFixture f("gantry-cell");
  Pendant& p = *f.pendant;
  for (int k = 1; k <= 5; ++k) {
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "X", 100);
    INFO(o.message);
    REQUIRE(o.ok);
    CHECK(p.state().encoders == JogValues{1000 * k, 0, 0, 0});
  }
  const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "X", 100);
  checkRefused(p, o, JogValues{5000, 0, 0, 0}, 5'000'000, "range");
  // Joint 1's value is its D-H d: home 500 plus 0.1 x 6000.
  CHECK(o.message ==
        "world jog X +100 length units refused (range): motor X would go to 6000 (joint 1 at 1100 length "
        "units), outside its range -5000..5000; nothing moved");
}

TEST_CASE("a cartesian jog into a collision is refused, nothing moved, and names it", "[teach][jog]") {
  // The gantry (tests/teach/test_pendant.cpp has its numbers) over block 1, open: lowered by 10 at a time
  // along the world's Y, the open fingers pass either side of the block and meet the pallet under it.
  JogFixture f("gantry-cell");
  Pendant& p = *f.pendant;
  REQUIRE(p.moveTo(JogValues{-2800, 2800, 1000, 0}).ok);
  rs::teach::Outcome o;
  JogValues before = p.state().encoders;
  std::int64_t at = p.state().clock;
  for (int k = 0; k < 20 && (o = p.jogCartesian(JogFrame::World, "Y", -10)).ok; ++k) {
    before = p.state().encoders;
    at = p.state().clock;
  }
  checkRefused(p, o, before, at, "collision");
  CHECK(o.message.rfind("world jog Y -10 length units refused (collision): the move to ", 0) == 0);
  CHECK(o.message.find("(pallet)") != std::string::npos);
}

TEST_CASE("jogCartesian as a JSON command, and its malformed requests", "[teach][jog]") {
  JogFixture f("gantry-cell");
  Pendant& p = *f.pendant;
  // The gantry's tool centre point is (500 + X/10, 200 - Y/10, 400 + Z/10): +10 along the world's Z is 100
  // counts of motor Z (the second); it has no rotation to jog.
  const rs::teach::Outcome o = rs::teach::applyCommand(
      p, nlohmann::json{{"op", "jogCartesian"}, {"frame", "world"}, {"axis", "Z"}, {"amount", 10}});
  INFO(o.message);
  CHECK(o.ok);
  CHECK(p.state().encoders == JogValues{0, 100, 0, 0});
  CHECK(p.state().toolAxes.size() == 3);
  for (const nlohmann::json& bad :
       {nlohmann::json{{"op", "jogCartesian"}, {"frame", "joint"}, {"axis", "X"}, {"amount", 1}},
        nlohmann::json{{"op", "jogCartesian"}, {"frame", "world"}, {"amount", 1}},
        nlohmann::json{{"op", "jogCartesian"}, {"frame", "tool"}, {"axis", "X"}, {"amount", "1"}},
        nlohmann::json{{"op", "jogCartesian"}, {"frame", "tool"}, {"axis", "X"}, {"amount", 1e300}},
        nlohmann::json{{"op", "jogCartesian"}, {"frame", "tool"}, {"axis", "RX"}, {"amount", 1}}}) {
    const rs::teach::Outcome r = rs::teach::applyCommand(p, bad);
    INFO(bad.dump() << ": " << r.message);
    CHECK_FALSE(r.ok);
    CHECK(r.badRequest);
  }
  CHECK(p.state().encoders == JogValues{0, 100, 0, 0});
}

TEST_CASE("world and tool jogs lift a gripped block off its pallet along the tool's straight line",
          "[teach][jog][straight]") {
  // xr4-cell's front block stands on the pallet (x 220..260, y 780..820, z -60..-20): the tool pointing down,
  // its centre 1 above the block's middle (y 801), the gripper closes on it. A joint move of a jog swung the
  // block through the pallet ("object 3 (block) hits object 2 (pallet)" 0.003 s into a 1-unit lift); the line
  // a jog now runs, as DEPART does in a program, lifts it straight up.
  JogFixture f("xr4-cell");
  Pendant& p = *f.pendant;
  const JogValues above = ikEncoders({"xr4-cell", "--approach", "0,-1,0", "--", "240", "861", "-40"});
  const JogValues grasp = ikEncoders({"xr4-cell", "--approach", "0,-1,0", "--", "240", "801", "-40"});
  REQUIRE(p.moveTo(above).ok);
  REQUIRE(p.moveTo(grasp).ok);
  const rs::teach::Outcome closed = p.gripper(true);
  INFO(closed.message);
  REQUIRE(closed.message == "gripper closed: holds block");
  const std::size_t block = 2;  // object 3
  REQUIRE(p.state().objects[block].held);
  const Eigen::Vector3d rest = p.state().objects[block].pose.translation();
  const WherePose grasped = whereAt("xr4-cell", p.state().encoders);

  // Up 1 along the world's Y, as the HTTP API asks it.
  const rs::teach::Outcome up = rs::teach::applyCommand(
      p, nlohmann::json{{"op", "jogCartesian"}, {"frame", "world"}, {"axis", "Y"}, {"amount", 1}});
  INFO(up.message);
  REQUIRE(up.ok);
  CHECK(p.state().limit.empty());
  const Eigen::Vector3d lifted = p.state().objects[block].pose.translation() - rest;
  CHECK(lifted.y() == Approx(1).margin(0.3));  // the counts' rounding at this reach: a few tenths
  CHECK(std::hypot(lifted.x(), lifted.z()) < 0.3);

  // Up 60 more along the tool's z (the approach points down), by the keys' operation.
  const rs::teach::Outcome tool = p.jogCartesian(JogFrame::Tool, "Z", -60);
  INFO(tool.message);
  REQUIRE(tool.ok);
  CHECK(tool.message.rfind("tool jog Z -60 length units: tool centre point at ", 0) == 0);
  const rs::teach::PendantState s = p.state();
  CHECK(s.objects[block].held);
  CHECK(s.objects[block].pose.translation().y() - rest.y() == Approx(61).margin(0.5));
  // The move is the line: every frame of it, by forward kinematics of its counts (robotsim where), stays
  // on the vertical through where it started, within the line's tolerance and the counts' rounding (about
  // a unit at this reach: 0.1 degree a count), and never goes back down.
  REQUIRE(s.motion.size() > 5);
  const Eigen::Vector3d from = whereAt("xr4-cell", s.motion.front().encoders).position;
  double last = -INFINITY, across = 0;
  for (const rs::teach::MotionFrame& frame : s.motion) {
    const Eigen::Vector3d at = whereAt("xr4-cell", frame.encoders).position;
    across = std::max(across, std::hypot(at.x() - from.x(), at.z() - from.z()));
    CHECK(at.y() >= last - 0.05);
    last = at.y();
  }
  CHECK(across < 1.0);
  CHECK(from.y() - grasped.position.y() > 0.5);  // it started 1 up, and went no lower
  CHECK(last - grasped.position.y() == Approx(61).margin(0.5));
}

TEST_CASE("a cartesian jog's step: a turn of half a turn or more is refused as a step, a long line that is clear moves",
          "[teach][jog][straight]") {
  JogFixture f("puma-cell");
  Pendant& p = *f.pendant;
  const JogValues start = pumaReachingBack();
  REQUIRE(p.moveTo(start).ok);
  const std::int64_t clock = p.state().clock;
  SECTION("turns: +720 moved nothing and said ok; +1000000 turned 280 degrees past the singularity guard") {
    for (const double turn : {720.0, 1e6, 180.0, -180.0, 359.0}) {
      const rs::teach::Outcome o = p.jogCartesian(JogFrame::Tool, "RZ", turn);
      checkRefused(p, o, start, clock, "step");
      CHECK(o.message.find("less than 180 degrees at a time") != std::string::npos);
    }
    // A turn of less than half a turn goes the way it is asked: +90 about the approach, the point kept (the
    // other way the palm meets the forearm).
    const WherePose before = whereAt("puma-cell", start);
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::Tool, "RZ", 90);
    INFO(o.message);
    REQUIRE(o.ok);
    const WherePose after = whereAt("puma-cell", p.state().encoders);
    CHECK((after.position - before.position).norm() < 1.0);
    CHECK((after.rotation.col(2) - before.rotation.col(2)).norm() < 0.01);
    const Eigen::Matrix3d wanted =
        before.rotation * Eigen::AngleAxisd(90.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    CHECK((after.rotation - wanted).cwiseAbs().maxCoeff() < 0.01);
  }
  SECTION("a 300-unit step along X, clear of every singular pose, was refused as near-singular: it moves") {
    const WherePose before = whereAt("puma-cell", start);
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "X", 300);
    INFO(o.message);
    REQUIRE(o.ok);
    const WherePose after = whereAt("puma-cell", p.state().encoders);
    CHECK(after.position.x() - before.position.x() == Approx(300).margin(1.0));
    CHECK(after.position.y() == Approx(before.position.y()).margin(1.0));
    CHECK(after.position.z() == Approx(before.position.z()).margin(1.0));
    // Along the line all the way (joint 1 turns 35 degrees on the way, which the old guard took for a
    // singular pose): each frame's tool centre point within a unit of the line.
    for (const rs::teach::MotionFrame& frame : p.state().motion) {
      const Eigen::Vector3d at = whereAt("puma-cell", frame.encoders).position;
      CHECK(std::hypot(at.y() - before.position.y(), at.z() - before.position.z()) < 1.0);
    }
  }
}
