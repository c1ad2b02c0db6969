// Errors in robot and workcell descriptions (.rsd, docs/models.md "Errors"):
// each case is a small file in a scratch directory and the exact
// diagnostics (file, line, column, message) the library reports for it, in
// one run. Columns were counted by hand (1-based, in characters). The
// errors of a robot's parts (frames, joints, grippers) are in
// test_description_part_errors.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "compiler/description/description.h"
#include "compiler/description/library.h"
#include "tests/models/description_errors_support.h"

namespace {

using rs::compiler::Library;
using rs::testing::diagnosticList;
using rs::testing::kBase;
using rs::testing::kGripperLines;
using rs::testing::lines;
using rs::testing::robotErrors;
using rs::testing::runCli;
using rs::testing::Strings;
using rs::testing::TempDir;
using rs::testing::workcellErrors;

}  // namespace

TEST_CASE("description: every statement-level error of a file, in one run", "[models]") {
  TempDir dir;
  dir.write("p.rsd", lines({
                         "stray words here",                          // 1
                         "LINK a extra",                              // 2
                         "  SPIN 1 2 3",                              // 3
                         "  LINE 0 0 0 1 1",                          // 4
                         "  LINE 0 0 0 1 1 x",                        // 5
                         "  BOX 1 2 3 4 5 6 COLOR PURPLE",            // 6
                         "  BOX 1 2 3 4 5 6 COLOR 16",                // 7
                         "  COLOR 16",                                // 8
                         "  ROTATE W 90",                             // 9
                         "  ROTATE Z",                                // 10
                         "  MOVE 1 2",                                // 11
                         "  LINE 0 0 0 1 1 1 COLOR",                  // 12
                         "  LINE 0 0 0 1 1 2000000000",               // 13
                         "END foo",                                   // 14
                         "OBJECT o",                                  // 15
                         "  LINK x",                                  // 16
                         "  BOX 1 2 3",                               // 17
                         "END",                                       // 18
                         "GRIPPER g",                                 // 19
                         "  GRASP",                                   // 20
                         "  LETTER 5",                                // 21
                         "  LETTER AB",                               // 22
                         "  PRECISION 0",                             // 23
                         "  PRECISION -0.5",                          // 24
                         "  SPEED 0",                                 // 25
                         "  SPEED -5",                                // 26
                         "  RANGE 10 5",                              // 27
                         "  RANGE 0 1.5",                             // 28
                         "  FINGERS f1",                              // 29
                         "  NORMAL 0 0 0 1 0",                        // 30
                         "END",                                       // 31
                         "ROBOT r",                                   // 32
                         "  JOINT one REVOLUTE",                      // 33
                         "  JOINT 1 TWISTY",                          // 34
                         "  JOINT 1.5 REVOLUTE",                      // 35
                         "  LINK l FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 36
                         "  JOINT 1 REVOLUTE LETTER F PRECISION 0",  // 37
                         "  SPEED 0",                                 // 38
                         "  PRECISION -1",                            // 39
                         "  COUPLING MAYBE",                          // 40
                         "  WOBBLE",                                  // 41
                         "  LINK",                                    // 42
                         "  GRIPPER 9",                               // 43
                         "END",                                       // 44
                         "WORKCELL w",                                // 45
                         "  AT 1 2 3",                                // 46
                         "  ROBOT r AT 1 2",                          // 47
                         "  ROBOT r SPIN",                            // 48
                         "  OBJECT 7",                                // 49
                         "  ROBOT r ROTATE Q 5",                      // 50
                         "END",                                       // 51
                         "END",                                       // 52
                         "LINK",                                      // 53
                         "LINK b",                                    // 54
                         "  LINE 0 0 0 1 1 1",                        // 55
                     }));
  const std::string colour = "a colour: one of the 16 EGA colour names (BLACK .. WHITE) or a number 0..15";
  const std::string robotStatements =
      "LINK, FRAME, ORIGIN, XAXIS, ZAXIS, TOOL, JOINT, LETTER, PRECISION, RANGE, COUPLING, SPEED, ACCELERATION, "
      "GRIPPER or END";
  const Strings expected{
      "p.rsd:1:1: expected LINK, OBJECT, GRIPPER, ROBOT or WORKCELL, found 'stray'",
      "p.rsd:2:8: unexpected 'extra' after the LINK name (statements go on the next lines)",
      "p.rsd:3:3: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'SPIN'",
      "p.rsd:4:17: expected the LINE's second endpoint (z coordinate) before the end of the line",
      "p.rsd:5:18: expected the LINE's second endpoint (z coordinate), found 'x'",
      "p.rsd:6:25: expected " + colour + ", found 'PURPLE'",
      "p.rsd:7:25: expected " + colour + ", found '16'",
      "p.rsd:8:9: expected " + colour + ", found '16'",
      "p.rsd:9:10: expected an axis X, Y or Z, found 'W'",
      "p.rsd:10:11: expected an angle in degrees before the end of the line",
      "p.rsd:11:11: expected a displacement (z coordinate) before the end of the line",
      "p.rsd:12:25: expected " + colour + " before the end of the line",
      "p.rsd:13:18: expected the LINE's second endpoint (z coordinate) (at most 1e+09 in size), found '2000000000'",
      "p.rsd:14:5: END takes nothing after it, found 'foo'",
      "p.rsd:16:3: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE, PART, FIXTURE, BELT or END, found 'LINK'",
      "p.rsd:17:12: expected the BOX's bottom edge before the end of the line",
      "p.rsd:20:3: expected BASE, FINGERS, LETTER, PRECISION, RANGE, SPEED, ACCELERATION, ACTUATION, AXIS2, AXIS3, NORMAL, APPROACH or END, "
      "found 'GRASP'",
      "p.rsd:21:10: expected a motor letter A..Z, found '5'",
      "p.rsd:22:10: expected a motor letter A..Z, found 'AB'",
      "p.rsd:23:13: a precision must be greater than 0",
      "p.rsd:24:13: a precision must be greater than 0",
      "p.rsd:25:9: a speed must be greater than 0",
      "p.rsd:26:9: a speed must be greater than 0",
      "p.rsd:27:9: range 10..5 is empty: the minimum is greater than the maximum",
      "p.rsd:28:11: expected the maximum encoder value (a whole number), found '1.5'",
      "p.rsd:29:13: expected the second finger link before the end of the line",
      "p.rsd:30:19: expected the normal vector's end point (z coordinate) before the end of the line",
      "p.rsd:33:9: expected a joint number, found 'one'",
      "p.rsd:34:11: expected REVOLUTE or PRISMATIC, found 'TWISTY'",
      "p.rsd:35:9: expected a joint number (a whole number), found '1.5'",
      "p.rsd:37:39: a precision must be greater than 0",
      "p.rsd:38:9: a speed must be greater than 0",
      "p.rsd:39:13: a precision must be greater than 0",
      "p.rsd:40:12: expected ON or OFF, found 'MAYBE'",
      "p.rsd:41:3: expected " + robotStatements + ", found 'WOBBLE'",
      "p.rsd:42:7: expected a link name before the end of the line",
      "p.rsd:43:11: expected a gripper name, found '9'",
      "p.rsd:46:3: expected ROBOT, OBJECT, FLOOR, CONVEYOR, FEEDER, SENSOR, SINK, WIRE or END, found 'AT'",
      "p.rsd:47:17: expected a position (z coordinate) before the end of the line",
      "p.rsd:48:11: expected ROBOT, OBJECT, AT, ROTATE, AS, PROGRAM, FLOOR, CONVEYOR, FEEDER, SENSOR, SINK, WIRE or END, "
      "found 'SPIN'",
      "p.rsd:49:10: expected an object name, found '7'",
      "p.rsd:50:18: expected an axis X, Y or Z, found 'Q'",
      "p.rsd:52:1: expected LINK, OBJECT, GRIPPER, ROBOT or WORKCELL, found 'END'",
      // A LINK without a name still opens its block (so what follows is
      // read as its contents, not as stray text); that block has no END.
      "p.rsd:53:1: LINK has no END",
      "p.rsd:53:5: expected a name for the LINK before the end of the line",
      "p.rsd:54:1: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'LINK'",
      // Then what only the library can tell, in the same run: the robot's
      // link 'l' is defined nowhere. (Nothing else about robot r: its lines
      // with errors make its joint count and numbering meaningless.)
      "p.rsd:36:8: unknown link 'l': not defined in this file, and no l.rsd beside it or on the library path",
  };
  CHECK(robotErrors(dir, "p.rsd") == expected);
}

