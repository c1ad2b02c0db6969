// Sensors see what the robot carries and, with SEES ROBOTS, the robot
// itself, at the exact microsecond a move brings it there (issue 35;
// runtime/cell/robot_sight.h). The times are worked out by hand on the
// library's gantry: its motors are Cartesian, 0.1 mm per count, at
// constant speed (X and Z 1000 counts/s, Y 800, the gripper 200), and
// the tool centre point is at (500 + X/10, 200 - Y/10, 400 + Z/10), so a
// count is reached at count/speed seconds into a move.
#include <catch2/catch.hpp>

#include <string>

#include "../render/render_test_util.h"
#include "bench/adept_hour.h"
#include "compiler/description/library.h"
#include "runtime/run/run.h"
#include "tests/cli/cli_support.h"

using rs::testing::CliResult;
using rs::testing::runCli;

namespace robotsighttest {

bool hasLine(const std::string& trace, const std::string& line) {
  return trace.find("\n" + line + "\n") != std::string::npos;
}

// The gantry over a block on a pallet, with the beam `beam` wired to
// input 1; and the program's lines that take the block and lift it.
std::string carryCell(const std::string& beam) {
  return "WORKCELL carry\n"
         "  ROBOT gantry    AT 0 1000 0\n"
         "  OBJECT pallet   AT 150 0 760\n"
         "  OBJECT block    AT 200 30 700\n"
         "  SENSOR eye BEAM " + beam + "\n"
         "  WIRE eye TO IN 1\n"
         "END\n";
}
constexpr const char* kTakeAndLift =
    "; cell: cell.rsd\n"
    "        MOVETO -2800 2800 0 0\n"
    "        MOVE 0 0 1490 0\n"
    "        MOVE 0 0 0 100\n"
    "        MOVE 0 0 -1490 0\n";

}  // namespace robotsighttest

using robotsighttest::carryCell;
using robotsighttest::hasLine;
using robotsighttest::kTakeAndLift;

