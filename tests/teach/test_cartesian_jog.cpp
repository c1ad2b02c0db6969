// The pendant's world and tool jogs (teach/pendant.h, jogCartesian;
// model/workcell/cartesian_jog.h). Every pose is checked with `robotsim
// where`, forward kinematics from the encoder counts that does not use the
// jog code or the inverse kinematics; every refusal leaves the motors and
// the clock as they were and names its limit.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>
#include <cmath>

#include "../render/render_test_util.h"
#include "base/file_io.h"
#include "launch/program.h"
#include "teach/commands.h"
#include "teach/pendant.h"
#include "tests/cli/cli_support.h"

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
  std::vector<std::string> all = {"ik"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  const auto r = rs::testing::runCli(all);
  INFO(r.err);
  REQUIRE(r.code == 0);
  JogValues e;
  for (const auto& [letter, v] : nlohmann::ordered_json::parse(r.out)["encoders"].items()) e.push_back(v.get<int>());
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

// The PUMA above the table's free end, the tool pointing down: away from its home, where the arm stands
// straight up (singular).
JogValues pumaAboveTable() { return ikEncoders({"puma-cell", "--approach", "0,-1,0", "--normal", "1,0,0", "--", "650", "950", "100"}); }

double largestTurn(const JogValues& a, const JogValues& b) {
  double most = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) most = std::max(most, std::abs(a[i] - b[i]) * 0.1);  // 0.1 degree a count
  return most;
}

}  // namespace

TEST_CASE("world jog: ten steps of +10 along X move the tool 100 along the world's X, orientation kept", "[teach][jog]") {
  JogFixture f("puma-cell");
  Pendant& p = *f.pendant;
  const JogValues start = pumaAboveTable();
  REQUIRE(p.moveTo(start).ok);
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

TEST_CASE("tool jog: +10 along the tool's z moves along the approach; a turn about the world's Y keeps the point",
          "[teach][jog]") {
  JogFixture f("puma-cell");
  Pendant& p = *f.pendant;
  const JogValues start = pumaAboveTable();
  REQUIRE(p.moveTo(start).ok);
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
  const Eigen::Matrix3d wanted = Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                                 down.rotation;
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
  const JogValues start = pumaAboveTable();
  REQUIRE(p.moveTo(start).ok);
  const std::int64_t clock = p.state().clock;
  SECTION("reach") {
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "X", 1000);
    checkRefused(p, o, start, clock, "reach");
    CHECK(o.message.find("out of the arm's reach") != std::string::npos);
  }
  SECTION("range: the tool turned about its approach until joint 6 meets the end of its range") {
    rs::teach::Outcome o;
    JogValues before = start;
    std::int64_t at = clock;
    for (int k = 0; k < 40 && (o = p.jogCartesian(JogFrame::Tool, "RZ", 15)).ok; ++k) {
      before = p.state().encoders;
      at = p.state().clock;
    }
    checkRefused(p, o, before, at, "range");
    CHECK(o.message.find("motor B would go to") != std::string::npos);
    CHECK(o.message.find("outside its range -2660..2660") != std::string::npos);
  }
  SECTION("collision: the tool lowered onto the table") {
    rs::teach::Outcome o;
    JogValues before = start;
    std::int64_t at = clock;
    for (int k = 0; k < 10 && (o = p.jogCartesian(JogFrame::World, "Y", -50)).ok; ++k) {
      before = p.state().encoders;
      at = p.state().clock;
    }
    checkRefused(p, o, before, at, "collision");
    CHECK(o.message.find("hits object 1 (table)") != std::string::npos);
  }
  SECTION("an axis the arm does not have is a bad request") {
    const rs::teach::Outcome o = p.jogCartesian(JogFrame::World, "PITCH", 5);
    CHECK_FALSE(o.ok);
    CHECK(o.badRequest);
    CHECK(o.message == "robot puma560 has no world jog axis PITCH (it has X Y Z RX RY RZ)");
    CHECK(p.state().encoders == start);
  }
}

TEST_CASE("jogCartesian as a JSON command, and its malformed requests", "[teach][jog]") {
  JogFixture f("gantry-cell");
  Pendant& p = *f.pendant;
  // The gantry's tool centre point is (500 + X/10, 200 - Y/10, 400 + Z/10): +10 along the world's Z is 100
  // counts of motor Z (the second); it has no rotation to jog.
  const rs::teach::Outcome o =
      rs::teach::applyCommand(p, nlohmann::json{{"op", "jogCartesian"}, {"frame", "world"}, {"axis", "Z"}, {"amount", 10}});
  INFO(o.message);
  CHECK(o.ok);
  CHECK(p.state().encoders == JogValues{0, 100, 0, 0});
  CHECK(p.state().toolAxes.size() == 3);
  for (const nlohmann::json& bad : {nlohmann::json{{"op", "jogCartesian"}, {"frame", "joint"}, {"axis", "X"}, {"amount", 1}},
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
