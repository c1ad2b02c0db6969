// Issue 36: several robots of one cell each run their own program on the
// cell's one clock. The times are checked against runs of one robot: a
// robot alone takes t1 for MOVE 100 and t2 for MOVE 200 (the same robot
// model, the same motor), so in the cell the wire without AFTER answers
// right's WAITFOR at t1, right ends at t1 + t2, and left, waiting for
// right's output, ends at t1 + t2 + t1.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

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
  // Without waiting for it, right reaches in while left is still there
  // (left waits 3 s before it turns; right's reach takes 2 s): right's
  // check poses left where it is at each moment, here at home.
  dir.write("l.rsp", "        DELAY 3\n        MOVE 900 0 0 0 0 0\n        OUTSIG 1 ON\n        END\n");
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

// examples/two_robots/relay: a hand-over from gripper to gripper. The
// taker closes with its tool centre point at (-310, 840, 0), 100 from the
// bar's centre in x (the bar runs along x from -330 to -90, centre x -210,
// z 0); it carries the bar rigidly and sets it down straight, so the
// bar's centre ends 100 from the taker's tool centre point in x-z, and at
// y 780 + 15 = 795 (resting on the pallet's top, the bar 30 high).
TEST_CASE("cell run: a part handed from gripper to gripper goes on with the taker", "[cell-run][robots][examples]") {
  const std::string cell = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/relay.rsd";
  const auto text = rs::testing::runCli({"run", "--cell", cell, "--trace"});
  INFO(text.err);
  REQUIRE(text.code == 0);
  CHECK(text.out.find("takes bar (object 3) from robot 'giver'") != std::string::npos);
  CHECK(text.out.find("lets go of bar (object 3): robot 'taker' has it") != std::string::npos);
  // The JSON trace says the same: from whom, to whom.
  const auto json = rs::testing::runCli({"run", "--cell", cell, "--trace=json"});
  REQUIRE(json.code == 0);
  std::istringstream lines(json.out);
  std::string line;
  int from = 0, to = 0;
  while (std::getline(lines, line)) {
    if (!line.starts_with("{\"robot\"")) continue;
    const auto j = nlohmann::json::parse(line);
    if (!j.contains("grasp")) continue;
    if (j.at("grasp").contains("from")) from += j.at("robot") == "taker" && j.at("grasp").at("from") == "giver";
    if (j.at("grasp").contains("to")) to += j.at("robot") == "giver" && j.at("grasp").at("to") == "taker";
  }
  CHECK(from == 1);
  CHECK(to == 1);
  const nlohmann::json j = runJson({"run", "--cell", cell, "--format=json"});
  CHECK(j.at("status") == "finished");
  std::vector<double> tcp;
  for (const auto& r : j.at("robots"))
    if (r.at("name") == "taker") tcp = r.at("tcp").get<std::vector<double>>();
  REQUIRE(tcp.size() == 3);
  bool found = false;
  for (const auto& o : j.at("objects"))
    if (o.at("name") == "bar") {
      found = true;
      const auto c = o.at("centre").get<std::vector<double>>();
      CHECK(std::hypot(c[0] - tcp[0], c[2] - tcp[2]) == Approx(100).margin(0.05));
      CHECK(c[1] == Approx(795).margin(0.01));
      CHECK(o.at("held") == false);
    }
  CHECK(found);
  const auto check = rs::testing::runCli({"check", "--cell", cell, "--strict"});
  INFO(check.err);
  CHECK(check.code == 0);
}

