// Issue 35 on a cell of several robots: `debug --cell` stops at a sensor's
// edge, a part fed and a part taken, prints the cell's devices and objects,
// and going back (a re-run of the cell) restores the devices as they were
// going forwards. The cell is tests/debug/programs/belt_pair.rsd with the
// interlock's programs (examples/two_robots/left.rsp and right.rsp).
//
// The expected values, by hand. The robots' steps are those of
// tests/debug/test_debug_cell.cpp's top: left's MOVEs 0-1 and 1-2 s, its
// OUTSIG 1 ON at 2, its WAITFOR until 4.25, OUTSIG 1 OFF at 4.25, its
// second pass's MOVEs 4.25-5.25-6.25; right's WAITFOR until 2, MOVEs 2-3
// and 3-4. The belt runs at 100 a second from 0 s; the feeder's block
// (object 2: the conveyor is the cell's one object) is fed at 0 s with its
// AT corner at x -740, y 500, z 2870 and the next one (object 3) at 6 s.
// Its front (x -700) reaches the beam at x -550 at 1.5 s, its back leaves
// it at 1.9 s; its centre (x -720) reaches the sink's zone (x -300) at
// 4.2 s. A device's event stops the cell after the next step of any robot
// that ends after it: the feed at 0 s (the cell acts after the robots'
// first instructions at 0) with left's first MOVE at 1 s, the edges with
// left's second MOVE at 2 s, the take with left's WAITFOR at 4.25 s.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "base/seconds.h"
#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "tests/debug/cell_debug_util.h"
#include "tests/debug/debug_test_util.h"
#include "tools/debug/cell_session.h"
#include "tools/debug/device_points.h"

namespace {

using debugtest::afterCommand;

rs::testing::CliResult debugBeltPair(const std::string& commands) {
  const std::string two = debugtest::kExamples + "two_robots/";
  return debugtest::runCellDebugger(rendertest::kSourceDir + "/tests/debug/programs/belt_pair.rsd", commands,
                                    {"left=" + two + "left.rsp", "right=" + two + "right.rsp"});
}

// The devices at 2 s: the block 200 on from -740, the beam behind it.
const std::string kDevicesAt2 =
    "sensor eye         OFF, turned ON 1 time\n"
    "conveyor belt      running, carried 1 part\n"
    "feeder parts       fed 1 part\n"
    "sink done          took 0 parts\n"
    "block (object 2)   at (-540.000, 500.000, 2870.000), riding belt\n";

// At 3 s: 100 further on.
const std::string kDevicesAt3 =
    "sensor eye         OFF, turned ON 1 time\n"
    "conveyor belt      running, carried 1 part\n"
    "feeder parts       fed 1 part\n"
    "sink done          took 0 parts\n"
    "block (object 2)   at (-440.000, 500.000, 2870.000), riding belt\n";

}  // namespace

