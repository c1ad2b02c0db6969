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