// While both grippers hold the bar it stays where the giver held it when
// the taker closed: the giver took it 0.96 below its top (tool centre
// point at 809.04, the bar's top at 810) and lifted it to 840, so its
// centre is at 795 + 30.96 = 825.96; the giver then moves down 10 without
// opening, and the bar does not follow.
TEST_CASE("cell run: a part two grippers hold stays put", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  const std::string examples = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/";
  const std::string cell = rs::testing::readBytes(examples + "relay.rsd");
  dir.write("relay.rsd", cell);
  dir.write("giver.rsp",
            "        MOVEP ABOVE\n        MOVEP PICK\n        MOVEP TAKE\n        MOVEP LIFT\n        OUTSIG 1 ON\n"
            "        WAITFOR 1 ON\n        MOVEP LOWER\n        END\nPOINTS\n"
            "ABOVE AT -110 870 0 APPROACH 0 -1 0 NORMAL 0 0 1 GRIP 0\nPICK AT -110 809 0\n"
            "TAKE AT -110 809 0 GRIP 120\nLIFT AT -110 840 0\nLOWER AT -110 830 0\n");
  dir.write("taker.rsp",
            "        WAITFOR 1 ON\n        MOVEP ABOVE\n        MOVEP PICK\n        MOVEP TAKE\n        OUTSIG 1 ON\n"
            "        END\nPOINTS\nABOVE AT -310 870 0 APPROACH 0 -1 0 NORMAL 0 0 1 GRIP 0\nPICK AT -310 840 0\n"
            "TAKE AT -310 840 0 GRIP 120\n");
  const nlohmann::json j = runJson({"run", "--cell", dir.file("relay.rsd"), "--format=json"});
  CHECK(j.at("status") == "finished");
  bool found = false;
  for (const auto& o : j.at("objects"))
    if (o.at("name") == "bar") {
      found = true;
      CHECK(o.at("centre").at(0).get<double>() == Approx(-210).margin(0.05));
      CHECK(o.at("centre").at(1).get<double>() == Approx(825.96).margin(0.01));
      CHECK(o.at("held") == true);
    }
  CHECK(found);
}

// A part let go where another robot's part rested before that robot took
// it away settles on what is really there: the giver carries the bar
// (top at 810 where it lay) off to its parking place; the taker lets a
// block go with its tool centre point at 860.04 (the block's bottom 1 +
// 40 below it, at 821.04), over the bar's old place, and the block falls
// onto the pallet (top at 780): 41.04, not 11.04 onto where the bar was.
TEST_CASE("cell run: a part let go does not settle on a part another robot carried away", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd",
            "WORKCELL ghost\n  ROBOT rhino-scara AT 0 750 0 AS giver PROGRAM g.rsp\n"
            "  ROBOT rhino-scara AT -420 750 0 ROTATE Y 90 AS taker PROGRAM t.rsp\n  OBJECT table AT -900 0 250\n"
            "  OBJECT pallet AT -330 750 80\n  OBJECT bar AT -330 780 15\n  OBJECT block AT -250 780 80\n"
            "  WIRE giver.OUT 1 TO taker.IN 1\nEND\nOBJECT bar\n  PART\n  BOX 0 240 30 0 30 0\nEND\n");
  dir.write("g.rsp",
            "        MOVEP ABOVE\n        MOVEP PICK\n        MOVEP TAKE\n        MOVEP LIFT\n        MOVEP PARK\n"
            "        OUTSIG 1 ON\n        END\nPOINTS\nABOVE AT -110 870 0 APPROACH 0 -1 0 NORMAL 0 0 1 GRIP 0\n"
            "PICK AT -110 809 0\nTAKE AT -110 809 0 GRIP 120\nLIFT AT -110 870 0\nPARK AT -100 870 -150\n");
  dir.write("t.rsp",
            "        WAITFOR 1 ON\n        MOVEP ABOVE\n        MOVEP PICK\n        MOVEP TAKE\n        MOVEP LIFT\n"
            "        MOVEP OVER\n        MOVEP DROP\n        END\nPOINTS\nABOVE AT -230 870 60 GRIP 0\n"
            "PICK AT -230 819 60\nTAKE AT -230 819 60 GRIP 120\nLIFT AT -230 870 60\nOVER AT -210 860 0\n"
            "DROP AT -210 860 0 GRIP 0\n");
  const auto r = rs::testing::runCli({"run", "--cell", dir.file("c.rsd"), "--trace"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("lets go of block (object 4): it settles on pallet (object 2), dropped 41.04") != std::string::npos);
}