TEST_CASE("robot sight: a block the gripper carries breaks a beam at the microsecond worked out by hand",
          "[cell][devices]") {
  rs::testing::TempDir dir;
  dir.write("cell.rsd", carryCell("400 200 600  400 200 760"));
  // Over the block (2.8 s), down 1490 (1.8625 s), close (0.5 s), up
  // (1.8625 s): at 7.025 s the block (x 200..240, y 179..219 once lifted)
  // starts along +x at 100 mm/s. Its front face reaches the beam at
  // x = 400 after 1600 counts (7.025 + 1.600 = 8.625 s); its back face is
  // past it (x > 400) at count 2001 (200 + 200.1): 7.025 + 2.001 = 9.026 s.
  const std::string prog =
      dir.write("p.rsp", std::string(kTakeAndLift) + "        MOVE 2800 0 0 0\n        END\n");
  const CliResult r = runCli({"run", prog, "--trace"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(hasLine(r.out, "     8.625  sensor eye ON"));
  CHECK(hasLine(r.out, "     8.625  input 1 ON: wire from sensor eye"));
  CHECK(hasLine(r.out, "     9.026  sensor eye OFF"));
  CHECK(hasLine(r.out, "     9.026  input 1 OFF: wire from sensor eye"));
  // The edges come during the move, before the line of the move they happen in.
  CHECK(r.out.find("8.625  sensor eye ON") < r.out.find("MOVE    2800 0 0 0"));
  // An empty gripper through the same beam: nothing (the sensor sees parts only).
  const std::string empty = dir.write("e.rsp",
                                      "; cell: cell.rsd\n"
                                      "        MOVETO -2800 2800 1490 0\n"
                                      "        MOVE 2800 0 0 0\n"
                                      "        END\n");
  const CliResult e = runCli({"run", empty, "--trace"});
  CHECK(e.out.find("sensor eye ON") == std::string::npos);
}

TEST_CASE("robot sight: a light curtain (SEES ROBOTS) sees the gripper cross it at the hand-computed microsecond",
          "[cell][devices]") {
  rs::testing::TempDir dir;
  // The zone x 350..360, y 100..285, z 600..760 catches the gripper's palm
  // (x and z within 50 and 30 of the tool centre point, y 270..290 above
  // it at y = 200), made smaller by 0.01 on every face as every collision
  // piece is. A beam that sees parts only stands beside it and stays off.
  dir.write("cell.rsd",
            "WORKCELL curtain\n"
            "  ROBOT gantry    AT 0 1000 0\n"
            "  SENSOR curtain ZONE 350 360 285 100 760 600 SEES ROBOTS\n"
            "  SENSOR eye BEAM 355 250 600  355 250 760\n"
            "  WIRE curtain TO IN 2\n"
            "END\n");
  const std::string prog = dir.write("p.rsp",
                                     "; cell: cell.rsd\n"
                                     "        MOVETO -2800 2800 0 0\n"
                                     "        MOVE 2800 0 0 0\n"
                                     "        END\n");
  const CliResult r = runCli({"run", prog, "--trace"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  // The first move: x = 500 - 100 t, z = 400 + 100 t. The palm's far z
  // face (z + 29.99) reaches 600 at count 1701 (1.701 s); its near x face
  // (x + 49.99) leaves 350 at count 2000 (x = 300: 349.99), 2.000 s.
  CHECK(hasLine(r.out, "     1.701  sensor curtain ON"));
  CHECK(hasLine(r.out, "     2.000  sensor curtain OFF"));
  // The second, along +x from x = 220 at 2.8 s: the front face (x + 49.99)
  // reaches 350 at count 801 (3.601 s); the back face (x - 49.99) is past
  // 360 at count 1900 (x = 410: 360.01), 4.700 s.
  CHECK(hasLine(r.out, "     3.601  sensor curtain ON"));
  CHECK(hasLine(r.out, "     3.601  input 2 ON: wire from sensor curtain"));
  CHECK(hasLine(r.out, "     4.700  sensor curtain OFF"));
  CHECK(r.out.find("sensor eye ON") == std::string::npos);
  // The same cell and program give the same bytes.
  CHECK(runCli({"run", prog, "--trace"}).out == r.out);
}

// Issue 36: a light curtain sees every robot of the cell that runs, not
// only the first. The same gantry and the same moves as above, now the
// second robot of a cell, placed 5000 further along x (so its tool centre
// point is at (5500 + X/10, 200 - Y/10, 400 + Z/10)), with the curtain
// moved with it; the first robot only waits for the curtain on its input
// 2, so it ends when the curtain first turns on: at 1.701 s, as above.
TEST_CASE("robot sight: a light curtain sees the second robot of a cell too", "[cell][devices][robots]") {
  rs::testing::TempDir dir;
  dir.write("cell.rsd",
            "WORKCELL curtain\n"
            "  ROBOT gantry    AT 0 1000 0    AS a PROGRAM a.rsp\n"
            "  ROBOT gantry    AT 5000 1000 0 AS b PROGRAM b.rsp\n"
            "  SENSOR curtain ZONE 5350 5360 285 100 760 600 SEES ROBOTS\n"
            "  WIRE curtain TO a.IN 2\n"
            "END\n");
  dir.write("a.rsp", "        WAITFOR 2 ON\n        END\n");
  dir.write("b.rsp", "        MOVETO -2800 2800 0 0\n        MOVE 2800 0 0 0\n        END\n");
  const CliResult r = runCli({"run", "--cell", dir.file("cell.rsd"), "--trace", "--format=json"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("1.701  sensor curtain ON") != std::string::npos);
  CHECK(r.out.find("3.601  sensor curtain ON") != std::string::npos);
  CHECK(r.out.find("4.700  sensor curtain OFF") != std::string::npos);
  CHECK(r.out.find("\"time\":1.701,\"robots\"") == std::string::npos);  // the summary's shape below
  const std::string summary = r.out.substr(r.out.rfind("\n{\"status\"") + 1);
  CHECK(summary.find("{\"name\":\"a\",\"program\"") != std::string::npos);
  CHECK(summary.find("\"name\":\"a\",\"program\":\"" + dir.file("a.rsp") + "\",\"status\":\"finished\",\"time\":1.701") !=
        std::string::npos);
}

// The carried block lifted through a beam above it: it turns the beam ON
// as its top passes and OFF as its bottom does, the OFF found from a look
// that sees the block (RobotSight's search along the crossing face's gap).
// The gantry cell above, the beam at y = 100.15 across the block's x.
// The lift (the third motor, 800 counts/s, 0.1 per count) starts at
// 5.1625 s (2.8 s over the block, 1.8625 s down, 0.5 s to close) with
// the block at y 30..70: its top passes 100.15 at count 302 (top 100.2;
// at 301 it is 100.1), 302 / 800 = 0.3775 s in: 5.540 s; its bottom at
// count 702 (bottom 100.2; at 701, 100.1 still touches), 702 / 800 =
// 0.8775 s in: 6.040 s.
TEST_CASE("robot sight: a carried block lifted through a beam leaves it at the microsecond worked out by hand",
          "[cell][devices]") {
  rs::testing::TempDir dir;
  dir.write("cell.rsd", carryCell("220 100.15 600  220 100.15 760"));
  const std::string prog = dir.write("p.rsp", std::string(kTakeAndLift) + "        END\n");
  const CliResult r = runCli({"run", prog, "--trace=json"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("{\"event\":\"sensor\",\"time\":5.54,\"name\":\"eye\",\"on\":true") != std::string::npos);
  CHECK(r.out.find("{\"event\":\"sensor\",\"time\":6.04,\"name\":\"eye\",\"on\":false") != std::string::npos);
  const CliResult text = runCli({"run", prog, "--trace"});
  CHECK(hasLine(text.out, "     5.540  sensor eye ON"));
  CHECK(hasLine(text.out, "     6.040  sensor eye OFF"));
}

// The sight remembers a search by the motion it was made for (RobotSight::
// firstChange, RobotSight::kRemembered): the second carry across the beam
// from the same place is the first one again, answered from memory, and
// a carry of the same length that also lifts the block (the same X motion,
// another Y) is not. Each edge by hand, as above: a carry from x 200..240
// breaks the beam at x = 400 1.600 s in and leaves it 2.001 s in; the way
// back (from x 480..520) 0.800 s and 1.201 s in; a move of 2800 X counts
// takes 2.8 s. The lift of 1000 Y counts (800 counts/s) raises the block's
// bottom (y 179) past the beam's height (y 200) at count 211, 0.26375 s
// in, long before its front reaches x = 400: no edge.
TEST_CASE("robot sight: a carry made again is answered from memory at the same hand-computed microseconds",
          "[cell][devices]") {
  rs::testing::TempDir dir;
  dir.write("cell.rsd", carryCell("400 200 600  400 200 760"));
  const std::string prog = dir.write("p.rsp", std::string(kTakeAndLift) +
                                                  "        MOVE 2800 0 0 0\n"      // 7.025 .. 9.825
                                                  "        MOVE -2800 0 0 0\n"     //       .. 12.625
                                                  "        MOVE 2800 0 0 0\n"      //       .. 15.425
                                                  "        MOVE -2800 0 0 0\n"     //       .. 18.225
                                                  "        MOVE 2800 0 -1000 0\n"  //       .. 21.025
                                                  "        END\n");
  const CliResult r = runCli({"run", prog, "--trace"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  for (const char* line : {"     8.625  sensor eye ON", "     9.026  sensor eye OFF", "    10.625  sensor eye ON",
                           "    11.026  sensor eye OFF", "    14.225  sensor eye ON", "    14.626  sensor eye OFF",
                           "    16.225  sensor eye ON", "    16.626  sensor eye OFF"}) {
    CAPTURE(line);
    CHECK(hasLine(r.out, line));
  }
  CHECK(r.out.find("turned ON 4 times") != std::string::npos);
}

TEST_CASE("robot sight: a production loop's searches are answered from memory after its first cycles",
          "[cell][devices]") {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const auto cell = library.workcell("adept-cell");
  REQUIRE(cell);
  const auto run = rendertest::runOf(rendertest::compileText(rs::bench::adeptHourProgram(40), *cell), &*cell, {},
                                     false, rs::runtime::CollisionMode::Off);
  const rs::vm::RunOutcome outcome = run->runToEnd();
  REQUIRE(outcome.ok());
  const rs::runtime::CellDevices& devices = *run->rig().devices();
  CHECK(devices.taken(0) == 40);
  // The loop carries a block out of the beam and over to the outfeed each
  // 6 s cycle, the same moves from the same places once the belts' timing
  // repeats: the searches of a few cycles are made, the rest remembered.
  INFO("searched " << devices.sightsSearched() << ", remembered " << devices.sightsRemembered());
  CHECK(devices.sightsSearched() > 0);
  CHECK(devices.sightsRemembered() > 30 * 3);
  CHECK(devices.sightsSearched() < devices.sightsRemembered() / 4);
}

// The swept check's memory in the same loop (collisions on): the moves of
// a cycle are swept in the first cycles and answered after. The parts
// upstream on the infeed stand somewhere new each cycle until the queue
// settles (about 13 cycles), and the feeder's parts come in three slots in
// turn; a move's reach key counts only the objects some check of it could
// look at (stretches of the move, a check looking no farther than
// MotionBounds::kLookAhead) and names them by shape and place, not number.
// At 8a59268, keyed by number and by the whole move's reach, 57 moves were
// swept afresh in the first 13 cycles.
TEST_CASE("sweep memory: a production loop's moves are swept in its first cycles only", "[cell][devices][collision]") {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const auto cell = library.workcell("adept-cell");
  REQUIRE(cell);
  const auto run = rendertest::runOf(rendertest::compileText(rs::bench::adeptHourProgram(40), *cell), &*cell, {},
                                     false, rs::runtime::CollisionMode::Error);
  REQUIRE(run->runToEnd().ok());
  REQUIRE(run->rig().devices()->taken(0) == 40);
  const rs::runtime::CollisionWatch* watch = run->rig().collisionWatch();
  REQUIRE(watch);
  // 8 moves a cycle, then HRDHOME: 40 × 8 + 1.
  CHECK(watch->moves() == 40 * 8 + 1);
  // At most two cycles' moves and the last HRDHOME are swept afresh.
  INFO("swept " << watch->moves() - watch->remembered() << " of " << watch->moves());
  CHECK(watch->moves() - watch->remembered() <= 2 * 8 + 1);
}