TEST_CASE("description: the CLI prints each error with its source line and a caret", "[models]") {
  TempDir dir;
  const std::string file = dir.write("r.rsd", lines({"LINK a", "  BOX 1 2 3 4 5 6 COLOR PURPLE", "END"}));
  const auto r = runCli({"table", file});
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err == file + ":2:25: error: expected a colour: one of the 16 EGA colour names (BLACK .. WHITE) or a "
                        "number 0..15, found 'PURPLE'\n"
                        "    BOX 1 2 3 4 5 6 COLOR PURPLE\n" +
                        std::string(2 + 24, ' ') + "^\n");
}

TEST_CASE("description: invalid UTF-8", "[models]") {
  TempDir dir;
  SECTION("an invalid byte is an error at its position") {
    dir.write("u.rsd", lines({"LINK a", "  LINE 0 0 0 1 1 1 ; caf\xC3", "END"}));
    CHECK(robotErrors(dir, "u.rsd") == Strings{"u.rsd:2:25: invalid UTF-8 (byte 0xC3): descriptions are UTF-8 text"});
  }
  SECTION("a stray byte after valid multi-byte text counts columns in characters") {
    dir.write("u.rsd", lines({"; d\xC3\xA9j\xC3\xA0", "LINK \xC3\xA9t\xC3\xA9 \xFF", "END"}));
    CHECK(robotErrors(dir, "u.rsd") == Strings{"u.rsd:2:10: invalid UTF-8 (byte 0xFF): descriptions are UTF-8 text"});
  }
}

