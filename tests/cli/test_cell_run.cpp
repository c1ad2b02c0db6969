// Issue 36: several robots of one cell each run their own program on the
// cell's one clock. The times are checked against runs of one robot: a
// robot alone takes t1 for MOVE 100 and t2 for MOVE 200 (the same robot
// model, the same motor), so in the cell the wire without AFTER answers
// right's WAITFOR at t1, right ends at t1 + t2, and left, waiting for
// right's output, ends at t1 + t2 + t1.
#include <catch2/catch.hpp>

#include <map>
#include <sstream>
#include <string>

#include "tests/cli/cli_support.h"
#include <nlohmann/json.hpp>

namespace cell_run_test {

std::string cellText(bool swapped, const std::string& after = "") {
  const std::string left = "  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM left.rsp\n";
  const std::string right = "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM right.rsp\n";
  return "WORKCELL two\n" + (swapped ? right + left : left + right) + "  WIRE left.OUT 1 TO right.IN 2" + after +
         "\n  WIRE right.OUT 1 TO left.IN 1\nEND\n";
}

const char* const kLeft =
    "        MOVE 100 0 0 0 0 0\n"
    "        OUTSIG 1 ON\n"
    "        WAITFOR 1 ON\n"
    "        MOVE -100 0 0 0 0 0\n"
    "        END\n";
const char* const kRight =
    "        WAITFOR 2 ON\n"
    "        MOVE 200 0 0 0 0 0\n"
    "        OUTSIG 1 ON\n"
    "        END\n";

nlohmann::json runJson(const std::vector<std::string>& args) {
  const auto r = rs::testing::runCli(args);
  INFO(r.err);
  REQUIRE(r.code == 0);
  return nlohmann::json::parse(r.out);
}

// A robot's `time` in a cell run's JSON summary.
double timeOf(const nlohmann::json& j, const std::string& robot) {
  for (const auto& r : j.at("robots"))
    if (r.at("name") == robot) return r.at("time").get<double>();
  FAIL("no robot " << robot);
  return 0;
}

// How long one move takes on an XR-4 running alone.
double aloneTime(const rs::testing::TempDir& dir, const std::string& move) {
  dir.write("alone.rsp", "        " + move + "\n        END\n");
  return runJson({"run", dir.file("alone.rsp"), "--cell", "xr4-cell", "--format=json"}).at("time").get<double>();
}

}  // namespace cell_run_test

using namespace cell_run_test;

TEST_CASE("cell run: two robots hand a signal back and forth on one clock", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("left.rsp", kLeft);
  dir.write("right.rsp", kRight);
  const double t1 = aloneTime(dir, "MOVE 100 0 0 0 0 0");
  const double t2 = aloneTime(dir, "MOVE 200 0 0 0 0 0");
  REQUIRE(t1 > 0);
  REQUIRE(t2 > t1);

  for (const bool swapped : {false, true}) {
    INFO("robots in the cell's order swapped: " << swapped);
    dir.write("c.rsd", cellText(swapped));
    const nlohmann::json j = runJson({"run", "--cell", dir.file("c.rsd"), "--format=json"});
    CHECK(j.at("status") == "finished");
    REQUIRE(j.at("robots").size() == 2);
    CHECK(timeOf(j, "right") == Approx(t1 + t2).margin(2e-6));
    CHECK(timeOf(j, "left") == Approx(2 * t1 + t2).margin(2e-6));
    CHECK(j.at("time").get<double>() == Approx(2 * t1 + t2).margin(2e-6));
    for (const auto& r : j.at("robots")) {
      CHECK(r.at("status") == "finished");
      CHECK(r.at("outputs").at(0) == true);
      CHECK(r.contains("motors"));
      CHECK(r.contains("tcp"));
      CHECK(r.contains("variables"));
      CHECK(r.contains("inputs"));
    }
  }
  // The same cell and programs give the same bytes, whatever the robots' order.
  dir.write("c.rsd", cellText(false));
  const auto a = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--trace"});
  const auto b = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--trace"});
  CHECK(a.out == b.out);
  CHECK(a.out.find("right:      0.333  input 2 ON: wire from left.OUT 1") != std::string::npos);
}

TEST_CASE("cell run: a wire's AFTER delays the other robot by exactly that", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("left.rsp", kLeft);
  dir.write("right.rsp", kRight);
  dir.write("c.rsd", cellText(false, " AFTER 0.5"));
  const double t1 = aloneTime(dir, "MOVE 100 0 0 0 0 0");
  const double t2 = aloneTime(dir, "MOVE 200 0 0 0 0 0");
  const nlohmann::json j = runJson({"run", "--cell", dir.file("c.rsd"), "--format=json"});
  CHECK(timeOf(j, "right") == Approx(t1 + 0.5 + t2).margin(2e-6));
  CHECK(timeOf(j, "left") == Approx(2 * t1 + 0.5 + t2).margin(2e-6));
}