TEST_CASE("debug cell: break sensor, feeder and sink stop the cell, print devices and objects show it",
          "[debug][cell-debug][devices]") {
  const auto r = debugBeltPair("break sensor eye on\nbreak sink done\nbreak feeder parts\ncontinue\ncontinue\n"
                               "print devices\nprint objects\ncontinue\nprint devices\ncontinue\ninfo breakpoints\n"
                               "goto-time 2.5\nprint devices\nbreak sensor nope\nbreak sensor eye up\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "break sensor eye on") == "breakpoint 1: sensor eye ON\n");
  CHECK(afterCommand(r.out, "continue") ==
        "breakpoint 3 (feeder parts): feeder parts: block (object 2) at (-740, 500, 2870) at 0.000 s\n"
        "left: line 8 @3, step 2, clock 1.000 s\n    8 |         MOVE -300 0 0 0 0 0     ; ... and back out\n");
  CHECK(afterCommand(r.out, "continue", 2) == "breakpoint 1 (sensor eye ON): sensor eye ON at 1.500 s\n"
                                              "left: line 9 @4, step 3, clock 2.000 s\n"
                                              "    9 |         OUTSIG 1 ON             ; your turn\n");
  CHECK(afterCommand(r.out, "print devices") == kDevicesAt2);
  // The conveyor where the cell puts it; the block's centre 20 in from its corner (40 a side).
  CHECK(afterCommand(r.out, "print objects") ==
        "1 conveyor at (-750.000, 0.000, 3000.000), centre (0.000, 265.000, 2850.000)\n"
        "2 block at (-540.000, 500.000, 2870.000), centre (-520.000, 520.000, 2850.000), moved\n");
  CHECK(afterCommand(r.out, "continue", 3).starts_with(
      "breakpoint 2 (sink done): sink done: takes block (object 2) at 4.200 s\nleft: line 11 @6, step 5, clock 4.250 s\n"));
  // The sink took the block: no part is left in the cell.
  CHECK(afterCommand(r.out, "print devices", 2) ==
        "sensor eye         OFF, turned ON 1 time\nconveyor belt      running, carried 1 part\n"
        "feeder parts       fed 1 part\nsink done          took 1 part\n");
  // The second block at 6 s, with left's second pass's second MOVE at 6.25 s (its tenth step).
  CHECK(afterCommand(r.out, "continue", 4).starts_with(
      "breakpoint 3 (feeder parts): feeder parts: block (object 3) at (-740, 500, 2870) at 6.000 s\n"
      "left: line 9 @4, step 10, clock 6.250 s\n"));
  CHECK(afterCommand(r.out, "info breakpoints") == "id  what\n1   break sensor eye ON (reached 1 time)\n"
                                                   "2   break sink done (reached 1 time)\n"
                                                   "3   break feeder parts (reached 2 times)\n");
  // Between two instants the devices are shown as at the last one, 2 s.
  CHECK(afterCommand(r.out, "print devices", 3) ==
        kDevicesAt2 + "(the devices and the parts as they were at 2.000 s, the cell's last instant before)\n");
  CHECK(afterCommand(r.out, "break sensor nope") == "error: the cell has no sensor 'nope': its sensors are eye\n");
  CHECK(afterCommand(r.out, "break sensor eye up") == "error: 'up': a sensor's edge is on or off\n");
}

TEST_CASE("debug cell: going back restores the devices as they were going forwards", "[debug][cell-debug][devices]") {
  // At the beam's OFF edge (2 s), right steps its WAITFOR (ends at 2) and its MOVE (2-3 s), then back one and on again.
  const auto r = debugBeltPair("break sensor eye off if TURNS = 0\ncontinue\nprint devices\nthread right\nstep 2\n"
                               "print devices\nreverse-step\nprint devices\nstep\nprint devices\ncontinue\n"
                               "reverse-continue\nprint devices\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "continue").starts_with(
      "breakpoint 1 (sensor eye OFF if TURNS = 0 on left): sensor eye OFF at 1.900 s\n"));
  CHECK(afterCommand(r.out, "print devices") == kDevicesAt2);
  CHECK(afterCommand(r.out, "step 2").starts_with("right: line 7 @4, step 3, clock 3.000 s\n"));
  CHECK(afterCommand(r.out, "print devices", 2) == kDevicesAt3);
  CHECK(afterCommand(r.out, "reverse-step").starts_with("right: line 6 @3, step 2, clock 2.000 s\n"));
  CHECK(afterCommand(r.out, "print devices", 3) == kDevicesAt2);
  CHECK(afterCommand(r.out, "print devices", 4) == kDevicesAt3);
  // The block's second pass of the beam is the second block's, at 7.5-7.9 s with TURNS 1: the run ends first.
  CHECK(afterCommand(r.out, "continue", 2).starts_with("every program ended\n"));
  CHECK(afterCommand(r.out, "reverse-continue").starts_with("breakpoint 1 (sensor eye OFF if TURNS = 0 on left)"));
  CHECK(afterCommand(r.out, "print devices", 5) == kDevicesAt2);
}

// The property behind the two tests above, at every moment of the run: left
// steps from the start to its end, the devices' rows (each one's state,
// every part and its place) kept at each stop; then back one step at a
// time, each stop shows the rows kept there going forwards. Nothing is
// worked out by hand: the forward run is the reference.
TEST_CASE("debug cell: at every reverse-step the devices are as they were going forwards", "[debug][cell-debug][devices]") {
  const std::string two = debugtest::kExamples + "two_robots/";
  rs::launch::ProgramRequest request;
  request.cell = rendertest::kSourceDir + "/tests/debug/programs/belt_pair.rsd";
  rs::launch::CellPrograms programs;
  const std::vector<std::string> assignments = {"left=" + two + "left.rsp", "right=" + two + "right.rsp"};
  REQUIRE(rs::launch::assignCellPrograms(request, assignments, programs));
  rs::launch::compileAssignedPrograms(request, programs);
  std::vector<rs::diag::Diagnostic> diags;
  const auto spec = rs::launch::prepareCellRun(programs, {}, diags);
  REQUIRE(spec);
  rs::debug::CellSession session(*spec);
  const auto rows = [&session] {
    std::string text = rs::base::formatSeconds(session.clock()) + "\n";
    for (const rs::debug::DeviceRow& r : rs::debug::deviceRows(session.cell().robot(0), session.view(0)))
      text += r.name + " = " + r.value + "\n";
    return text;
  };
  std::vector<std::string> forwards = {rows()};
  while (true) {
    session.select(0);
    const auto stop = session.step();
    REQUIRE(stop);
    if (stop->finished() || session.cell().end(0) != rs::runtime::RobotEnd::Running) break;
    forwards.push_back(rows());
  }
  // The start and after each of left's 16 steps (SET, two passes of its 7-instruction loop, END).
  CHECK(forwards.size() == 17);
  CHECK(forwards.back().find("feeder parts = fed 2 parts") != std::string::npos);  // the second block came at 6 s
  for (std::size_t k = forwards.size() - 1; k-- > 0;) {
    session.select(0);
    session.reverseStep();
    INFO("back to left's step " << k);
    CHECK(rows() == forwards[k]);
  }
}