namespace {

// Diagnostics and segment count of one file parsed alone.
std::pair<Strings, std::size_t> parsed(const std::string& text) {
  rs::diag::Diagnostics d("x.rsd");
  const auto f = rs::compiler::parseDescription(std::make_unique<rs::diag::SourceFile>("x.rsd", text), d);
  Strings out;
  for (const auto& diag : d.sorted()) out.push_back(fmt::format("{}:{}: {}", diag.pos.line, diag.pos.col, diag.message));
  std::size_t segments = 0;
  for (const auto& l : f.links) segments += l.segments.size();
  return {out, segments};
}

void expectOneLoss(const std::pair<Strings, std::size_t>& got, const Strings& diagnostics) {
  CHECK(got.first == diagnostics);
  CHECK(got.second == 1);  // the good LINE's segment
}

}  // namespace

TEST_CASE("description: an unexpected character is reported wherever it is, and no other line is lost", "[models]") {
  // Each file has one bad line (dropped, with one message) and one good
  // LINE whose segment must survive.
  SECTION("followed by a name") {
    expectOneLoss(parsed(lines({"LINK a", "  LINE 0 0 0 1 1 1 # x", "  LINE 0 0 0 2 2 2", "END"})),
                  Strings{"2:20: unexpected character '#'"});
  }
  SECTION("at the end of a line") {
    expectOneLoss(parsed(lines({"LINK a", "  LINE 0 0 0 1 1 1 @", "  LINE 0 0 0 2 2 2", "END"})),
                  Strings{"2:20: unexpected character '@'"});
  }
  SECTION("followed by a number") {
    expectOneLoss(parsed(lines({"LINK a", "  LINE 0 0 0 1 1 @ 1", "  LINE 0 0 0 2 2 2", "END"})),
                  Strings{"2:18: unexpected character '@'"});
  }
  SECTION("where a colour should be") {
    expectOneLoss(parsed(lines({"LINK a", "  BOX 1 2 3 4 5 6 COLOR @", "  LINE 0 0 0 2 2 2", "END"})),
                  Strings{"2:25: unexpected character '@'"});
  }
  SECTION("alone on a line between blocks") {
    expectOneLoss(parsed(lines({"LINK a", "  LINE 0 0 0 2 2 2", "END", "@", "LINK b", "END"})),
                  Strings{"4:1: unexpected character '@'"});
  }
  SECTION("a valid non-ASCII character, columns counted in characters") {
    expectOneLoss(parsed(lines({"LINK a", "  LINE 0 0 0 \xC3\xA9 1 1", "  LINE 0 0 0 2 2 2", "END"})),
                  Strings{"2:14: unexpected character '\xC3\xA9'"});
  }
}

