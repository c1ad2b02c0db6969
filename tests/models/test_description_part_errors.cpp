// Errors in the parts of a robot description (.rsd, docs/models.md
// "Errors"): link frames, joints and grippers. As in
// test_description_errors.cpp, each case is a small file in a scratch
// directory and the exact diagnostics the library reports for it; columns
// were counted by hand (1-based, in characters).
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "tests/models/description_errors_support.h"

namespace {

using rs::compiler::Library;
using rs::testing::gripperFile;
using rs::testing::kBase;
using rs::testing::kGripperLines;
using rs::testing::kHandRobotLines;
using rs::testing::lines;
using rs::testing::robotErrors;
using rs::testing::Strings;
using rs::testing::TempDir;

}  // namespace

TEST_CASE("description: link frames", "[models]") {
  TempDir dir;
  const auto robot = [&](const std::string& frame1) {
    dir.write("r.rsd", kBase + lines({
                                    "ROBOT r",                                                 // 4
                                    "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 5
                                    "  LINK base" + frame1,                                   // 6
                                    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",   // 7
                                    "END",
                                }));
    return robotErrors(dir, "r.rsd");
  };
  SECTION("a link without FRAME") {
    CHECK(robot("") == Strings{"r.rsd:6:8: link 'base' has no FRAME (ORIGIN, XAXIS and ZAXIS points)"});
  }
  SECTION("axes not perpendicular") {
    // x = +X, z = (1, 0, 1)/sqrt 2: 45 degrees apart.
    CHECK(robot(" FRAME ORIGIN 0 0 5 XAXIS 1 0 5 ZAXIS 1 0 6") ==
          Strings{"r.rsd:6:26: link 'base': x axis and z axis are not perpendicular (the angle between them is 45 "
                  "degrees)"});
  }
  SECTION("a zero-length axis") {
    CHECK(robot(" FRAME ORIGIN 0 0 5 XAXIS 0 0 5 ZAXIS 0 0 6") ==
          Strings{"r.rsd:6:26: link 'base': x axis has zero length"});
    CHECK(robot(" FRAME ORIGIN 0 0 5 XAXIS 1 0 5 ZAXIS 0 0 5") ==
          Strings{"r.rsd:6:26: link 'base': z axis has zero length"});
  }
  SECTION("x1 not perpendicular to z0 (D-H rule)") {
    // x1 = (1, 0, 1)/sqrt 2 makes 45 degrees with z0 = +Z; z1 = (-1, 0, 1)/sqrt 2.
    CHECK(robot(" FRAME ORIGIN 0 0 5 XAXIS 1 0 6 ZAXIS -1 0 6") ==
          Strings{"r.rsd:6:26: robot 'r': x1 is not perpendicular to z0 (the angle between them is 45 degrees), as "
                  "the D-H convention requires"});
  }
  SECTION("x1 not meeting z0 (D-H rule)") {
    // x1 runs along +X through (0, 50, 5): 50 from the z0 axis.
    CHECK(robot(" FRAME ORIGIN 0 50 5 XAXIS 1 50 5 ZAXIS 0 50 6") ==
          Strings{"r.rsd:6:26: robot 'r': x1 does not meet z0 (they pass 50 apart), as the D-H convention requires"});
  }
  SECTION("a frame statement before any LINK") {
    // The message is about the keyword, so it points at the keyword.
    for (const std::string kw : {"ORIGIN", "XAXIS", "ZAXIS"}) {
      dir.write("r.rsd", lines({"ROBOT r", "  " + kw + " 1 0 0", "END"}));
      CHECK(robotErrors(dir, "r.rsd") ==
            Strings{"r.rsd:2:3: " + kw + " before any LINK: a frame belongs to the LINK before it"});
    }
  }
}

