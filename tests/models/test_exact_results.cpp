// table --json and where --json carry full double precision, angles in
// (-180, 180]; the text tables round to 4 decimals, and an angle that
// rounds to -180 is printed 180. The robot is built here with a link frame
// turned by -179.99999 degrees; the expected values are computed from the
// numbers written into its file (atan2, hypot), not by the D-H code.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "tests/models/models_support.h"
#include "tools/cli/lib/robot_commands.h"

namespace {

using nlohmann::json;
using rs::testing::lines;
using rs::testing::runCli;
using rs::testing::TempDir;

constexpr double kDeg = 180.0 / M_PI;

// A one-joint robot: frame 1 at `radius` from the z axis, at height 5, its
// x axis turned by `turn` degrees about z0 (from x0). Writes the numbers
// with 15 decimals (descriptions take no exponent) and gives them back
// as read.
struct TurnedRobot {
  double ox, oy, xx, xy;  // frame 1's origin and x-axis point, as written
  std::string text;
};

TurnedRobot turnedRobot(double turnDegrees, double radius, const std::string& yText = "") {
  const double c = std::cos(turnDegrees / kDeg), s = std::sin(turnDegrees / kDeg);
  TurnedRobot r;
  const std::string ox = fmt::format("{:.15f}", radius * c), oy = yText.empty() ? fmt::format("{:.15f}", radius * s) : yText;
  const std::string xx = fmt::format("{:.15f}", (radius + 1000) * c),
                    xy = yText.empty() ? fmt::format("{:.15f}", (radius + 1000) * s) : yText;
  r.ox = std::stod(ox), r.oy = std::stod(oy), r.xx = std::stod(xx), r.xy = std::stod(xy);
  r.text = lines({
      "LINK l0",
      "  LINE 0 0 0 0 0 1",
      "END",
      "LINK l1",
      "  LINE 0 0 0 1 0 0",
      "END",
      "ROBOT turned",
      "  LINK l0 FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",
      fmt::format("  LINK l1 FRAME ORIGIN {} {} 5 XAXIS {} {} 5 ZAXIS {} {} 6", ox, oy, xx, xy, ox, oy),
      "  JOINT 1 REVOLUTE LETTER E PRECISION 0.1 RANGE -100 100",
      "END",
  });
  return r;
}

json parse(const std::string& text) {
  INFO(text);
  REQUIRE(json::accept(text));
  return json::parse(text);
}

}  // namespace

TEST_CASE("exact results: angles lie in -180 < a <= 180", "[models][exact]") {
  using rs::cli::formatAngle;
  using rs::cli::normalizeDegrees;
  CHECK(normalizeDegrees(-180.0) == 180.0);
  CHECK(normalizeDegrees(180.0) == 180.0);
  CHECK(normalizeDegrees(540.0) == 180.0);
  CHECK(normalizeDegrees(-190.0) == 170.0);
  CHECK(normalizeDegrees(190.5) == -169.5);
  CHECK(normalizeDegrees(-179.99999) == -179.99999);  // in range: kept to the last bit
  CHECK(std::signbit(normalizeDegrees(-0.0)) == false);
  CHECK(formatAngle(-179.99999) == "180");  // rounds to -180: shown as 180
  CHECK(formatAngle(-179.9999) == "-179.9999");
  CHECK(formatAngle(-180.0) == "180");
  CHECK(formatAngle(359.99999) == "0");
}