TEST_CASE("description: unknown names", "[models]") {
  TempDir dir;
  SECTION("a link that is neither in the file nor on the path") {
    dir.write("r.rsd", kBase + lines({
                                    "ROBOT r",                                                 // 4
                                    "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 5
                                    "  LINK nowhere FRAME ORIGIN 1 0 0 XAXIS 2 0 0 ZAXIS 1 0 1",  // 6
                                    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",   // 7
                                    "END",
                                }));
    CHECK(robotErrors(dir, "r.rsd") ==
          Strings{"r.rsd:6:8: unknown link 'nowhere': not defined in this file, and no nowhere.rsd beside it or on the library path"});
    SECTION("a file of that name that defines something else does not count") {
      dir.write("nowhere.rsd", lines({"OBJECT nowhere", "  LINE 0 0 0 1 1 1", "END"}));
      CHECK(robotErrors(dir, "r.rsd") ==
            Strings{"r.rsd:6:8: unknown link 'nowhere': not defined in this file, and no nowhere.rsd beside it or on "
                    "the library path"});
    }
  }
  SECTION("a gripper") {
    dir.write("r.rsd", kBase + lines({
                                    "ROBOT r",                                                 // 4
                                    "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 5
                                    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",   // 6
                                    "  GRIPPER hand",                                         // 7
                                    "END",
                                }));
    CHECK(robotErrors(dir, "r.rsd") ==
          Strings{"r.rsd:7:11: unknown gripper 'hand': not defined in this file, and no hand.rsd beside it or on the "
                  "library path"});
  }
  SECTION("a robot and an object in a WORKCELL, both reported") {
    dir.write("w.rsd", lines({"WORKCELL w", "  ROBOT ghost AT 0 0 0", "  OBJECT phantom AT 1 2 3", "END"}));
    CHECK(workcellErrors(dir, "w.rsd") ==
          Strings{"w.rsd:2:9: unknown robot 'ghost': not defined in this file, and no ghost.rsd beside it or on the "
                  "library path",
                  "w.rsd:3:10: unknown object 'phantom': not defined in this file, and no phantom.rsd beside it or on "
                  "the library path"});
  }
  SECTION("a file or library name that does not exist") {
    Library lib({dir.path()});
    CHECK_FALSE(lib.robot("no-such-robot"));
    CHECK(diagnosticList(lib.diagnostics(), dir.path().string()) ==
          Strings{"no-such-robot:0:0: no such file, and no robot of that name on the library path"});
  }
}