TEST_CASE("description: a FRAME missing ORIGIN, XAXIS or ZAXIS is reported as such", "[models]") {
  // The complete frame ORIGIN 5 0 0 XAXIS 6 0 0 ZAXIS 5 0 1 is sound (a1 = 5).
  // A missing point must not silently become (0, 0, 0): without XAXIS the
  // x axis would point from (5, 0, 0) to the origin (-X) and be accepted;
  // without ORIGIN or ZAXIS the message would be about perpendicular axes.
  TempDir dir;
  for (const auto& [missing, frame] : std::vector<std::pair<std::string, std::string>>{
           {"", "ORIGIN 5 0 0 XAXIS 6 0 0 ZAXIS 5 0 1"},
           {"ORIGIN", "XAXIS 6 0 0 ZAXIS 5 0 1"},
           {"XAXIS", "ORIGIN 5 0 0 ZAXIS 5 0 1"},
           {"ZAXIS", "ORIGIN 5 0 0 XAXIS 6 0 0"},
       }) {
    dir.write("r.rsd", kBase + lines({
                                    "ROBOT r",                                                 // 4
                                    "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 5
                                    "  LINK base FRAME " + frame,                             // 6
                                    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",   // 7
                                    "END",
                                }));
    const Strings d = robotErrors(dir, "r.rsd");
    INFO("without " << missing << ": " << rs::testing::joined(d));
    if (missing.empty()) {
      CHECK(d.empty());
      continue;
    }
    CHECK(d.size() == 1);
    if (d.size() != 1) continue;
    CHECK(d[0].rfind("r.rsd:6:", 0) == 0);
    CHECK(d[0].find(missing) != std::string::npos);
  }
}

TEST_CASE("description: joints", "[models]") {
  TempDir dir;
  const auto robot = [&](const Strings& joints, int links = 3) {
    Strings ls{"ROBOT r"};  // 4
    for (int i = 0; i < links; ++i)
      ls.push_back("  LINK base FRAME ORIGIN " + std::to_string(i) + " 0 0 XAXIS 9 0 0 ZAXIS " + std::to_string(i) +
                   " 0 1");  // 5, 6, 7
    ls.insert(ls.end(), joints.begin(), joints.end());
    ls.push_back("END");
    dir.write("r.rsd", kBase + lines(ls));
    return robotErrors(dir, "r.rsd");
  };
  SECTION("numbers out of order") {
    CHECK(robot({"  JOINT 2 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",
                 "  JOINT 1 REVOLUTE LETTER Q PRECISION 1 RANGE -10 10"}) ==
          Strings{"r.rsd:8:9: joints are numbered in order: expected JOINT 1, found JOINT 2",
                  "r.rsd:9:9: joints are numbered in order: expected JOINT 2, found JOINT 1"});
  }
  SECTION("a joint without LETTER, PRECISION and RANGE") {
    CHECK(robot({"  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10", "  JOINT 2 PRISMATIC"}) ==
          Strings{"r.rsd:9:9: JOINT 2 has no LETTER", "r.rsd:9:9: JOINT 2 has no PRECISION",
                  "r.rsd:9:9: JOINT 2 has no RANGE"});
  }
  SECTION("joint statements spread over several lines") {
    CHECK(robot({"  JOINT 1 REVOLUTE", "  LETTER P", "  PRECISION 1", "  RANGE -10 10", "  COUPLING OFF",
                 "  SPEED 10", "  JOINT 2 REVOLUTE", "  LETTER Q PRECISION 1 RANGE -10 10"})
              .empty());
  }
  SECTION("a joint count that does not match the links") {
    CHECK(robot({"  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10"}) ==
          Strings{"r.rsd:4:1: robot 'r' has 3 links and so needs 2 joints, found 1"});
    CHECK(robot({"  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10"}, 1) ==
          Strings{"r.rsd:4:1: robot 'r' has 1 link and so needs 0 joints, found 1"});
  }
  SECTION("a motor letter used twice") {
    CHECK(robot({"  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",
                 "  JOINT 2 REVOLUTE LETTER p PRECISION 1 RANGE -10 10"}) ==
          Strings{"r.rsd:9:9: motor letter P is used twice"});
  }
  SECTION("COUPLING before any JOINT") {
    CHECK(robot({"  COUPLING ON"}) == Strings{"r.rsd:8:12: expected a JOINT before COUPLING, found 'ON'"});
  }
  SECTION("LETTER before any JOINT names the problem") {
    const Strings d = robot({"  LETTER P"});
    REQUIRE(d.size() == 1);
    CHECK(d[0].rfind("r.rsd:8:3: ", 0) == 0);
    // "expected LINK, ..., LETTER, ..., found 'LETTER'" contradicts itself.
    CHECK(d[0].find("found 'LETTER'") == std::string::npos);
  }
  SECTION("an acceleration must let the motor reach its speed in less than 1000 s") {
    // 5000 units/s at 5 units/s² takes 1000 s: at least 5000 / 1000 + 1 = 6.
    CHECK(robot({"  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10 SPEED 5000 ACCELERATION 5",
                 "  JOINT 2 REVOLUTE LETTER Q PRECISION 1 RANGE -10 10 SPEED 5000 ACCELERATION 6"}) ==
          Strings{"r.rsd:8:78: acceleration 5 takes 1000 s or more to reach speed 5000: give at least 6"});
  }
  SECTION("an acceleration of 0, and ACTUATION on a joint") {
    const Strings d = robot({"  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10 ACCELERATION 0",
                             "  JOINT 2 REVOLUTE LETTER Q PRECISION 1 RANGE -10 10 ACTUATION 0.5"});
    REQUIRE(d.size() == 2);
    CHECK(d[0] == "r.rsd:8:67: an acceleration must be 1..1000000000 encoder units per second squared (leave it out "
                  "for a motor that starts and stops at full speed)");
    CHECK(d[1].rfind("r.rsd:9:54: expected LINK, FRAME", 0) == 0);
    CHECK(d[1].find("found 'ACTUATION'") != std::string::npos);
  }
  SECTION("a joint without LETTER does not also clash with another joint's letter A") {
    CHECK(robot({"  JOINT 1 REVOLUTE PRECISION 1 RANGE -10 10", "  JOINT 2 REVOLUTE LETTER A PRECISION 1 RANGE -10 10"}) ==
          Strings{"r.rsd:8:9: JOINT 1 has no LETTER"});
  }
}