// A program run alone on one robot of a cell of several (`run PROG --cell
// CELL --robot LABEL`, the others without programs) meets the others
// where they stand, at home: the same two facing XR-4s 600 apart as in
// "every robot is an obstacle to the other", left reaching forward.
TEST_CASE("cell run: a robot run alone meets the others standing at home", "[cell-run][robots][collision]") {
  rs::testing::TempDir dir;
  const auto cellAt = [&](int x) {
    dir.write("c.rsd", "WORKCELL face\n  ROBOT rhino-xr4 AT 0 750 0 AS left\n  ROBOT rhino-xr4 AT " + std::to_string(x) +
                           " 750 0 ROTATE Y 180 AS right\nEND\n");
  };
  dir.write("l.rsp", "        MOVE 0 600 0 0 0 0\n        END\n");
  cellAt(600);
  const auto near = rs::testing::runCli({"run", dir.file("l.rsp"), "--cell", dir.file("c.rsd"), "--robot", "left"});
  CHECK(near.code == 1);
  CHECK(near.err.find("of robot 'left' hits ") != std::string::npos);
  CHECK(near.err.find("of robot 'right'") != std::string::npos);
  cellAt(800);
  const auto far = rs::testing::runCli({"check", dir.file("l.rsp"), "--cell", dir.file("c.rsd"), "--robot", "left"});
  INFO(far.err);
  CHECK(far.code == 0);
}

// --profile of a cell: each robot's own profile and its share of the
// cell's cycle. By hand (the interlock's timeline above): each robot makes
// four moves of 1 s (4 s moving) and waits the rest of the cell's 8.5 s:
// left at its WAITFOR 2-4.25 and 6.25-8.5 (4.5 s, both ended by the wire
// from right.OUT 1); right 0-2 and 4.25-6.25 for ON, 4-4.25 and 8.25-8.5
// for OFF (4.5 s in four waits, by the wire from left.OUT 1). In the relay
// the giver ends at 9.512 s, the cell at 14.486 s: 4.974 s ended.
TEST_CASE("cell run: --profile gives each robot's profile and its share of the cell's cycle", "[cell-run][robots][profile]") {
  const std::string cell = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/interlock.rsd";
  const nlohmann::json j = runJson({"run", "--cell", cell, "--profile", "--format=json"});
  for (const auto& r : j.at("robots")) {
    INFO(r.at("name"));
    const auto& share = r.at("profile").at("cell_share");
    CHECK(share.at("cell_us") == 8500000);
    CHECK(share.at("moving_us") == 4000000);
    CHECK(share.at("waiting_us") == 4500000);
    CHECK(share.at("ended_us") == 0);
    const auto& waits = r.at("profile").at("input_waits");
    REQUIRE(waits.size() == 1);
    const bool left = r.at("name") == "left";
    CHECK(waits.at(0).at("driver") == (left ? "wire from right.OUT 1" : "wire from left.OUT 1"));
    CHECK(waits.at(0).at("waits") == (left ? 2 : 4));
    CHECK(waits.at(0).at("waiting_us") == 4500000);
  }
  const auto text = rs::testing::runCli({"run", "--cell", std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/relay.rsd",
                                         "--profile"});
  INFO(text.err);
  REQUIRE(text.code == 0);
  CHECK(text.out.find("profile of robot giver (") != std::string::npos);
  CHECK(text.out.find("profile of robot taker (") != std::string::npos);
  CHECK(text.out.find("share of the cell's cycle (14.486 s): ") != std::string::npos);
  CHECK(text.out.find("ended 34.3 %") != std::string::npos);  // 4.974 / 14.486
}