TEST_CASE("cell run: LABEL=FILE overrides a PROGRAM, and a deadlock names both robots", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", cellText(false));
  dir.write("left.rsp", kLeft);
  dir.write("right.rsp", kRight);
  // Each waits for the other before it writes its own output.
  dir.write("l2.rsp", "        MOVE 100 0 0 0 0 0\n        WAITFOR 1 ON\n        OUTSIG 1 ON\n        END\n");
  dir.write("r2.rsp", "        WAITFOR 2 ON\n        OUTSIG 1 ON\n        END\n");
  const auto r = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "left=" + dir.file("l2.rsp"),
                                      "right=" + dir.file("r2.rsp")});
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(r.err.find("l2.rsp:2:1: error: deadlock: left waits at " + dir.file("l2.rsp") +
                   ":2 for input 1 (wired from right.OUT 1); right waits at " + dir.file("r2.rsp") +
                   ":1 for input 2 (wired from left.OUT 1)") != std::string::npos);
  CHECK(r.out.find("robot left: ") != std::string::npos);
  CHECK(r.out.find("stopped at line 2") != std::string::npos);

  const auto ghost = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "ghost=" + dir.file("l2.rsp")});
  CHECK(ghost.code == 2);
  CHECK(ghost.err.find("error: workcell two has no robot labelled `ghost`") != std::string::npos);
  CHECK(ghost.err.find("hint: the cell's robots are `left`, `right`") != std::string::npos);
}

TEST_CASE("cell run: a runtime error in one robot stops the cell and names it", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", cellText(false));
  dir.write("left.rsp", kLeft);
  // Motor F's range is -1750..1750: the second pass of the loop leaves it.
  dir.write("right.rsp", "        SET T 0\nagain:  MOVE 1000 0 0 0 0 0\n        ADD T 1\n        JMPVAR T < 4 again\n        END\n");
  const auto r = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--format=json"});
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(r.err.find("right.rsp:2:") != std::string::npos);
  CHECK(r.err.find("robot right stopped the cell") != std::string::npos);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("status") == "error");
  for (const auto& robot : j.at("robots"))
    CHECK(robot.at("status") == (robot.at("name") == "right" ? "runtime error" : "stopped"));
}

// examples/two_robots: by hand, with motor F at 300 counts/s (its SPEED in
// stdlib/robots/rhino-xr4.rsd), each MOVE of 300 takes 1 s. left: in and
// out 0-2 s, OUT 1 ON at 2. right: IN 1 ON at 2 (no AFTER), in and out 2-4,
// OUT 1 ON at 4. left: IN 1 ON at 4.25 (AFTER 0.25), OUT 1 OFF, in and out
// 4.25-6.25, OUT 1 ON, waits (its IN 1 went OFF at 4.5, 0.25 after right's
// OUT 1 OFF at 4.25). right: IN 1 ON at 6.25, in and out 6.25-8.25, OUT 1
// ON at 8.25. left: IN 1 ON at 8.5, ends at 8.5 with TURNS 2; right sees its
// IN 1 OFF at 8.5 and ends then too; left's IN 1 is still ON (it goes OFF
// at 8.75, after every program has ended).
TEST_CASE("cell run: the interlock example takes turns as worked out by hand", "[cell-run][robots][examples]") {
  const std::string cell = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/interlock.rsd";
  const nlohmann::json j = runJson({"run", "--cell", cell, "--format=json"});
  CHECK(j.at("time").get<double>() == Approx(8.5).margin(1e-6));
  CHECK(timeOf(j, "left") == Approx(8.5).margin(1e-6));
  CHECK(timeOf(j, "right") == Approx(8.5).margin(1e-6));
  for (const auto& r : j.at("robots")) {
    CHECK(r.at("variables").at("TURNS") == 2);
    CHECK(r.at("inputs").at(0) == (r.at("name") == "left"));
    CHECK(r.at("outputs").at(0) == false);
  }
}

