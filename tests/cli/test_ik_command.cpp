// robotsim ik: the encoder counts for a pose and a POINTS line that,
// pasted into a program, compiles to those counts; checked with `where`'s
// forward kinematics, which does not use the inverse.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <cmath>
#include <fmt/format.h>
#include <sstream>

#include "tests/cli/cli_support.h"

using rs::testing::runCli;

TEST_CASE("robotsim ik prints encoders and a POINTS line that where confirms", "[cli][ik]") {
  const auto r = runCli({"ik", "puma560", "--frame", "robot", "--approach", "0,-1,0", "--name", "ABOVE", "--json", "--",
                         "500", "0", "100"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::ordered_json::parse(r.out);
  CHECK(j["family"] == "articulated-6");
  CHECK(j["solutions"].get<int>() >= 1);
  std::vector<std::int32_t> e;
  for (const auto& [letter, v] : j["encoders"].items()) e.push_back(v.get<int>());
  REQUIRE(e.size() == 7);
  std::string line = "ABOVE";
  std::string list;
  for (std::size_t i = 0; i < e.size(); ++i) line += " " + std::to_string(e[i]), list += (i ? "," : "") + std::to_string(e[i]);
  CHECK(j["points_line"] == line);
  // where (design coordinates) puts the tool there, within what 0.1-degree counts allow.
  const auto w = runCli({"where", "puma560", "--encoders", list, "--json"});
  REQUIRE(w.code == 0);
  const auto wj = nlohmann::json::parse(w.out);
  const double dx = wj["position"][0].get<double>() - 500, dy = wj["position"][1].get<double>(),
               dz = wj["position"][2].get<double>() - 100;
  CHECK(std::sqrt(dx * dx + dy * dy + dz * dz) < 2.0);
  CHECK(wj["matrix"][1][2].get<double>() < -0.9999);  // approach (0, -1, 0)
}

TEST_CASE("robotsim ik text output and its refusals", "[cli][ik]") {
  const auto ok = runCli({"ik", "scara-pick", "--", "-130", "800", "0"});
  INFO(ok.err);
  REQUIRE(ok.code == 0);
  CHECK(ok.out.find("rhino-scara (scara family): tool centre point AT -130 800 0 (world coordinates)") == 0);
  CHECK(ok.out.find("POINTS line:\nP1 ") != std::string::npos);
  const auto far = runCli({"ik", "scara-pick", "--", "-600", "800", "0"});
  CHECK(far.code == 2);
  CHECK(far.err.find("the point is 375 out of the arm's reach") != std::string::npos);
  const auto badVector = runCli({"ik", "scara-pick", "--approach", "0,x,0", "--", "-130", "800", "0"});
  CHECK(badVector.code == 2);
  CHECK(badVector.err.find("--approach: error: value 2 'x' is not a number") != std::string::npos);
  const auto noRobot = runCli({"ik", "no-such-robot", "1", "2", "3"});
  CHECK(noRobot.code == 2);
}

TEST_CASE("disasm and the trace show where a pose point came from", "[cli][ik][pose]") {
  const std::string program = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/stack_blocks.rsp";
  const auto listing = runCli({"disasm", program});
  REQUIRE(listing.code == 0);
  CHECK(listing.out.find("; PICK = ") != std::string::npos);
  CHECK(listing.out.find(" (from AT -130 819 0)") != std::string::npos);
  CHECK(listing.out.find("; from AT -180 859 -45 GRIP 0\n") != std::string::npos);
  const auto text = runCli({"run", program, "--trace"});
  REQUIRE(text.code == 0);
  CHECK(text.out.find("PICK from AT -130 819 0") != std::string::npos);
  const auto json = runCli({"run", program, "--trace=json"});
  REQUIRE(json.code == 0);
  std::istringstream lines(json.out);
  std::string first;
  std::getline(lines, first);
  const auto j = nlohmann::json::parse(first);
  CHECK(j["op"] == "MOVEP");
  CHECK(j["point_from"] == "AT -130 870 0 GRIP 0");  // the words one space apart
}

TEST_CASE("robotsim ik: a five-axis arm refuses an approach out of its arm's plane", "[cli][ik]") {
  // The XR-3's joint 1 turns about its design y axis; at (300, 200, 0) the arm's plane is z = 0,
  // so the approach (0, -1, 0) lies in it and (0, -1, 1) does not.
  CHECK(runCli({"ik", "rhino-xr3", "--frame", "robot", "--approach", "0,-1,0", "300", "200", "0"}).code == 0);
  const auto r = runCli({"ik", "rhino-xr3", "--frame", "robot", "--approach", "0,-1,1", "300", "200", "0"});
  CHECK(r.code == 2);
  CHECK(r.err.find("keeps its approach in the plane of its arm") != std::string::npos);
  // The hint names the options that give it (robotsim ik's words, not a program's).
  CHECK(r.err.find("hint: here it reaches --approach 0,-1,0 --normal ") != std::string::npos);
}

TEST_CASE("robotsim ik --solution N solves one configuration alone", "[cli][ik]") {
  // The SCARA's two configurations for (-130, 800, 0): elbow + is what the
  // command chooses anyway (docs/cli.md's example), elbow - the mirror.
  const auto one = runCli({"ik", "scara-pick", "--solution", "1", "--", "-130", "800", "0"});
  REQUIRE(one.code == 0);
  CHECK(one.out.find("solution 1 of 2 asked for (elbow +), solved alone") != std::string::npos);
  CHECK(one.out.find("P1 -513 492 333 222 0") != std::string::npos);
  const auto two = runCli({"ik", "scara-pick", "--solution", "2", "--json", "--", "-130", "800", "0"});
  REQUIRE(two.code == 0);
  const auto j = nlohmann::ordered_json::parse(two.out);  // the encoders in motor order
  CHECK(j["solution"] == 2);
  CHECK(j["points_line"] != "P1 -513 492 333 222 0");
  std::string list;
  for (const auto& [letter, v] : j["encoders"].items()) list += (list.empty() ? "" : ",") + std::to_string(v.get<int>());
  // where's forward kinematics puts the other elbow at the same point,
  // within what whole counts allow (the same 0.2341 as elbow +).
  const auto w = runCli({"where", "scara-pick", "--encoders", list, "--json"});
  REQUIRE(w.code == 0);
  const auto tcp = nlohmann::json::parse(w.out)["position"];
  CHECK(std::hypot(tcp[0].get<double>() + 130, tcp[1].get<double>() - 800, tcp[2].get<double>()) < 0.25);
  // A configuration the family does not have.
  const auto bad = runCli({"ik", "scara-pick", "--solution", "3", "--", "-130", "800", "0"});
  CHECK(bad.code == 2);
  CHECK(bad.err.find("--solution: error: the scara family has 2 configurations: N from 1 to 2") != std::string::npos);
}

namespace {

// `robotsim ik CELL -- X Y Z --json` succeeds, and `where` puts the tool centre point there (forward
// kinematics, which does not use the inverse): within what whole encoder counts allow.
nlohmann::ordered_json ikReachedByWhere(const std::string& cell, double x, double y, double z) {
  const auto r = runCli({"ik", cell, "--json", "--", fmt::format("{}", x), fmt::format("{}", y), fmt::format("{}", z)});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::ordered_json::parse(r.out);
  std::string list;
  for (const auto& [letter, v] : j["encoders"].items()) list += (list.empty() ? "" : ",") + std::to_string(v.get<int>());
  const auto w = runCli({"where", cell, "--encoders", list, "--json"});
  REQUIRE(w.code == 0);
  const auto wj = nlohmann::json::parse(w.out);
  const double dx = wj["position"][0].get<double>() - x, dy = wj["position"][1].get<double>() - y,
               dz = wj["position"][2].get<double>() - z;
  CHECK(std::sqrt(dx * dx + dy * dy + dz * dz) < 2.0);
  // The approach it reports is the one `where` finds.
  for (int i = 0; i < 3; ++i)
    CHECK(wj["matrix"][static_cast<std::size_t>(i)][2].get<double>() ==
          Approx(j["approach"][static_cast<std::size_t>(i)].get<double>()).margin(0.01));
  return j;
}

}  // namespace

TEST_CASE("robotsim ik with a position only tries the orientations a six-axis arm leaves free", "[cli][ik]") {
  // 850 out along the world's X at the PUMA's shoulder height (and its 149.09 shoulder offset): with the
  // tool pointing down as at home, joint 3 would leave its range (and the point is out of reach from the
  // home orientation's wrist centre a little further out); turned 50 degrees, the wrist reaches it.
  const auto kept = runCli({"ik", "puma-cell", "--approach", "0,-1,0", "--", "850", "660", "-149.09"});
  CHECK(kept.code == 2);
  CHECK(kept.err.find("outside its range -450..2250") != std::string::npos);
  CHECK(kept.err.find("the normal was kept from the previous point: give --normal too") != std::string::npos);
  const auto j = ikReachedByWhere("puma-cell", 850, 660, -149.09);
  CHECK(j["orientations_tried"].get<int>() > 0);
  CHECK(j["turned"].get<double>() == Approx(50));
  CHECK(j["approach"][1].get<double>() > -0.99);  // no longer straight down
  const auto text = runCli({"ik", "puma-cell", "--", "850", "660", "-149.09"});
  REQUIRE(text.code == 0);
  CHECK(text.out.find("the orientation kept from home does not reach it; free orientation ") != std::string::npos);
  CHECK(text.out.find(", turned 50 degrees from it, does: --approach ") != std::string::npos);
  // Where the kept orientation reaches, nothing is searched: the answer is the compiler's.
  const auto near = ikReachedByWhere("puma-cell", 700, 660, -149.09);
  CHECK(near["orientations_tried"].get<int>() == 0);
  CHECK(near["turned"].get<double>() == 0);
}

TEST_CASE("robotsim ik with a position only tries every pitch a five-axis arm leaves free", "[cli][ik]") {
  // The XR-4 (base at y 750) pointing down, as at home, reaches no further out than about 430 at y 1000;
  // pitched up 40 degrees it reaches 550.
  const auto kept = runCli({"ik", "xr4-cell", "--approach", "0,-1,0", "--", "550", "1000", "0"});
  CHECK(kept.code == 2);
  CHECK(kept.err.find("out of the arm's reach") != std::string::npos);
  const auto j = ikReachedByWhere("xr4-cell", 550, 1000, 0);
  CHECK(j["family"] == "articulated-5");
  CHECK(j["turned"].get<double>() == Approx(40));
}

TEST_CASE("robotsim ik: a refusal after every free orientation, and where the options would help", "[cli][ik]") {
  // 1000 out: no orientation reaches it, and the hint does not offer --approach or --normal.
  const auto far = runCli({"ik", "puma-cell", "--", "1000", "660", "-149.09"});
  CHECK(far.code == 2);
  CHECK(far.err.find("the point is 136.2 out of the arm's reach") != std::string::npos);
  CHECK(far.err.find("hint: 864 other orientations the arm leaves free were tried, and none reaches the point: move "
                     "it nearer the robot") != std::string::npos);
  CHECK(far.err.find("--approach") == std::string::npos);
  // 875 out: some orientations reach the point but put a motor out of range; one between the search's
  // steps might not, which --approach and --normal can give.
  const auto edge = runCli({"ik", "puma-cell", "--", "875", "660", "-149.09"});
  CHECK(edge.code == 2);
  CHECK(edge.err.find("(in steps of 10 degrees), and none reaches it with every motor in range: --approach and "
                      "--normal try one between those steps, or move the point") != std::string::npos);
  // A cartesian arm leaves nothing free: its refusal stands as it was.
  const auto gantry = runCli({"ik", "gantry-cell", "--", "5000", "200", "400"});
  CHECK(gantry.code == 2);
  CHECK(gantry.err.find("orientations") == std::string::npos);
}
