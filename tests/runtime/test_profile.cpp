// `robotsim run --profile` (runtime/run/profile.h, tools/cli/lib/profile_report.h):
// a small program on the default robot whose every figure is worked out by
// hand below from the motor speeds (stdlib/default_robot.cpp: E 400, D 400,
// C 300, B 500 units/s, gripper A 200 units/s).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "../cli/cli_support.h"

namespace {

// line  instruction               time (s)  kind      by hand
//  1    MOVETO 400 0 0 0 0        0 -> 1    moving    E 0->400 at 400/s: 1 s
//  2    DELAY 2                   1 -> 3    waiting
//  3    GOSUB grab                3
//  4    GOSUB grab                4
//  5    END                       5
//  6    grab: MOVETO 400 0 0 0 100
//         1st call                3 -> 3.5  gripper   A 0->100 at 200/s: 0.5 s, nothing else moves
//         2nd call                4 -> 4.5  moving    D back 200->0 at 400/s: 0.5 s (A stays)
//  7    MOVE 0 200 0 0 0
//         1st call                3.5 -> 4  moving    D 0->200 at 400/s: 0.5 s
//         2nd call                4.5 -> 5  moving    D 0->200 again: 0.5 s
//  8    RETURN (twice)            0
// Total 5 s: moving 1 + 0.5 + 0.5 + 0.5 = 2.5 s (50 %), waiting 2 s (40 %),
// gripper 0.5 s (10 %); five moves.
const char* kProfiledProgram =
    "        MOVETO 400 0 0 0 0\n"
    "        DELAY 2\n"
    "        GOSUB grab\n"
    "        GOSUB grab\n"
    "        END\n"
    "grab:   MOVETO 400 0 0 0 100\n"
    "        MOVE 0 200 0 0 0\n"
    "        RETURN\n";

}  // namespace

