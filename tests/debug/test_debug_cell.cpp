// Issue 36: `robotsim debug --cell CELL` on examples/two_robots/interlock.rsd,
// every robot a thread of one session, driven through its console in
// batch mode (-x) as a person would type it.
//
// The expected places and times are worked out by hand from the programs
// (left.rsp, right.rsp) and the XR-4's motor F at 300 counts a second (its
// SPEED in stdlib/robots/rhino-xr4.rsd), so each MOVE of 300 takes 1 s:
//   left:  @1 SET (line 6) at 0; @2 MOVE 300 0-1 s; @3 MOVE -300 1-2 s;
//          @4 OUTSIG 1 ON at 2; @5 WAITFOR 1 ON (line 10) until right's OUT 1
//          comes on at 4 plus the wire's AFTER 0.25: 4.25; @6 OUTSIG 1 OFF
//          (line 11) is next then, after 5 steps.
//   right: @1 SET (line 4) at 0; @2 WAITFOR 1 ON (line 5) until left's OUT 1
//          at 2 (no AFTER); @3 MOVE 300 (line 6) 2-3 s; @4 MOVE -300 (line 7)
//          3-4 s; @5 OUTSIG 1 ON at 4.
// At 2.5 s right is half way through its first move: motor F at 150 (the
// profile is symmetric in time). The run ends at 8.5 s (tests/cli/test_cell_run.cpp).
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "tests/cli/cli_support.h"
#include "tests/debug/cell_debug_util.h"
#include "tests/debug/debug_test_util.h"
#include "tools/debug/cell_session.h"

namespace {

const std::string kInterlock = debugtest::kExamples + "two_robots/interlock.rsd";

rs::testing::CliResult debugCell(const std::string& commands, std::vector<std::string> extra = {}) {
  return debugtest::runCellDebugger(kInterlock, commands, std::move(extra));
}

using debugtest::afterCommand;

}  // namespace