// Two XR-4s facing each other (right turned 180 degrees about y). At 600
// apart they stand clear at home, but left's shoulder (motor E) swung by
// 600 counts brings its wrist into right's gripper; at 800 apart the same
// move passes. Right only waits, so the robots meet only if right is an
// obstacle to left's swept check.
TEST_CASE("cell run: every robot is an obstacle to the other", "[cell-run][robots][collision]") {
  rs::testing::TempDir dir;
  const auto cellAt = [&](int x) {
    dir.write("c.rsd", "WORKCELL face\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n  ROBOT rhino-xr4 AT " +
                           std::to_string(x) + " 750 0 ROTATE Y 180 AS right PROGRAM r.rsp\nEND\n");
  };
  dir.write("l.rsp", "        MOVE 0 600 0 0 0 0\n        END\n");
  dir.write("r.rsp", "        DELAY 3\n        END\n");
  cellAt(600);
  const auto near = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--format=json"});
  INFO(near.err);
  CHECK(near.code == 1);
  CHECK(near.err.find("l.rsp:1:9: error: runtime error: collision at ") != std::string::npos);
  CHECK(near.err.find("of robot 'left' hits ") != std::string::npos);
  CHECK(near.err.find("of robot 'right'") != std::string::npos);
  CHECK(near.err.find("robot left stopped the cell") != std::string::npos);
  // The same check with collisions off finishes: the error was the other robot.
  const auto off = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--collisions=off"});
  CHECK(off.code == 0);
  cellAt(800);
  const auto far = rs::testing::runCli({"run", "--cell", dir.file("c.rsd")});
  INFO(far.err);
  CHECK(far.code == 0);
  // Right moves into left's space while left stands at home: right's move is the one that hits.
  dir.write("l.rsp", "        DELAY 3\n        END\n");
  dir.write("r.rsp", "        MOVE 0 600 0 0 0 0\n        END\n");
  cellAt(600);
  const auto other = rs::testing::runCli({"run", "--cell", dir.file("c.rsd")});
  CHECK(other.code == 1);
  CHECK(other.err.find("r.rsp:1:9: error: runtime error: collision at ") != std::string::npos);
  CHECK(other.err.find("of robot 'right' hits ") != std::string::npos);
}

// examples/two_robots/handover: the packer's DROP point is (-300, 819, 40),
// 1 below the top of the 40-unit block it carries, so the block comes to
// rest with its centre at (-300, 800, 40) on the pallet (whose top is at
// 780); the feeder signals once it is parked; `check --strict` passes with
// the two running together (the packer alone would wait for ever).
TEST_CASE("cell run: the hand-over example takes the block to the packer's corner", "[cell-run][robots][examples]") {
  const std::string cell = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/handover.rsd";
  const nlohmann::json j = runJson({"run", "--cell", cell, "--format=json"});
  CHECK(j.at("status") == "finished");
  bool found = false;
  for (const auto& o : j.at("objects"))
    if (o.at("name") == "block") {
      found = true;
      CHECK(o.at("centre").at(0).get<double>() == Approx(-300).margin(0.1));
      CHECK(o.at("centre").at(1).get<double>() == Approx(800).margin(0.1));
      CHECK(o.at("centre").at(2).get<double>() == Approx(40).margin(0.1));
      CHECK(o.at("held") == false);
    }
  CHECK(found);
  CHECK(timeOf(j, "packer") > timeOf(j, "feeder"));
  for (const auto& r : j.at("robots"))
    CHECK(r.at(r.at("name") == "feeder" ? "outputs" : "inputs").at(0) == true);
  const auto check = rs::testing::runCli({"check", "--cell", cell, "--strict"});
  INFO(check.err);
  CHECK(check.code == 0);
  CHECK(check.out.find("robot packer: ") != std::string::npos);
  CHECK(check.out.find("packer.rsp: ok (10 instructions executed") != std::string::npos);
}

// The other robot is posed where its motors are, not at home: left first
// turns its waist (motor F, 0.1 degree a count) a quarter turn away, then
// lets right reach into the space its arm had at home.
TEST_CASE("cell run: a robot that moved out of the way is no obstacle there", "[cell-run][robots][collision]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd",
            "WORKCELL face\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n  ROBOT rhino-xr4 AT 600 750 0 ROTATE Y "
            "180 AS right PROGRAM r.rsp\n  WIRE left.OUT 1 TO right.IN 1\nEND\n");
  dir.write("l.rsp", "        MOVE 900 0 0 0 0 0\n        OUTSIG 1 ON\n        END\n");
  dir.write("r.rsp", "        WAITFOR 1 ON\n        MOVE 0 600 0 0 0 0\n        END\n");
  const auto r = rs::testing::runCli({"run", "--cell", dir.file("c.rsd")});
  INFO(r.err);
  CHECK(r.code == 0);
  // Without waiting for it, right reaches in while left is still there.
  dir.write("r.rsp", "        MOVE 0 600 0 0 0 0\n        END\n");
  const auto early = rs::testing::runCli({"run", "--cell", dir.file("c.rsd")});
  CHECK(early.code == 1);
  CHECK(early.err.find("of robot 'right' hits ") != std::string::npos);
}

TEST_CASE("cell run: the JSON trace names each line's robot", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", cellText(false));
  dir.write("left.rsp", kLeft);
  dir.write("right.rsp", kRight);
  const auto r = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--trace=json"});
  REQUIRE(r.code == 0);
  std::istringstream lines(r.out);
  std::string line;
  std::map<std::string, int> steps;
  while (std::getline(lines, line)) {
    if (!line.starts_with("{\"robot\"")) continue;
    const auto j = nlohmann::json::parse(line);
    if (j.contains("instr")) ++steps[j.at("robot").get<std::string>()];
  }
  CHECK(steps["left"] == 5);   // left.rsp's five instructions
  CHECK(steps["right"] == 4);  // right.rsp's four
}