TEST_CASE("run --profile --format=json gives the hand-computed times", "[profile]") {
  rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp", kProfiledProgram);
  const rs::testing::CliResult r = rs::testing::runCli({"run", program, "--profile", "--format=json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& p = j.at("profile");
  CHECK(p["total_us"] == 5'000'000);
  CHECK(p["moving_us"] == 2'500'000);
  CHECK(p["waiting_us"] == 2'000'000);
  CHECK(p["gripper_us"] == 500'000);
  CHECK(p["other_us"] == 0);
  CHECK(p["moves"] == 5);  // lines 1, 6, 7, 6, 7

  std::map<int, std::pair<long, int>> lines;  // line -> (total, steps)
  for (const auto& l : p["lines"]) lines[l["line"].get<int>()] = {l["total_us"].get<long>(), l["steps"].get<int>()};
  CHECK(lines == std::map<int, std::pair<long, int>>{{1, {1'000'000, 1}},
                                                      {2, {2'000'000, 1}},
                                                      {3, {0, 1}},
                                                      {4, {0, 1}},
                                                      {5, {0, 1}},
                                                      {6, {1'000'000, 2}},
                                                      {7, {1'000'000, 2}},
                                                      {8, {0, 2}}});

  REQUIRE(p["labels"].size() == 2);
  CHECK(p["labels"][0]["name"] == "(start)");
  CHECK(p["labels"][0]["total_us"] == 3'000'000);
  CHECK(p["labels"][0]["steps"] == 5);
  CHECK(p["labels"][1]["name"] == "grab");
  CHECK(p["labels"][1]["line"] == 6);
  CHECK(p["labels"][1]["total_us"] == 2'000'000);
  CHECK(p["labels"][1]["gripper_us"] == 500'000);
  CHECK(p["labels"][1]["steps"] == 6);

  REQUIRE(p["subroutines"].size() == 1);
  CHECK(p["subroutines"][0]["name"] == "grab");
  CHECK(p["subroutines"][0]["calls"] == 2);
  CHECK(p["subroutines"][0]["total_us"] == 2'000'000);
  CHECK(p["subroutines"][0]["moving_us"] == 1'500'000);

  // Longest first; the four 0.5 s moves in the order they ran.
  const nlohmann::json& slow = p["slowest_moves"];
  REQUIRE(slow.size() == 5);
  CHECK(slow[0]["line"] == 1);
  CHECK(slow[0]["duration_us"] == 1'000'000);
  CHECK(slow[0]["motor"] == "E");
  CHECK(slow[1]["line"] == 6);
  CHECK(slow[1]["motor"] == "A");
  CHECK(slow[1]["start_us"] == 3'000'000);
  CHECK(slow[2]["line"] == 7);
  CHECK(slow[2]["from"] == 0);
  CHECK(slow[2]["to"] == 200);
  CHECK(slow[3]["line"] == 6);
  CHECK(slow[3]["motor"] == "D");
  CHECK(slow[3]["start_us"] == 4'000'000);
  CHECK(slow[3]["from"] == 200);
  CHECK(slow[3]["to"] == 0);
  CHECK(slow[4]["start_us"] == 4'500'000);
}

TEST_CASE("run --profile prints the same figures as text", "[profile]") {
  rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp", kProfiledProgram);
  const rs::testing::CliResult r = rs::testing::runCli({"run", program, "--profile"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("profile: 5.000 s simulated, 5 moves"));
  CHECK_THAT(r.out, Catch::Contains("moving         2.500 s   50.0 %"));
  CHECK_THAT(r.out, Catch::Contains("waiting        2.000 s   40.0 %"));
  CHECK_THAT(r.out, Catch::Contains("gripper        0.500 s   10.0 %"));
  CHECK_THAT(r.out, Catch::Contains("grab (line 6)"));
  CHECK_THAT(r.out, Catch::Contains("1. line 1: 1.000 s from 0.000 s (motor E 0 -> 400)"));
  // Without --profile, no profile.
  CHECK_THAT(rs::testing::runCli({"run", program}).out, !Catch::Contains("profile:"));
}

TEST_CASE("run --profile refuses a real controller", "[profile]") {
  rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp", kProfiledProgram);
  const rs::testing::CliResult r = rs::testing::runCli({"run", program, "--profile", "--device", "/dev/null"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--profile: error:"));
}

TEST_CASE("a subroutine that calls itself counts each moment once", "[profile]") {
  // r is entered three times, each call inside the one before; each runs
  // one MOVE of E by 100 at 400 units/s = 0.25 s. Inside r the whole time
  // from the first call's start: 3 × 0.25 = 0.75 s (adding each active
  // call's share would give 0.25 · (1 + 2 + 3) = 1.5 s).
  rs::testing::TempDir dir;
  const std::string program = dir.write("r.rsp",
                                        "        GOSUB r\n"
                                        "        END\n"
                                        "r:      ADD N 1\n"
                                        "        MOVE 100 0 0 0 0\n"
                                        "        JMPVAR N = 3 out\n"
                                        "        GOSUB r\n"
                                        "out:    RETURN\n");
  const rs::testing::CliResult r = rs::testing::runCli({"run", program, "--profile", "--format=json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json p = nlohmann::json::parse(r.out).at("profile");
  CHECK(p["total_us"] == 750'000);
  REQUIRE(p["subroutines"].size() == 1);
  CHECK(p["subroutines"][0]["calls"] == 3);
  CHECK(p["subroutines"][0]["total_us"] == 750'000);
  // By label: r's region (lines 3..6) holds every move; out's only RETURNs.
  REQUIRE(p["labels"].size() == 3);
  CHECK(p["labels"][1]["name"] == "r");
  CHECK(p["labels"][1]["total_us"] == 750'000);
  CHECK(p["labels"][2]["name"] == "out");
  CHECK(p["labels"][2]["steps"] == 3);
  CHECK(p["labels"][2]["total_us"] == 0);
}

TEST_CASE("an image compiled for an accelerating cell runs with the same timing as its source", "[profile]") {
  // The IRB 120's G turns 90 degrees: 449287 µs (tests/library); the image
  // (1.1, with its motion section) carries the accelerations beside the
  // cell's geometry.
  rs::testing::TempDir dir;
  const std::string program = dir.write("t.rsp", "MOVE 9000 0 0 0 0 0 0\nEND\n");
  const std::string image = dir.file("t.rsb");
  REQUIRE(rs::testing::runCli({"compile", program, "--cell", "irb120-cell", "-o", image}).code == 0);
  CHECK(rs::testing::readBytes(image)[10] == 1);  // minor version 1
  const rs::testing::CliResult r = rs::testing::runCli({"run", image, "--profile", "--format=json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.out)["profile"]["total_us"] == 449287);
}