TEST_CASE("exact results: table --json at full precision, the text table rounded and saying so", "[models][exact]") {
  TempDir dir;
  const TurnedRobot robot = turnedRobot(-179.99999, 250);
  const std::string file = dir.write("turned.rsd", robot.text);
  // Independently: theta is the direction of x1 seen from z0; a is the
  // distance of o1 from the z0 axis; d its height.
  const double theta = std::atan2(robot.xy - robot.oy, robot.xx - robot.ox) * kDeg;
  const double a = std::hypot(robot.ox, robot.oy);
  REQUIRE(theta > -180.0);
  REQUIRE(theta < -179.9999);

  const auto r = runCli({"table", file, "--json"});
  REQUIRE(r.code == 0);
  const json j = parse(r.out);
  REQUIRE(j["rows"].size() == 1);
  const json& row = j["rows"][0];
  CHECK(row["theta"].get<double>() == Approx(theta).margin(1e-9));
  CHECK(row["home"].get<double>() == Approx(theta).margin(1e-9));
  CHECK(row["theta"].get<double>() > -180.0);  // full precision: not rounded to -180, and not moved to 180
  CHECK(row["a"].get<double>() == Approx(a).epsilon(1e-14));
  CHECK(row["d"].get<double>() == 5.0);
  CHECK(row["alpha"].get<double>() == 0.0);

  const auto text = runCli({"table", file});
  REQUIRE(text.code == 0);
  // -179.99999 rounds to -180, printed as 180.
  CHECK_THAT(text.out, Catch::Contains("1     revolute       theta1         0       250         5       180\n"));
  CHECK_THAT(text.out, Catch::EndsWith("(values rounded to 4 decimals, angles in (-180, 180]; --json gives full "
                                       "precision)\n"));
}

TEST_CASE("exact results: a turn of exactly 180 degrees is 180, never -180", "[models][exact]") {
  TempDir dir;
  // x1 points along -x with a y of -0: atan2 would say -180.
  const std::string file = dir.write("half.rsd", turnedRobot(180.0, 250, "-0").text);
  const json t = parse(runCli({"table", file, "--json"}).out);
  CHECK(t["rows"][0]["theta"].get<double>() == 180.0);
  const json w = parse(runCli({"where", file, "--json"}).out);
  CHECK(w["rpy"][2].get<double>() == 180.0);
  CHECK_THAT(runCli({"where", file}).out, Catch::Contains("yaw 180 "));
}

TEST_CASE("exact results: where --json at full precision, in the robot's design coordinates", "[models][exact]") {
  TempDir dir;
  const TurnedRobot robot = turnedRobot(-179.99999, 250);
  const std::string file = dir.write("turned.rsd", robot.text);
  // At home the tool is frame 1: its origin as written, its x axis towards
  // the XAXIS point, z up: roll 0, pitch 0, yaw the direction of x1.
  const double yaw = std::atan2(robot.xy - robot.oy, robot.xx - robot.ox) * kDeg;
  const auto r = runCli({"where", file, "--encoders", "0", "--json"});
  REQUIRE(r.code == 0);
  const json j = parse(r.out);
  CHECK(j["position"][0].get<double>() == Approx(robot.ox).epsilon(1e-14));
  CHECK(j["position"][1].get<double>() == Approx(robot.oy).margin(1e-12));
  CHECK(j["position"][2].get<double>() == 5.0);
  // More than the text's 4 decimals: y is about -4.4e-5, which rounds to 0.
  CHECK(j["position"][1].get<double>() != 0.0);
  CHECK(j["rpy"][0].get<double>() == Approx(0.0).margin(1e-12));
  CHECK(j["rpy"][1].get<double>() == Approx(0.0).margin(1e-12));
  CHECK(j["rpy"][2].get<double>() == Approx(yaw).margin(1e-9));
  CHECK(j["rpy"][2].get<double>() > -180.0);
  // The position is the matrix's last column, as matrix --json gives it.
  for (int k = 0; k < 3; ++k) CHECK(j["position"][k] == j["matrix"][k][3]);

  const auto text = runCli({"where", file, "--encoders", "0"});
  REQUIRE(text.code == 0);
  CHECK_THAT(text.out, Catch::StartsWith("turned: tool centre point at (-250, 0, 5)\n"));
  CHECK_THAT(text.out, Catch::Contains("  roll 0  pitch 0  yaw 180 (degrees"));
  CHECK_THAT(text.out, Catch::EndsWith("(the robot's design coordinates, those its description is drawn in; values "
                                       "rounded to 4 decimals, angles in (-180, 180]; --json gives full precision)\n"));
}
