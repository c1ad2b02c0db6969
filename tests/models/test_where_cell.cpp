// `robotsim where CELL`: the tool centre point in the workcell's world
// coordinates. Every expected number is worked out here by hand from the
// description files, not by the kinematics code:
//
// scara-pick (stdlib/workcells/scara-pick.rsd) places rhino-scara's link 0
// origin, design (90, -125, 0), AT (0, 750, 0), not turned: world = design
// + (-90, 875, 0). rhino-scara.rsd's frame 0 has x0 = -x (XAXIS 70 -125 0)
// and z0 = +y (ZAXIS 90 -105 0), so y0 = z0 x x0 = +z. In frame 0 the arm
// is planar: the tool centre point lies at
//   (105 cos t1 + 120 cos(t1 + t2), 105 sin t1 + 120 sin(t1 + t2))
// (a1 = 105, a2 = 120 from the file's D-H comment) and at height
// 90 - C * 0.12 above frame 0 (the TCP at design y -35, frame 0 at -125;
// positive C counts lower the shaft). Its n vector turns by
// t1 + t2 - t4 about z0 (z3 points down, so joint B turns the other way)
// and a points down (-y) whatever the joints.
//
// scorobot-cell places scorobot (design frame 0 at the origin) AT 0 0 0
// ROTATE X -90, which takes design (x, y, z) to world (x, z, -y).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

using nlohmann::json;
using rs::testing::runCli;

constexpr double kRad = M_PI / 180.0;

json whereJson(const std::vector<std::string>& args) {
  std::vector<std::string> all{"where"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  const auto r = runCli(all);
  INFO(r.err);
  REQUIRE(r.code == 0);
  REQUIRE(json::accept(r.out));
  return json::parse(r.out);
}

}  // namespace

TEST_CASE("where cell: scara-pick at home is the cell comment's (-225, 840, 0)", "[models][where]") {
  const json j = whereJson({"scara-pick"});
  CHECK(j["cell"] == "scara-pick");
  CHECK(j["robot"] == "rhino-scara");
  CHECK(j["frame"] == "world");
  CHECK(j["position"][0].get<double>() == Approx(-225.0).margin(1e-9));
  CHECK(j["position"][1].get<double>() == Approx(840.0).margin(1e-9));
  CHECK(j["position"][2].get<double>() == Approx(0.0).margin(1e-9));
  // n = -x, a = -y: the matrix's first and third columns.
  CHECK(j["matrix"][0][0].get<double>() == Approx(-1.0).margin(1e-12));
  CHECK(j["matrix"][1][2].get<double>() == Approx(-1.0).margin(1e-12));

  // The robot alone stays in its design coordinates: (-135, -35, 0), and
  // its JSON names no cell.
  const json design = whereJson({"rhino-scara"});
  CHECK_FALSE(design.contains("cell"));
  CHECK(design["position"][0].get<double>() == Approx(-135.0).margin(1e-9));
  CHECK(design["position"][1].get<double>() == Approx(-35.0).margin(1e-9));
}

TEST_CASE("where cell: scara-pick with every arm joint turned, against the planar arm by hand", "[models][where]") {
  const double t1 = 400 * 0.1175, t2 = -300 * 0.2233, t4 = 100 * 0.2233;
  const double px = 105 * std::cos(t1 * kRad) + 120 * std::cos((t1 + t2) * kRad);
  const double py = 105 * std::sin(t1 * kRad) + 120 * std::sin((t1 + t2) * kRad);
  const double h = 90 - 100 * 0.12;
  // World = frame 0's origin (0, 750, 0) + px x0 + py y0 + h z0.
  const double x = -px, y = 750 + h, z = py;
  const double nAngle = (t1 + t2 - t4) * kRad;
  const double nx = -std::cos(nAngle), nz = std::sin(nAngle);  // n = cos x0 + sin y0

  const json j = whereJson({"scara-pick", "--encoders", "400,-300,100,100"});
  CHECK(j["position"][0].get<double>() == Approx(x).margin(1e-9));
  CHECK(j["position"][1].get<double>() == Approx(y).margin(1e-9));
  CHECK(j["position"][2].get<double>() == Approx(z).margin(1e-9));
  CHECK(j["matrix"][0][0].get<double>() == Approx(nx).margin(1e-12));
  CHECK(j["matrix"][1][0].get<double>() == Approx(0.0).margin(1e-12));
  CHECK(j["matrix"][2][0].get<double>() == Approx(nz).margin(1e-12));
  CHECK(j["matrix"][1][2].get<double>() == Approx(-1.0).margin(1e-12));

  // The text form: rounded, and saying which frame.
  const auto text = runCli({"where", "scara-pick", "--encoders", "400,-300,100,100,60"});
  REQUIRE(text.code == 0);
  CHECK_THAT(text.out, Catch::StartsWith("scara-pick (rhino-scara): tool centre point at ("));
  CHECK_THAT(text.out, Catch::EndsWith("(world coordinates of workcell scara-pick, whose rhino-scara has link 0's "
                                       "origin at (0, 750, 0); values rounded to 4 decimals, angles in (-180, 180]; "
                                       "--json gives full precision)\n"));
}

TEST_CASE("where cell: a turned robot, scorobot-cell against the scorobot golden turned by hand", "[models][where]") {
  // tests/golden/models/scorobot.where-100.json (checked by hand there):
  // design (757 cos 11.75, 757 sin 11.75, 1397) -> world (x, z, -y).
  const double c = 757 * std::cos(11.75 * kRad), s = 757 * std::sin(11.75 * kRad);
  const json j = whereJson({"scorobot-cell", "--encoders", "100,0,0,0,0"});
  CHECK(j["cell"] == "scorobot-cell");
  CHECK(j["position"][0].get<double>() == Approx(c).margin(1e-9));
  CHECK(j["position"][1].get<double>() == Approx(1397.0).margin(1e-9));
  CHECK(j["position"][2].get<double>() == Approx(-s).margin(1e-9));
  // a: design (0, 0, -1) (the golden's) goes to (0, -1, 0): down.
  CHECK(j["matrix"][1][2].get<double>() == Approx(-1.0).margin(1e-12));
  for (int k = 0; k < 3; ++k) CHECK(j["position"][k] == j["matrix"][k][3]);
}

TEST_CASE("where cell: errors name the option or the cell", "[models][where]") {
  auto r = runCli({"where", "scara-pick", "--encoders", "2000,0,0,0"});
  CHECK(r.code == 2);
  CHECK(r.err ==
        "--encoders: error: value 1 (E, joint 1) 2000 is outside the motor's range -1000..1000\n"
        "  hint: encoder counts are whole numbers within each motor's RANGE (robotsim describe CELL lists them)\n");
  r = runCli({"where", "scara-pick", "--encoders", "1,2"});
  CHECK(r.code == 2);
  CHECK(r.err.starts_with("--encoders: error: 4 values needed (one per joint, the gripper's optional), found 2\n"));
  r = runCli({"where", "no-such-cell"});
  CHECK(r.code == 2);
  CHECK(r.err == "no-such-cell: error: no such file, and no workcell or robot of that name on the library path\n");
}