TEST_CASE("description: a workcell that places nothing", "[models]") {
  TempDir dir;
  dir.write("w.rsd", lines({"; nothing here", "WORKCELL empty", "END"}));
  CHECK(workcellErrors(dir, "w.rsd") == Strings{"w.rsd:2:1: workcell 'empty' places no robot and no object"});
}

TEST_CASE("description: errors in several files are reported together", "[models]") {
  TempDir dir;
  // wobbly.rsd and hand.rsd are found on the search path; each has its own
  // mistakes, and the robot file has one of its own.
  dir.write("wobbly.rsd", lines({
                              "LINK wobbly",                     // 1
                              "  LINE 0 0 0 0 0 1 COLOR MAUVE",  // 2
                              "  SHEAR 2",                       // 3
                              "END",
                          }));
  Strings hand = kGripperLines;
  hand[6] = "  AXIS2 0 -1 0  1 -1";  // missing a coordinate
  hand.resize(14);
  dir.write("hand.rsd", lines(hand));
  dir.write("r.rsd", kBase + lines({
                                  "ROBOT r",                                                        // 4
                                  "  LINK base FRAME ORIGIN 0 0 10 XAXIS 1 0 10 ZAXIS 0 0 11",      // 5
                                  "  LINK wobbly FRAME ORIGIN 0 0 10 XAXIS 1 0 10 ZAXIS 0 0 11",    // 6
                                  "  JOINT 1 REVOLUTE LETTER P PRECISION 1",                        // 7
                                  "  JOINT 2 REVOLUTE LETTER Q PRECISION 1 RANGE -10 10",           // 8
                                  "  GRIPPER hand",                                                 // 9
                                  "END",
                              }));
  const Strings expected{
      "wobbly.rsd:2:26: expected a colour: one of the 16 EGA colour names (BLACK .. WHITE) or a number 0..15, found "
      "'MAUVE'",
      "wobbly.rsd:3:3: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'SHEAR'",
      "hand.rsd:7:21: expected the axis r2's end point (z coordinate) before the end of the line",
      "r.rsd:7:9: JOINT 1 has no RANGE",
  };
  CHECK(robotErrors(dir, "r.rsd") == expected);
}

TEST_CASE("description: a file's own statement errors do not hide the errors of the files it uses", "[models]") {
  // docs/models.md: "Every error of every file is reported in one run".
  TempDir dir;
  dir.write("wobbly.rsd", lines({"LINK wobbly", "  SHEAR 2", "END"}));
  dir.write("r.rsd", lines({
                         "LINK base",                                                    // 1
                         "  LINE 0 0 0 0 0 1 COLOR MAUVE",                               // 2
                         "END",                                                          // 3
                         "ROBOT r",                                                      // 4
                         "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",       // 5
                         "  LINK wobbly FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",     // 6
                         "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",         // 7
                         "END",
                     }));
  const Strings d = robotErrors(dir, "r.rsd");
  CHECK(std::find(d.begin(), d.end(),
                  "r.rsd:2:26: expected a colour: one of the 16 EGA colour names (BLACK .. WHITE) or a number 0..15, "
                  "found 'MAUVE'") != d.end());
  CHECK(std::find(d.begin(), d.end(), "wobbly.rsd:2:3: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'SHEAR'") !=
        d.end());
}