TEST_CASE("description: grippers", "[models]") {
  TempDir dir;
  SECTION("the reference gripper is sound") {
    dir.write("g.rsd", gripperFile(kGripperLines));
    CHECK(robotErrors(dir, "g.rsd").empty());
  }
  SECTION("ACTUATION: more than 0 and at most 60 s, kept in whole microseconds") {
    for (const auto& [value, error] : std::vector<std::pair<std::string, std::string>>{
             {"0", "g.rsd:7:13: an actuation time must be more than 0 and at most 60 s"},
             {"60.5", "g.rsd:7:13: an actuation time must be more than 0 and at most 60 s"},
             {"-1", "g.rsd:7:13: an actuation time must be more than 0 and at most 60 s"}}) {
      Strings g = kGripperLines;
      g.insert(g.begin() + 6, "  ACTUATION " + value);  // line 7
      dir.write("g.rsd", gripperFile(g));
      INFO(value);
      CHECK(robotErrors(dir, "g.rsd") == Strings{error});
    }
    Strings g = kGripperLines;
    g.insert(g.begin() + 6, "  ACTUATION 0.25  ACCELERATION 800");
    dir.write("g.rsd", gripperFile(g));
    Library lib({dir.path()});
    const auto robot = lib.robot(dir.file("g.rsd"));
    REQUIRE(robot.has_value());
    const rs::vm::MotorSpec hand = rs::compiler::motorTable(*robot).back();
    CHECK(hand.kind == rs::vm::JointKind::Gripper);
    CHECK(hand.actuation == 250'000);
    CHECK(hand.acceleration == 800);
  }
  SECTION("each missing part is reported") {
    const std::vector<std::pair<std::size_t, std::string>> parts{
        {1, "BASE link"},
        {2, "FINGERS"},
        {3, "LETTER"},
        {4, "PRECISION"},
        {5, "RANGE"},
        {6, "AXIS2 (finger 2's rotation axis r2)"},
        {7, "AXIS3 (finger 3's rotation axis r3)"},
        {8, "NORMAL vector"},
        {9, "APPROACH vector"},
    };
    for (const auto& [line, what] : parts) {
      Strings g = kGripperLines;
      g.erase(g.begin() + static_cast<std::ptrdiff_t>(line));
      dir.write("g.rsd", gripperFile(g));
      INFO("without " << kGripperLines[line]);
      CHECK(robotErrors(dir, "g.rsd") == Strings{"g.rsd:1:1: gripper 'hand' has no " + what});
    }
  }
  SECTION("an empty gripper lacks everything, all reported") {
    Strings g{"GRIPPER hand", "END", "LINK palm", "  LINE 0 0 0 0 0 1", "END"};
    while (g.size() < 14) g.push_back("");
    dir.write("g.rsd", gripperFile(g));
    CHECK(robotErrors(dir, "g.rsd") == Strings{"g.rsd:1:1: gripper 'hand' has no BASE link",
                                               "g.rsd:1:1: gripper 'hand' has no FINGERS",
                                               "g.rsd:1:1: gripper 'hand' has no LETTER",
                                               "g.rsd:1:1: gripper 'hand' has no PRECISION",
                                               "g.rsd:1:1: gripper 'hand' has no RANGE",
                                               "g.rsd:1:1: gripper 'hand' has no AXIS2 (finger 2's rotation axis r2)",
                                               "g.rsd:1:1: gripper 'hand' has no AXIS3 (finger 3's rotation axis r3)",
                                               "g.rsd:1:1: gripper 'hand' has no NORMAL vector",
                                               "g.rsd:1:1: gripper 'hand' has no APPROACH vector"});
  }
  SECTION("an approach vector that does not start at the normal vector's start") {
    Strings g = kGripperLines;
    g[9] = "  APPROACH 0 0 1  0 0 -1";
    dir.write("g.rsd", gripperFile(g));
    CHECK(robotErrors(dir, "g.rsd") ==
          Strings{"g.rsd:10:12: gripper 'hand': the approach vector starts at (0, 0, 1), not at the normal vector's "
                  "start (0, 0, 0): both must start at the tool centre point"});
  }
  SECTION("normal and approach not perpendicular") {
    Strings g = kGripperLines;
    g[9] = "  APPROACH 0 0 0  1 0 1";
    dir.write("g.rsd", gripperFile(g));
    CHECK(robotErrors(dir, "g.rsd") ==
          Strings{"g.rsd:9:10: gripper 'hand': the normal vector and the approach vector are not perpendicular (the "
                  "angle between them is 45 degrees)"});
  }
  SECTION("a zero-length AXIS2 is reported on the AXIS2 line") {
    Strings g = kGripperLines;
    g[6] = "  AXIS2 0 -1 0  0 -1 0";
    dir.write("g.rsd", gripperFile(g));
    CHECK(robotErrors(dir, "g.rsd") == Strings{"g.rsd:7:9: gripper 'hand': axis r2 has zero length"});
  }
  SECTION("the gripper's letter equal to a joint's") {
    Strings g = kGripperLines;
    g[3] = "  LETTER P";
    dir.write("g.rsd", gripperFile(g));
    CHECK(robotErrors(dir, "g.rsd") == Strings{"g.rsd:18:11: the gripper's motor letter P is also a joint's"});
  }
  SECTION("a joint without LETTER does not clash with the gripper's letter A") {
    Strings robot = kHandRobotLines;
    robot[2] = "  JOINT 1 REVOLUTE PRECISION 1 RANGE -10 10";
    Strings g = kGripperLines;
    g.insert(g.end(), robot.begin(), robot.end());
    dir.write("g.rsd", lines(g));
    CHECK(robotErrors(dir, "g.rsd") == Strings{"g.rsd:17:9: JOINT 1 has no LETTER"});
  }
  SECTION("joint count with a gripper") {
    Strings robot = kHandRobotLines;
    robot.insert(robot.begin() + 2, "  LINK palm FRAME ORIGIN 0 0 20 XAXIS 1 0 20 ZAXIS 0 0 21");
    Strings g = kGripperLines;
    g.insert(g.end(), robot.begin(), robot.end());
    dir.write("g.rsd", lines(g));
    CHECK(robotErrors(dir, "g.rsd") ==
          Strings{"g.rsd:15:1: robot 'r' has 2 links and a gripper and so needs 2 joints, found 1"});
  }
}
