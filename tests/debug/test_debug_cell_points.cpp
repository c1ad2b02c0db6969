// `debug --cell` on examples/two_robots/interlock.rsd: breakpoints at a
// time and on a condition, conditions and hit counts, watches, finish and
// reverse-next of the current robot, disasm. The robots' steps and times
// are worked out by hand at the top of tests/debug/test_debug_cell.cpp:
// right's MOVEs 2-3 and 3-4 s, its OUTSIG 1 ON at 4 (step 5), left's
// WAITFOR ending at 4.25 (step 5), its ADD TURNS 1 (step 7) at 4.25;
// right's second pass reaches line 6 at 6.25 (its tenth step), left's at
// line 11 at 8.5 (right's second OUTSIG 1 ON at 8.25 plus the wire's 0.25).
#include <catch2/catch.hpp>

#include <string>

#include "tests/debug/cell_debug_util.h"
#include "tests/debug/debug_test_util.h"

namespace {

using debugtest::afterCommand;

rs::testing::CliResult debugInterlock(const std::string& commands) {
  return debugtest::runCellDebugger(debugtest::kExamples + "two_robots/interlock.rsd", commands);
}

}  // namespace

TEST_CASE("debug cell: break at a time, when a condition becomes true, and watches", "[debug][cell-debug]") {
  const auto r = debugInterlock("break at 3\nthread right\nbreak when output 1 on\nthread left\nwatch TURNS\n"
                                "info breakpoints\ncontinue\ncontinue\ncontinue\nreverse-continue\nwatch nope\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "break when output 1 on") == "breakpoint 2: when out 1 = 1 on right\n");
  CHECK(afterCommand(r.out, "watch TURNS") == "watch 3: TURNS of left (now 0)\n");
  CHECK(afterCommand(r.out, "info breakpoints") == "id  what\n1   break at 3.000 s (reached 0 times)\n"
                                                   "2   break when out 1 = 1 on right (reached 0 times)\n"
                                                   "3   watch TURNS of left (now 0)\n");
  // Right's first MOVE ends at 3 s exactly, which is not past 3: the step that passes it is its second MOVE, at 4.
  CHECK(afterCommand(r.out, "continue") == "breakpoint 1 (at 3.000 s)\nright: line 8 @5, step 4, clock 4.000 s\n"
                                           "    8 |         OUTSIG 1 ON             ; your turn\n");
  CHECK(afterCommand(r.out, "continue", 2).starts_with("breakpoint 2 (when out 1 = 1 on right)\n"
                                                       "right: line 9 @6, step 5, clock 4.000 s\n"));
  CHECK(afterCommand(r.out, "continue", 3).starts_with("watch 3: TURNS of left changed from 0 to 1\n"
                                                       "left: line 13 @8, step 7, clock 4.250 s\n"));
  // Back: the last stop before 4.25 s is the condition's at 4 s.
  CHECK(afterCommand(r.out, "reverse-continue").starts_with("breakpoint 2 (when out 1 = 1 on right)\n"
                                                            "right: line 9 @6, step 5, clock 4.000 s\n"));
  CHECK(afterCommand(r.out, "watch nope").starts_with("error: 'nope' is not a variable of the program"));
}

TEST_CASE("debug cell: if and hits on a cell's breakpoints", "[debug][cell-debug]") {
  const auto r = debugInterlock("break right.rsp:6 hits 2\nbreak left.rsp:11 if TURNS = 1\ninfo breakpoints\n"
                                "continue\ncontinue\nreverse-continue\ninfo breakpoints\nbreak 6 if nope\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "info breakpoints") ==
        "id  what\n1   break right.rsp line 6 hits >= 2 (robot right, reached 0 times)\n"
        "2   break left.rsp line 11 if TURNS = 1 (robot left, reached 0 times)\n");
  // right's first pass (2 s) is its first hit, left's first line 11 (4.25 s) has TURNS 0: right's second pass.
  CHECK(afterCommand(r.out, "continue").starts_with("breakpoint 1 (right.rsp line 6 hits >= 2)\n"
                                                    "right: line 6 @3, step 10, clock 6.250 s\n"));
  CHECK(afterCommand(r.out, "continue", 2).starts_with("breakpoint 2 (left.rsp line 11 if TURNS = 1)\n"
                                                       "left: line 11 @6, step 12, clock 8.500 s\n"));
  // Going back, hit counts aside: right's line 6 at 6.25 s is the last before.
  CHECK(afterCommand(r.out, "reverse-continue").starts_with("breakpoint 1 (right.rsp line 6 hits >= 2)\n"
                                                            "right: line 6 @3, step 10, clock 6.250 s\n"));
  CHECK(afterCommand(r.out, "info breakpoints", 2).find("(robot right, reached 2 times)") != std::string::npos);
  CHECK(afterCommand(r.out, "break 6 if nope").starts_with("error: 'nope': a condition is NAME OP VALUE"));
}

// left: SET N 0 (line 1), GOSUB sub (2), SET N 1 (3), END; sub: two 1 s
// moves of motor F (lines 5, 6) and RETURN (7). right's DELAY 5 goes on
// meanwhile. After two steps left is at the subroutine's first MOVE at 0 s;
// one more is that move (1 s); finish runs the second and the RETURN: line
// 3 at 2 s, step 5. reverse-next goes back over the GOSUB to line 2, after
// the SET (step 1) at 0 s, and once more to the start.
TEST_CASE("debug cell: finish and reverse-next of the current robot", "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  const std::string cell = debugtest::writeTwoRobotCell(
      dir, "        SET N 0\n        GOSUB sub\n        SET N 1\n        END\nsub:    MOVE 300 0 0 0 0 0\n"
           "        MOVE -300 0 0 0 0 0\n        RETURN\n",
      "        DELAY 5\n        END\n");
  const auto r = debugtest::runCellDebugger(cell, "finish\nstep 2\nstep\nfinish\nreverse-next\nnext\nreverse-next\n"
                                                  "reverse-next\nreverse-next\ndisasm\ndisasm @9\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "finish") == "error: not in a subroutine: the call stack of left is empty\n");
  CHECK(afterCommand(r.out, "finish", 2) == "left: line 3 @3, step 5, clock 2.000 s\n    3 |         SET N 1\n");
  CHECK(afterCommand(r.out, "reverse-next") == "left: line 2 @2, step 1, clock 0.000 s\n    2 |         GOSUB sub\n");
  CHECK(afterCommand(r.out, "next") == "left: line 3 @3, step 5, clock 2.000 s\n    3 |         SET N 1\n");
  CHECK(afterCommand(r.out, "reverse-next", 2).starts_with("left: line 2 @2, step 1, clock 0.000 s\n"));
  CHECK(afterCommand(r.out, "reverse-next", 3).starts_with("at the start of the run\nleft: line 1 @1, step 0"));
  CHECK(afterCommand(r.out, "reverse-next", 4).starts_with("already at the start of the run\n"));
  // left's seven instructions, the current one (@1) marked.
  const std::string listing = afterCommand(r.out, "disasm");
  CHECK(listing.starts_with("=>  0001     1            SET     N 0\n"));
  CHECK(std::count(listing.begin(), listing.end(), '\n') == 7);
  CHECK(afterCommand(r.out, "disasm @9") == "error: '@9': disasm takes @N, N from 1 to 7\n");
}

// left waits for its input 3, which nothing drives; right's DELAY 2 ends
// the run at 2 s (without the set, a deadlock then). `set input 3 on` at
// 1 s (after until 1) is replayed as a stimulus at 1 s whose cause is
// "set by the debugger": left's WAITFOR ends there, and going back to the
// start and on again replays it. Input 1 of the
// interlock's left is wired: refused.
TEST_CASE("debug cell: set input is a stimulus at the present moment, replayed going back", "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  const std::string cell = debugtest::writeTwoRobotCell(dir, "        WAITFOR 3 ON\n        SET N 1\n        END\n",
                                                       "        DELAY 2\n        END\n", "  WIRE right.OUT 1 TO left.IN 1\n");
  const auto r = debugtest::runCellDebugger(cell, "set input 9 on\nset N = 3\nset input 1 on\nuntil 1\nset input 3 on\n"
                                                  "step\nprint in 3\nbreak 2\nreverse-step\ncontinue\ncontinue\nset input 3 off\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "set input 9 on") == "error: '9': inputs are 1..8\n");
  CHECK(afterCommand(r.out, "set N = 3").starts_with("error: usage: set input N on|off"));
  CHECK(afterCommand(r.out, "set input 1 on") == "error: input 1 of left is wired from right.OUT 1 (line 4 of two): right's OUTSIG 1 "
                                                   "turns it; to set it by hand, remove the WIRE\n");
  CHECK(afterCommand(r.out, "set input 3 on") == "input 3 of left is on from 1.000 s on\n");
  CHECK(afterCommand(r.out, "step") == "left: line 2 @2, step 1, clock 1.000 s\n    2 |         SET N 1\n");
  // The debugger's own change, not a stimulus (as the one-robot debugger says it).
  CHECK(afterCommand(r.out, "print in 3") == "in 3 = 1 (since 1.000 s: set by the debugger)\n");
  CHECK(afterCommand(r.out, "reverse-step").starts_with("at the start of the run\n"));
  CHECK(afterCommand(r.out, "continue") == "breakpoint 1 (l.rsp line 2)\nleft: line 2 @2, step 1, clock 1.000 s\n"
                                           "    2 |         SET N 1\n");
  CHECK(afterCommand(r.out, "continue", 2).starts_with("every program ended\n"));
  CHECK(afterCommand(r.out, "set input 3 off").starts_with("error: the run is over"));
}

// Labels and instructions of a robot's program: left's `again` is its @2
// (line 7), reached after its SET at 0 s; right's @3 is its first MOVE
// (line 6), reached at 2 s (test_debug_cell.cpp's top).
TEST_CASE("debug cell: break LABEL and @N, of the current robot or ROBOT:", "[debug][cell-debug]") {
  const auto r = debugInterlock("break again\nbreak right:@3\nbreak left:nope\nbreak @99\ninfo breakpoints\n"
                                "continue\ncontinue\nreverse-continue\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "break again") == "breakpoint 1: left.rsp label again, line 7 (robot left)\n");
  CHECK(afterCommand(r.out, "break right:@3") == "breakpoint 2: right.rsp @3, line 6 (robot right)\n");
  CHECK(afterCommand(r.out, "break left:nope") ==
        "error: 'left:nope' is not a line or a label of left.rsp: its program has no label 'nope'\n");
  CHECK(afterCommand(r.out, "break @99") == "error: no instruction @99: the program has @1 to @9\n");
  CHECK(afterCommand(r.out, "continue").starts_with("breakpoint 1 (left.rsp label again, line 7)\n"
                                                    "left: line 7 @2, step 1, clock 0.000 s\n"));
  CHECK(afterCommand(r.out, "continue", 2).starts_with("breakpoint 2 (right.rsp @3, line 6)\n"
                                                       "right: line 6 @3, step 2, clock 2.000 s\n"));
  CHECK(afterCommand(r.out, "reverse-continue").starts_with("breakpoint 1 (left.rsp label again, line 7)\n"));
}

// The gantry of gantry-cell beside an XR-4 (whose DELAY 1 is all it does),
// with --collisions warn. The gantry's program is test_moving_arm.cpp's
// lowering by 1100 counts, then down 600 more: its line 1 ends at 2.8 s,
// line 2 (1100 at 800 a second) at 4.175 s, line 3 closes the gripper 40
// above the block's centre, on nothing, ending at 4.675 s (the stop after
// it, with the words test_moving_arm.cpp checks); line 4 (600 at 800 a
// second, 4.675 to 5.425 s) takes the fingers into the block, which the
// swept check finds soon after 4.675 s: the stop after that step, at 5.425 s.
TEST_CASE("debug cell: break warning and break collision on a cell of several robots", "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  const std::string cell = debugtest::writeGantryBeside(dir);
  const auto r = debugtest::runCellDebugger(cell, "break warning\nbreak collision\ncontinue\ncontinue\nreverse-continue\n",
                                            {"--collisions", "warn"});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "break collision") == "breakpoint 2: collision\n");
  const std::string warning = "breakpoint 1 (warning: a gripper closing on nothing): a gripper closed on nothing: nearest: "
                              "block (object 2), its centre 40 below the tool centre point, which is 20 outside its box\n"
                              "arm: line 4 @4, step 3, clock 4.675 s\n";
  CHECK(afterCommand(r.out, "continue").starts_with(warning));
  const std::string collision = afterCommand(r.out, "continue", 2);
  CHECK(collision.starts_with("breakpoint 2 (collision): finger "));
  CHECK(collision.find("of robot 'arm' hits object 2 (block) at 4.7") != std::string::npos);
  CHECK(collision.find("arm: line 5 @5, step 4, clock 5.425 s\n") != std::string::npos);
  CHECK(afterCommand(r.out, "reverse-continue").starts_with(warning));
}