TEST_CASE("description: one slip gives one message, also in a file loaded by name", "[models]") {
  // A bad PRECISION or RANGE is reported where it is written; the part it
  // belongs to should not also be reported as missing it.
  TempDir dir;
  Strings hand = kGripperLines;
  hand[4] = "  PRECISION 0";
  hand.resize(14);
  dir.write("hand.rsd", lines(hand));
  dir.write("r.rsd", kBase + lines({
                                  "ROBOT r",                                                    // 4
                                  "  LINK base FRAME ORIGIN 0 0 10 XAXIS 1 0 10 ZAXIS 0 0 11",  // 5
                                  "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE -10 10",      // 6
                                  "  GRIPPER hand",                                            // 7
                                  "END",
                              }));
  CHECK(robotErrors(dir, "r.rsd") == Strings{"hand.rsd:5:13: a precision must be greater than 0"});

  dir.write("arm.rsd", kBase + lines({
                                    "ROBOT arm",                                               // 4
                                    "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 5
                                    "  LINK base FRAME ORIGIN 0 0 5 XAXIS 1 0 5 ZAXIS 0 0 6",  // 6
                                    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE 10 -10",   // 7
                                    "END",
                                }));
  dir.write("w.rsd", lines({"WORKCELL w", "  ROBOT arm", "END"}));
  CHECK(workcellErrors(dir, "w.rsd") ==
        Strings{"arm.rsd:7:47: range 10..-10 is empty: the minimum is greater than the maximum"});

  // Every motor starts at encoder 0, so a range must include it.
  dir.write("arm.rsd", kBase + lines({
                                    "ROBOT arm",                                               // 4
                                    "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",  // 5
                                    "  LINK base FRAME ORIGIN 0 0 5 XAXIS 1 0 5 ZAXIS 0 0 6",  // 6
                                    "  JOINT 1 REVOLUTE LETTER P PRECISION 1 RANGE 10 100",   // 7
                                    "END",
                                }));
  CHECK(workcellErrors(dir, "w.rsd") ==
        Strings{"arm.rsd:7:47: range 10..100 must include 0: every motor starts at encoder 0 (home)"});
}

TEST_CASE("description: a LINK header without a name gives one message, not one per line", "[models]") {
  TempDir dir;
  dir.write("r.rsd", lines({
                         "LINK",                  // 1
                         "  LINE 0 0 0 1 1 1",    // 2
                         "  BOX 1 2 3 4 5 6",     // 3
                         "END",                   // 4
                     }));
  CHECK(robotErrors(dir, "r.rsd") == Strings{"r.rsd:1:5: expected a name for the LINK before the end of the line"});
}

TEST_CASE("description: five independent mistakes in one file are all reported in one run", "[models]") {
  // docs/models.md: "Every error of every file is reported in one run". A
  // statement error used to stop the build of the file (only mistake 1 was
  // reported); then a robot's first error hid the rest of the workcell.
  TempDir dir;
  const std::string file = dir.write(
      "five.rsd", lines({
                      "LINK base",                                                         // 1
                      "  LINE 0 0 0 0 0 100 COLOUR RED",                                   // 2: 1, a keyword misspelled
                      "END",                                                               // 3
                      "LINK arm",                                                          // 4
                      "  BOX 0 100 10 -10 10 -10",                                         // 5
                      "END",                                                               // 6
                      "ROBOT r",                                                           // 7
                      "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",            // 8
                      "  LINK arm",                                                        // 9: 2, no frame
                      "  LINK forearm FRAME ORIGIN 100 0 0 XAXIS 101 0 0 ZAXIS 100 0 1",   // 10: 3, unknown link
                      "  JOINT 1 REVOLUTE LETTER E PRECISION 0.1 RANGE -100 100",          // 11
                      "  JOINT 3 REVOLUTE LETTER D PRECISION 0.1 RANGE -100 100",          // 12: 4, out of order
                      "END",                                                               // 13
                      "WORKCELL w",                                                        // 14
                      "  ROBOT r AT 0 0 0",                                                // 15
                      "  OBJECT crate AT 100 0 0",                                         // 16: 5, unknown object
                      "END",                                                               // 17
                  }));
  const Strings expected{
      "five.rsd:2:22: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'COLOUR'",
      "five.rsd:9:8: link 'arm' has no FRAME (ORIGIN, XAXIS and ZAXIS points)",
      "five.rsd:10:8: unknown link 'forearm': not defined in this file, and no forearm.rsd beside it or on the library path",
      "five.rsd:12:9: joints are numbered in order: expected JOINT 2, found JOINT 3",
      "five.rsd:16:10: unknown object 'crate': not defined in this file, and no crate.rsd beside it or on the library path",
  };
  CHECK(workcellErrors(dir, "five.rsd") == expected);
  // Through the command line: one run, five errors, exit code 2.
  const std::string prog = dir.write("p.rsp", "END\n");
  const auto r = runCli({"check", prog, "--cell", file});
  CHECK(r.code == 2);
  std::size_t errors = 0;
  for (std::size_t at = r.err.find(": error: "); at != std::string::npos; at = r.err.find(": error: ", at + 1)) ++errors;
  CHECK(errors == 5);
}