// Two XR-4s 400 apart, both placed ROTATE Y -90 so that at home each arm
// points along +z; left turns its waist +175 degrees (through +x, towards
// right), right -175 (through -x, towards left), both from time 0 at 300
// counts (30 degrees) a second: 5.833 s each. Neither the start poses
// (both along +z, 400 apart) nor the end ones (both near -z, the tips at
// x = 20.75 and 379.25) overlap; the check at each move's start and end
// saw nothing. Worked out by hand: at waist angle phi a design point
// (X, Z) of left is at world x = X sin(phi) - Z cos(phi); right is left's
// mirror image in the plane x = 200, so they first touch when left's
// farthest point reaches x = 200: the palm's corner (263.1, -36), at
// radius 265.55 and 7.79 degrees off the arm, so at phi = asin(200 /
// 265.55) - 7.79 = 41.07 degrees, t = 41.07 / 30 = 1.369 s. The check
// may see it up to a sweep step (1 unit, both palms closing at 91 units a
// second each) later: within [1.369, 1.380]. Apart by 534, the palms'
// corners pass 534 - 2 x 265.55 = 2.9 from each other: no collision.
TEST_CASE("cell run: two robots whose arms cross within one move each collide, at the time worked out by hand",
          "[cell-run][robots][collision]") {
  rs::testing::TempDir dir;
  const auto cellAt = [&](int x) {
    dir.write("c.rsd", "WORKCELL cross\n  ROBOT rhino-xr4 AT 0 750 0 ROTATE Y -90 AS left PROGRAM l.rsp\n"
                       "  ROBOT rhino-xr4 AT " + std::to_string(x) + " 750 0 ROTATE Y -90 AS right PROGRAM r.rsp\nEND\n");
  };
  dir.write("l.rsp", "        MOVE 1750 0 0 0 0 0\n        END\n");
  dir.write("r.rsp", "        MOVE -1750 0 0 0 0 0\n        END\n");
  cellAt(400);
  const auto cross = rs::testing::runCli({"run", "--cell", dir.file("c.rsd")});
  INFO(cross.err);
  CHECK(cross.code == 1);
  const std::string::size_type at = cross.err.find("collision at ");
  REQUIRE(at != std::string::npos);
  const double seconds = std::stod(cross.err.substr(at + 13));
  CHECK(seconds >= 1.369);
  CHECK(seconds <= 1.380);
  CHECK(cross.err.find("(xr4_palm) of robot 'left' hits the gripper's base (xr4_palm) of robot 'right'") !=
        std::string::npos);
  cellAt(534);
  const auto miss = rs::testing::runCli({"run", "--cell", dir.file("c.rsd")});
  INFO(miss.err);
  CHECK(miss.code == 0);
}

TEST_CASE("cell run: the last END right after RESET: the devices' look at that instant is in the trace and the summary",
          "[cell-run][robots][devices]") {
  // The part fed at 0 s into the zone; robot a's RESET at 1 s takes it out
  // of the cell and a's END, at the same microsecond, ends the cell (b
  // ended at 0.5 s). The sensor sees it gone at 1 s, and the line is a's.
  rs::testing::TempDir dir;
  dir.write("two.rsd",
            "OBJECT blk\n  PART\n  BOX 0 10 10 0 10 0\nEND\n"
            "WORKCELL two\n"
            "  ROBOT rhino-xr4 AT 0 750 0 AS a PROGRAM a.rsp\n"
            "  ROBOT rhino-xr4 AT 3000 750 0 AS b PROGRAM b.rsp\n"
            "  FEEDER f blk AT 1500 10 30 EVERY 5 COUNT 1\n"
            "  SENSOR z ZONE 1495 1515 25 5 15 35\n"
            "END\n");
  dir.write("a.rsp", "        DELAY 1\n        RESET\n        END\n");
  dir.write("b.rsp", "        DELAY 0.5\n        END\n");
  const auto r = rs::testing::runCli({"run", "--cell", dir.file("two.rsd"), "--trace"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("b:      0.000  sensor z ON\n") != std::string::npos);
  CHECK(r.out.find("a:      1.000  sensor z OFF\n") != std::string::npos);
  CHECK(r.out.find("  sensor z        OFF, turned ON 1 time\n") != std::string::npos);
}