TEST_CASE("debug cell: every robot is a thread, breakpoints per file, a stop stops the cell", "[debug][cell-debug]") {
  const auto r = debugCell("info threads\nbreak right.rsp:6\nbreak left.rsp:11\ncontinue\nstep\nprint motors\n"
                           "thread left\nprint clock\ninfo threads\ncontinue\ninfo breakpoints\nuntil 100\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("robotsim debug: cell interlock, 2 robots with programs") != std::string::npos);
  // Before anything ran: both at their first instruction.
  CHECK(afterCommand(r.out, "info threads") == "  id  robot            program              where\n"
                                        "* 1   left             left.rsp             line 6 @1, step 0\n"
                                        "  2   right            right.rsp            line 4 @1, step 0\n");
  CHECK(afterCommand(r.out, "break right.rsp:6") == "breakpoint 1: right.rsp line 6 (robot right)\n");
  // right reaches its first MOVE when its WAITFOR ends at 2 s; the stop makes right the current robot.
  CHECK(afterCommand(r.out, "continue") == "breakpoint 1 (right.rsp line 6)\nright: line 6 @3, step 2, clock 2.000 s\n"
                                    "    6 |         MOVE 300 0 0 0 0 0\n");
  // One step of right is its 1 s move; left waits meanwhile.
  CHECK(afterCommand(r.out, "step") == "right: line 7 @4, step 3, clock 3.000 s\n    7 |         MOVE -300 0 0 0 0 0\n");
  CHECK(afterCommand(r.out, "print motors").starts_with("F = 300\nE = 0\n"));
  CHECK(afterCommand(r.out, "thread left").starts_with("thread 1 (left): line 10 @5, step 4, clock 3.000 s\n"));
  CHECK(afterCommand(r.out, "print clock") == "clock = 3.000 s (step 4 of left)\n");
  CHECK(afterCommand(r.out, "info threads", 2).find("* 1   left             left.rsp             line 10 @5, step 4, in the "
                                             "instruction under way\n") != std::string::npos);
  // left's WAITFOR ends at 4.25 (right's OUT 1 at 4, the wire's AFTER 0.25).
  CHECK(afterCommand(r.out, "continue", 2) == "breakpoint 2 (left.rsp line 11)\nleft: line 11 @6, step 5, clock 4.250 s\n"
                                       "   11 |         OUTSIG 1 OFF\n");
  CHECK(afterCommand(r.out, "info breakpoints").find("2   break left.rsp line 11 (robot left, reached 1 time)") != std::string::npos);
  // right's second pass reaches its line 6 first, when its IN 1 comes on at 6.25 (left's OUT 1 at 6.25, no
  // AFTER): its tenth step (SET, WAITFOR, MOVE, MOVE, OUTSIG, WAITFOR, OUTSIG, ADD, JMPVAR, WAITFOR).
  CHECK(afterCommand(r.out, "until 100").starts_with("breakpoint 1 (right.rsp line 6)\nright: line 6 @3, step 10, clock 6.250 s\n"));
}

TEST_CASE("debug cell: reverse-step, reverse-continue and goto-time put the whole cell back", "[debug][cell-debug]") {
  const auto r = debugCell("break right.rsp:6\nbreak left.rsp:11\ncontinue\ncontinue\nreverse-continue\ngoto-time 2.5\n"
                           "thread right\nprint motors\nthread left\nprint motors\nreverse-step\nthread right\n"
                           "reverse-step\ninfo threads\nreverse-step\nreverse-step\ngoto-time 100\nthread 7\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "continue", 2).starts_with("breakpoint 2 (left.rsp line 11)\nleft: line 11 @6, step 5, clock 4.250 s\n"));
  // The last moment before 4.25 s a breakpoint would have stopped: right's at 2 s.
  CHECK(afterCommand(r.out, "reverse-continue") == "breakpoint 1 (right.rsp line 6)\nright: line 6 @3, step 2, clock 2.000 s\n"
                                            "    6 |         MOVE 300 0 0 0 0 0\n");
  CHECK(afterCommand(r.out, "goto-time 2.5").starts_with("at 2.500 s\nright: line 6 @3, step 2, clock 2.500 s\n"));
  // Half way through right's move 2-3 s; left stands at home, waiting since 2 s.
  CHECK(afterCommand(r.out, "print motors").starts_with("F = 150\n"));
  CHECK(afterCommand(r.out, "print motors", 2).starts_with("F = 0\n"));
  // left is inside its WAITFOR (step 4 done): back one puts it just before it, at 2 s.
  CHECK(afterCommand(r.out, "reverse-step").starts_with("left: line 10 @5, step 4, clock 2.000 s\n"));
  // right at 2 s, before its WAITFOR ended (step 1 done, at 0 s): its first reverse-step goes there.
  CHECK(afterCommand(r.out, "reverse-step", 2).starts_with("right: line 5 @2, step 1, clock 0.000 s\n"));
  CHECK(afterCommand(r.out, "reverse-step", 3).starts_with("at the start of the run\nright: line 4 @1, step 0, clock 0.000 s\n"));
  CHECK(afterCommand(r.out, "reverse-step", 4).starts_with("already at the start of the run\n"));
  // At 0 s, after right's SET: left ran first (the cell's order) and is in its first move.
  CHECK(afterCommand(r.out, "info threads").find("  1   left             left.rsp             line 7 @2, step 1, in the "
                                          "instruction under way\n") != std::string::npos);
  CHECK(afterCommand(r.out, "goto-time 100").starts_with("every program ended before 100.000 s\n"));
  CHECK(afterCommand(r.out, "thread 7").starts_with("error: no robot '7' in the cell: its robots are left, right"));
}

TEST_CASE("debug cell: bad places and commands get one message and the session goes on", "[debug][cell-debug]") {
  const auto r = debugCell("break middle.rsp:3\nbreak 400\nbreak left.rsp:x\nfly\nstep 0\ninfo\nstep\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(afterCommand(r.out, "break middle.rsp:3") ==
        "error: 'middle.rsp' names no robot of the cell and none of its programs: left (left.rsp), right (right.rsp)\n");
  CHECK(afterCommand(r.out, "break 400") == "error: no instruction on line 400 of left.rsp or after it\n");
  CHECK(afterCommand(r.out, "break left.rsp:x").starts_with("error: 'left.rsp:x' is not a line"));
  CHECK(afterCommand(r.out, "fly").starts_with("error: unknown command 'fly'"));
  CHECK(afterCommand(r.out, "step 0").starts_with("error: '0' is not a count"));
  CHECK(afterCommand(r.out, "info").starts_with("error: info what?"));
  // Still at the start: left's first step is its SET at 0 s.
  CHECK(afterCommand(r.out, "step") == "left: line 7 @2, step 1, clock 0.000 s\n    7 | again:  MOVE 300 0 0 0 0 0      ; reach into the shared space ...\n");
}

TEST_CASE("debug cell: a program that does not compile is an error at its line, nothing is debugged",
          "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
                     "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\nEND\n");
  dir.write("l.rsp", "        END\n");
  dir.write("r.rsp", "        MOVE 1 2\n        END\n");
  const auto r = rs::testing::runCli({"debug", "--cell", dir.file("c.rsd")});
  CHECK(r.code == 2);
  CHECK(r.err.find("r.rsp:1:") != std::string::npos);
  CHECK(r.out.empty());
}

// docs/debugging.md's worked two-robot session: the fenced block that starts
// with `$ robotsim debug --cell examples/two_robots/interlock.rsd`; its
// commands are the lines after `(rsdb) `, the rest what robotsim debug
// prints for them (the source directory written as `...`). Its lines are
// those worked out at the top of this file.
TEST_CASE("docs/debugging.md's two-robot session is what robotsim debug prints", "[debug][cell-debug][docs]") {
  std::ifstream in(rendertest::kSourceDir + "/docs/debugging.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string start = "```\n$ robotsim debug --cell examples/two_robots/interlock.rsd\n";
  const std::size_t at = doc.find(start);
  REQUIRE(at != std::string::npos);
  const std::size_t body = at + start.size();
  const std::string block = doc.substr(body, doc.find("```\n", body) - body);
  std::string commands;
  std::istringstream lines(block);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("(rsdb) ", 0) == 0) commands += line.substr(7) + "\n";
  const auto r = debugCell(commands);
  CHECK(r.code == 0);
  std::string out = r.out;
  for (std::size_t p; (p = out.find(rendertest::kSourceDir)) != std::string::npos;)
    out.replace(p, rendertest::kSourceDir.size(), "...");
  CHECK(out == block);
}

TEST_CASE("debug cell: LABEL=FILE naming no robot of the cell is an error with the labels", "[debug][cell-debug]") {
  const auto r = rs::testing::runCli({"debug", "--cell", kInterlock, "middle=" + debugtest::kExamples + "two_robots/left.rsp"});
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.find("middle") != std::string::npos);
  CHECK(r.err.find("left") != std::string::npos);
  CHECK(r.err.find("right") != std::string::npos);
  CHECK(r.out.empty());
}