TEST_CASE("description: a robot nothing uses is checked too, once", "[models]") {
  TempDir dir;
  dir.write("two.rsd", kBase + lines({
                                   "ROBOT used",                                                 // 4
                                   "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",     // 5
                                   "END",                                                        // 6
                                   "ROBOT spare",                                                // 7
                                   "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",     // 8
                                   "  LINK ghost FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",    // 9
                                   "  JOINT 1 REVOLUTE LETTER E PRECISION 1",                    // 10
                                   "END",                                                        // 11
                                   "WORKCELL w",                                                 // 12
                                   "  ROBOT spare AT 0 0 0",                                     // 13
                                   "END",
                               }));
  // robot() builds the first robot; the second, also placed by the
  // workcell, is reported once.
  CHECK(robotErrors(dir, "two.rsd") ==
        Strings{"two.rsd:9:8: unknown link 'ghost': not defined in this file, and no ghost.rsd beside it or on the library path",
                "two.rsd:10:9: JOINT 1 has no RANGE"});
}

TEST_CASE("description: number syntax as the grammar has it (.5 and 6. are numbers, 6e0 is not)", "[models]") {
  // grammar/RobotModel.g4: NUMBER : [+-]? ([0-9]+ ('.' [0-9]*)? | '.' [0-9]+)
  {
    rs::diag::Diagnostics d("n.rsd");
    const auto f = rs::compiler::parseDescription(
        std::make_unique<rs::diag::SourceFile>("n.rsd", lines({"LINK a", "  LINE .5 6. -.25 +.5 -6. +7", "END"})), d);
    CHECK(d.all().empty());
    REQUIRE(f.links.size() == 1);
    REQUIRE(f.links[0].segments.size() == 1);
    CHECK(f.links[0].segments[0].a == Eigen::Vector3d(0.5, 6.0, -0.25));
    CHECK(f.links[0].segments[0].b == Eigen::Vector3d(0.5, -6.0, 7.0));
  }
  // An exponent: one message at the number, and the number written out.
  rs::diag::Diagnostics d("e.rsd");
  rs::compiler::parseDescription(std::make_unique<rs::diag::SourceFile>("e.rsd", lines({
                                                                                    "LINK a",                    // 1
                                                                                    "  LINE 0 0 0 6e0 0 1",      // 2
                                                                                    "  LINE 0 0 0 1.5E3 0 1",    // 3
                                                                                    "  LINE 0 0 0 2e-3 0 1",     // 4
                                                                                    "  LINE 0 0 0 -2.5e+2 0 1",  // 5
                                                                                    "  MOVE 0 0 .5e1",           // 6
                                                                                    "END",
                                                                                })),
                                 d);
  Strings got;
  for (const auto& x : d.sorted())
    got.push_back(fmt::format("{}:{}: {} | {}", x.pos.line, x.pos.col, x.message, x.hint));
  CHECK(got == Strings{
                   "2:14: '6e0': exponents are not supported in descriptions | write 6",
                   "3:14: '1.5E3': exponents are not supported in descriptions | write 1500",
                   "4:14: '2e-3': exponents are not supported in descriptions | write 0.002",
                   "5:14: '-2.5e+2': exponents are not supported in descriptions | write -250",
                   "6:12: '.5e1': exponents are not supported in descriptions | write 5",
               });
}