// next steps over a GOSUB of the current robot: left's subroutine is two
// 1 s moves of motor F (300 counts at 300 a second), so `next` at line 1
// stands at line 2 at 2 s, both moves done; right's DELAY 5 goes on meanwhile.
TEST_CASE("debug cell: next steps the current robot over a GOSUB while the other goes on", "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
                     "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\nEND\n");
  dir.write("l.rsp", "        GOSUB sub\n        END\nsub:    MOVE 300 0 0 0 0 0\n        MOVE -300 0 0 0 0 0\n"
                     "        RETURN\n");
  dir.write("r.rsp", "        DELAY 5\n        END\n");
  const auto r = rs::testing::runCli(
      {"debug", "--cell", dir.file("c.rsd"), "-x", dir.write("s.cmds", "next\ninfo threads\n")});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  // GOSUB, MOVE, MOVE, RETURN: 4 steps of left.
  CHECK(afterCommand(r.out, "next") == "left: line 2 @2, step 4, clock 2.000 s\n    2 |         END\n");
  CHECK(afterCommand(r.out, "info threads").find("  2   right            r.rsp                line 1 @1, step 0, in the "
                                          "instruction under way\n") != std::string::npos);
}

// Each robot waits for the other's output 1: right's DELAY 1 ends at 1 s
// and then both wait for ever: the cell's deadlock at 1 s, which leaves the
// session inspectable, and goes back as any stop.
TEST_CASE("debug cell: a deadlock across robots stops the cell and can be gone back from", "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
                     "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\n"
                     "  WIRE left.OUT 1 TO right.IN 1\n  WIRE right.OUT 1 TO left.IN 1\nEND\n");
  dir.write("l.rsp", "        WAITFOR 1 ON\n        END\n");
  dir.write("r.rsp", "        DELAY 1\n        WAITFOR 1 ON\n        END\n");
  const auto r = rs::testing::runCli({"debug", "--cell", dir.file("c.rsd"), "-x",
                                      dir.write("s.cmds", "continue\ninfo threads\nthread right\nreverse-step\nstep\n")});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  const std::string stop = afterCommand(r.out, "continue");
  CHECK(stop.starts_with("deadlock: left waits at "));
  CHECK(stop.find("l.rsp:1 for input 1 (wired from right.OUT 1); right waits at ") != std::string::npos);
  CHECK(stop.find("left: line 1 @1, step 0, clock 1.000 s (the run is over)\n") != std::string::npos);
  CHECK(afterCommand(r.out, "info threads").find("  2   right            r.rsp                line 2 @2, step 1, stopped with "
                                          "the cell\n") != std::string::npos);
  // right's one step done was its DELAY (0-1 s): back before it, the start.
  CHECK(afterCommand(r.out, "reverse-step").starts_with("at the start of the run\nright: line 1 @1, step 0, clock 0.000 s\n"));
  CHECK(afterCommand(r.out, "step") == "right: line 2 @2, step 1, clock 1.000 s\n    2 |         WAITFOR 1 ON\n");
}

// A long run asks the interrupt (Ctrl-C at the terminal, the client's
// pause in the adapter) every 4096 steps: yes pauses the whole cell there.
TEST_CASE("debug cell: an interrupt pauses a long run of the cell", "[debug][cell-debug]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
                     "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\nEND\n");
  dir.write("l.rsp", "again:  ADD N 1\n        DELAY 0.001\n        JMPVAR N < 1000000 again\n        END\n");
  dir.write("r.rsp", "        DELAY 1\n        END\n");
  rs::launch::ProgramRequest request;
  request.cell = dir.file("c.rsd");
  rs::launch::CellPrograms programs;
  REQUIRE(rs::launch::assignCellPrograms(request, {}, programs));
  rs::launch::compileAssignedPrograms(request, programs);
  std::vector<rs::diag::Diagnostic> diags;
  const auto spec = rs::launch::prepareCellRun(programs, {}, diags);
  REQUIRE(spec);
  rs::debug::CellSession session(*spec);
  int asked = 0;
  session.setInterrupt([&asked] { return ++asked == 3; });
  const rs::debug::CellStop stop = session.resume();
  CHECK(stop.reason == rs::debug::StopReason::Pause);
  CHECK(stop.message == "interrupted");
  CHECK(session.cell().steps() == 3 * 4096);  // the third time asked
  CHECK_FALSE(session.cell().finished());
}
