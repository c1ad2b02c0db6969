// `robotsim test` on a cell of several robots (issue 36, docs/testing.md,
// "A cell of several robots"): scenario files that name the cell and the
// robots' programs, expectations per robot (`left.motors F=0`) and for the
// cell, grading one robot's program against the teacher's other one.
// Times by hand from the Rhino XR-4's motor F (300 counts/s,
// stdlib/robots/rhino-xr4.rsd): a MOVE of 300 takes 1 s, of 1000
// ceil(1000 * 10^6 / 300) = 3333334 us.
#include <catch2/catch.hpp>

#include <cstdlib>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "diag/source_file.h"
#include "tests/cli/cli_support.h"
#include "tools/testrun/scenario_file.h"

// Named, not anonymous: the tests are built as one unity file.
namespace cell_scenarios_test {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

const std::string kCellSource = ROBOTSIM_SOURCE_DIR;

// A temporary copy of the interlock example's cell and programs.
void interlockIn(const TempDir& dir) {
  for (const char* name : {"interlock.rsd", "left.rsp", "right.rsp"})
    dir.write(name, rs::testing::readBytes(kCellSource + "/examples/two_robots/" + name));
}

bool mentions(const std::string& text, const std::string& part) {
  INFO("looking for: " << part);
  return text.find(part) != std::string::npos;
}

}  // namespace cell_scenarios_test

using namespace cell_scenarios_test;

TEST_CASE("cell scenarios: program LABEL FILE lines, shared and a scenario's own, and test: robot",
          "[testrun][cell-run]") {
  const rs::testrun::ScenarioFile f = rs::testrun::parseScenarioFile(rs::diag::SourceFile(
      "c.rstest",
      "test: cell two.rsd\ntest: robot right\nprogram left l.rsp\nprogram right r.rsp\n\nscenario a\nexpect: "
      "left.motors F=0\n\nscenario b\nprogram LEFT l2.rsp\nexpect: right.finished\n"));
  REQUIRE(f.errors.empty());
  REQUIRE(f.scenarios.size() == 2);
  const rs::testrun::TestSettings a = rs::testrun::settingsOf(f, f.scenarios[0]);
  CHECK(a.robot == "right");
  REQUIRE(a.programs.size() == 2);
  CHECK(a.programs[0].label == "left");
  CHECK(a.programs[0].file == "l.rsp");
  CHECK(a.programs[0].pos.line == 3);
  CHECK(a.programs[0].labelCol == 9);
  CHECK(a.programs[0].fileCol == 14);
  const rs::testrun::Expectation& motors = f.scenarios[0].parsed.expectations.at(0);
  CHECK(motors.robot == "left");
  CHECK(motors.robotCol == 9);
  REQUIRE(motors.motorCols.size() == 1);
  CHECK(motors.motorCols[0] == 21);  // "expect: left.motors F=0": F=0 at column 21
  // Scenario b's own program for LEFT replaces the shared one of left (labels in any case).
  const rs::testrun::TestSettings b = rs::testrun::settingsOf(f, f.scenarios[1]);
  REQUIRE(b.programs.size() == 2);
  CHECK(b.programs[0].label == "right");
  CHECK(b.programs[1].file == "l2.rsp");
  CHECK(f.scenarios[1].parsed.expectations.at(0).robot == "right");

  // An order of two robots' lines: each side's robot.
  const rs::testrun::ScenarioFile order = rs::testrun::parseScenarioFile(rs::diag::SourceFile(
      "o.rstest", "scenario a\nexpect: left.output 1 on before right.input 1 on\n"));
  REQUIRE(order.errors.empty());
  const rs::testrun::Expectation& o = order.scenarios.at(0).parsed.expectations.at(0);
  CHECK(o.robot == "left");
  CHECK(o.secondRobot == "right");
  CHECK(o.secondRobotCol == 33);  // "right." after 'before'
  CHECK(!o.second.output);

  // Every bad line at once: a robot's program twice, a prefix on the
  // cell's own things, `stopped` without a robot.
  const rs::testrun::ScenarioFile bad = rs::testrun::parseScenarioFile(rs::diag::SourceFile(
      "b.rstest",
      "program left l.rsp\nprogram Left m.rsp\nscenario a\nexpect: left.object block at 1 2 3\nexpect: stopped\n"
      "expect: feeder.sensor eye count 2\n"));
  REQUIRE(bad.errors.size() == 4);
  CHECK(bad.errors[0].pos == rs::diag::Pos{2, 9});
  CHECK(bad.errors[0].message == "robot Left's program is named twice");
  CHECK(bad.errors[1].pos == rs::diag::Pos{4, 9});
  CHECK(bad.errors[1].message == "an object's place is the cell's, not a robot's: write it without 'left.'");
  CHECK(bad.errors[2].pos == rs::diag::Pos{5, 1});
  CHECK(bad.errors[3].message == "a device's count is the cell's, not a robot's: write it without 'feeder.'");
}

TEST_CASE("cell scenarios: the two-robot examples' scenarios pass, worked out by hand", "[testrun][cell-run][examples]") {
  // examples/two_robots/interlock.rstest and handover.rstest derive every
  // figure in their comments: both robots of the interlock end at 8.5 s;
  // with the right robot's program on both, each waits at its line 5 at 0 s.
  const std::string folder = kCellSource + "/examples/two_robots/";
  const TempDir dir;
  const CliResult r = runCli({"test", folder + "interlock.rstest", folder + "handover.rstest", "--junit",
                              dir.file("r.xml")});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(mentions(r.out, folder + "interlock.rstest [they take turns] PASSED (19 expectations, 8.500 s simulated)\n"));
  CHECK(mentions(r.out, folder + "interlock.rstest [both wait for the other] PASSED (5 expectations, 0.000 s simulated)\n"));
  CHECK(mentions(r.out, folder + "handover.rstest [the block reaches the packer's corner] PASSED (8 expectations, "));
  // JUnit: one testcase per scenario.
  const std::string xml = rs::testing::readBytes(dir.file("r.xml"));
  CHECK(mentions(xml, "<testsuite name=\"" + folder + "interlock.rstest\" tests=\"2\" failures=\"0\" errors=\"0\">"));
  CHECK(mentions(xml, "name=\"they take turns\"/>"));
  CHECK(mentions(xml, "name=\"both wait for the other\"/>"));
}

TEST_CASE("cell scenarios: each robot's expectations fail with the robot named, the cell's with the cell's time",
          "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  // As the interlock example: both end at 8.5 s, F back at 0, TURNS 2;
  // right's output 1 is ON from 4 s (the end of its first MOVE -300) to 4.25 s.
  const std::string spec = dir.write("t.rstest",
                                     "test: cell interlock.rsd\n"
                                     "scenario wrong on purpose\n"
                                     "expect: right.time = 8.4\n"              // 3
                                     "expect: left.motors F=1 Q=2\n"           // 4
                                     "expect: right.output 1 off at 4.1\n"     // 5
                                     "expect: left.variable TURNS = 3\n"       // 6
                                     "expect: time <= 8\n"                     // 7
                                     "expect: output 1 on\n"                   // 8
                                     "expect: ghost.output 1 on\n"             // 9
                                     "expect: deadlock at line 3\n"            // 10
                                     "expect: right.finished\n");              // 11: holds
  const CliResult r = runCli({"test", spec});
  INFO(r.out);
  CHECK(r.code == 1);
  for (const std::string& want :
       {spec + ":3:1: error: robot right: expected the run's simulated time = 8.400 s; it ended at line 13, 8.500 s\n",
        spec + ":4:21: error: robot left: expected motor F at 1 at the end; it is at 0 at line 14, 8.500 s\n",
        spec + ":4:25: error: robot left: the robot has no motor Q (its motors: F E D C B A)\n",
        spec + ":5:1: error: robot right: expected output 1 OFF at 4.100 s; it was ON then (set by line 8)\n",
        spec + ":6:1: error: robot left: expected variable TURNS = 3 at the end; it is 2 at line 14, 8.500 s\n",
        spec + ":7:1: error: expected the run's simulated time <= 8.000 s; it ended at 8.500 s\n",
        spec + ":8:1: error: a cell of several robots runs here: say whose line or motor this is, as in "
               "'LABEL.output 1 on'\n",
        std::string("  hint: the robots with a program: `left`, `right`\n"),
        spec + ":9:9: error: workcell interlock has no robot labelled `ghost`\n",
        std::string("  hint: the cell's robots are `left`, `right`\n"),
        spec + ":10:1: error: a cell of several robots ends at no one line: say whose, as in 'LABEL.deadlock at "
               "line 3'\n"})
    CHECK(mentions(r.out, want));
  CHECK(!mentions(r.out, spec + ":11:"));
}

TEST_CASE("cell scenarios: a runtime error in one robot stops the other, and a scenario can say so",
          "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  // F's range is -1750..1750: the second MOVE 1000 of `far.rsp` leaves it
  // as it starts, at 3333334 us; left then waits at its line 10 (its
  // WAITFOR, since 2 s) and is stopped with the cell.
  dir.write("far.rsp", "        MOVE 1000 0 0 0 0 0\n        MOVE 1000 0 0 0 0 0\n        END\n");
  const std::string spec = dir.write("t.rstest",
                                     "test: cell interlock.rsd\n"
                                     "program right far.rsp\n"
                                     "scenario the right robot goes too far\n"
                                     "expect: runtime error\n"
                                     "expect: right.runtime error at line 2\n"
                                     "expect: left.stopped at line 10\n"
                                     "expect: time = 3.333334\n"
                                     "expect: left.output 1 on\n"
                                     "scenario nobody said it would\n"
                                     "expect: left.finished\n"
                                     "scenario nothing stated\n"
                                     "expect: right.motors F=1000\n");
  const CliResult r = runCli({"test", spec});
  INFO(r.out);
  CHECK(mentions(r.out, spec + " [the right robot goes too far] PASSED (5 expectations, 3.333 s simulated)\n"));
  CHECK(mentions(r.out, spec + ":10:1: error: robot left: expected the run to end: finished; it ended: stopped at line 10, "
                          "3.333 s: robot right: "));
  // Without any end stated, the cell must finish: the failure is at the
  // instruction that stopped it, in its own file.
  CHECK(mentions(r.out, dir.file("far.rsp") + ":2:9: error: robot right: expected the run to end: finished; it ended: "
                                         "runtime error at line 2, 3.333 s: "));
}

TEST_CASE("cell scenarios: grading one robot's program, the teacher's program on the other",
          "[testrun][cell-run][examples]") {
  // examples/tests/grading_cell: the right robot of the interlock cell, the
  // teacher's left.rsp on the left one; 8 points: finished 1, left's TURNS
  // = 2 2, right's output 1 pulses twice 3, the cell's time 8.5 s 2.
  // good.rsp is right.rsp: all 8 at 8.5 s. once.rsp takes one turn: in and
  // out 2-4 s, OUT 1 ON at 4 s and ends; left's IN 1 ON at 4.25, it goes
  // in and out 4.25-6.25, and its WAITFOR 1 ON finds IN 1 still ON: the
  // cell ends at 6.25 s, finished (1) with left's TURNS 2 (2), one pulse:
  // 3. wrong_input.rsp waits for input 2, which nothing drives: left waits
  // at 2 s (after its first turn) and the cell deadlocks then: 0.
  const std::string folder = kCellSource + "/examples/tests/grading_cell";
  const std::string s = folder + "/submissions/";
  const std::string a = folder + "/assignment.rstest";
  const CliResult r = runCli({"test", "--spec", a, folder + "/submissions", "--format", "csv"});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out ==
        "file,points,max_points,passed,scenarios,\"points [two turns each]\",\"simulated_seconds [two turns each]\","
        "first_problem\n"
        "\"" + s + "good.rsp\",8,8,1,1,8,8.500,\"\"\n"
        "\"" + s + "once.rsp\",3,8,0,1,3,6.250,\"[two turns each] " + a +
            ":22:1: robot right: expected output 1 to turn ON 2 times; it turned ON 1 time (the run ended at line 6, "
            "4.000 s)\"\n"
        "\"" + s + "wrong_input.rsp\",0,8,0,1,0,2.000,\"[two turns each] " + a +
            ":20:1: expected the run to end: finished; it ended: deadlock at 2.000 s: deadlock: left waits at " +
            kCellSource + "/examples/two_robots/left.rsp:10 for input 1 (wired from right.OUT 1); right waits at " + s +
            "wrong_input.rsp:3 for input 2 (nothing drives it)\"\n");
  // The scenario file alone tests the teacher's own solution on the right robot.
  const CliResult own = runCli({"test", a});
  CHECK(own.code == 0);
  CHECK(mentions(own.out, a + " [two turns each] PASSED (4 expectations, 8.500 s simulated)\n"));
}

TEST_CASE("cell scenarios: bad input is an error at its line, with a hint", "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  const auto test = [&](const std::string& name, const std::string& text) {
    const std::string spec = dir.write(name, text);
    const CliResult r = runCli({"test", spec});
    INFO(r.out);
    CHECK(r.code == 2);
    return std::pair(spec, r.out);
  };
  {  // A program for a robot the cell lacks.
    const auto [spec, out] = test("ghost.rstest", "test: cell interlock.rsd\nprogram ghost left.rsp\nscenario a\n"
                                                  "expect: finished\n");
    CHECK(mentions(out, spec + ":2:9: error: workcell interlock has no robot labelled `ghost`\n"));
    CHECK(mentions(out, "  hint: the cell's robots are `left`, `right`\n"));
  }
  {  // A program file that is not there.
    const auto [spec, out] = test("missing.rstest", "test: cell interlock.rsd\nprogram left nothere.rsp\nscenario a\n"
                                                    "expect: finished\n");
    CHECK(mentions(out, spec + ":2:14: error: robot left's program 'nothere.rsp': cannot read file: "));
    CHECK(mentions(out, "  hint: a 'program LABEL FILE' line names a file relative to the scenario file\n"));
  }
  {  // The robot under test given another program too.
    const auto [spec, out] = test("twice.rstest", "test: cell interlock.rsd\ntest: robot right\nprogram right left.rsp\n"
                                                  "program right.rsp\nscenario a\nexpect: finished\n");
    CHECK(mentions(out, spec + ":3:9: error: robot right runs the program under test ('test: robot right'): a 'program "
                          "right FILE' line would replace it\n"));
  }
  {  // Grading a cell of several robots needs the submission's robot.
    const std::string spec = dir.write("nobody.rstest", "test: cell interlock.rsd\nscenario a\nexpect: finished\n");
    const CliResult r = runCli({"test", "--spec", spec, dir.file("right.rsp")});
    CHECK(r.code == 2);
    CHECK(mentions(r.out, spec + ": error: the cell runs several robots (`left`, `right`): the scenario file must say "
                            "which one a submission is\n"));
    CHECK(mentions(r.out, "  hint: add 'test: robot LABEL' before the first scenario\n"));
  }
}

TEST_CASE("cell scenarios: a program's own expectations on a cell where the other robot has a PROGRAM",
          "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  // right.rsp's text on the right robot (its `; robot:` line), left.rsp
  // (the cell's PROGRAM) on the left one: as the interlock example, 8.5 s.
  const std::string program =
      dir.write("mine.rsp", "; test: cell interlock.rsd\n; robot: right\n; expect: variable TURNS = 2\n"
                            "; expect: left.variable TURNS = 2\n; expect: time = 8.5\n" +
                                rs::testing::readBytes(dir.file("right.rsp")));
  const CliResult r = runCli({"test", program, "--format=json"});
  INFO(r.out);
  CHECK(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j.at("tests").size() == 1);
  CHECK(j.at("tests")[0].at("status") == "PASSED");
  CHECK(j.at("tests")[0].at("time") == 8.5);
  // 16 instructions of left, 18 of right (their traces: two turns each).
  CHECK(j.at("tests")[0].at("steps") == 34);
}

TEST_CASE("cell scenarios: the cell's devices and objects, whoever drives them", "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  // A feeder on the right robot's output 1, which rises at 4 s and 8.25 s
  // (the interlock's timeline): the first block goes in at 4 s, as object
  // 1 (the cell has no objects of its own); the second is due at 8.25 s,
  // its place taken by the first (docs/models.md, "Feeders"), so it waits:
  // 1 fed at the end, 8.5 s.
  std::string cell = rs::testing::readBytes(dir.file("interlock.rsd"));
  cell.insert(cell.rfind("END"), "  FEEDER parts block AT 1500 0 0 WHEN right.OUT 1\n");
  dir.write("interlock.rsd", cell);
  const std::string spec = dir.write("t.rstest",
                                     "test: cell interlock.rsd\n"
                                     "scenario fed by the right robot\n"
                                     "expect: finished\n"
                                     "expect: feeder parts count 1\n"
                                     "expect: object 1 at 1500 0 0\n"
                                     "expect: object block not held\n"
                                     "scenario a sensor it lacks\n"
                                     "expect: sensor eye count 1\n");
  const CliResult r = runCli({"test", spec});
  INFO(r.out);
  CHECK(mentions(r.out, spec + " [fed by the right robot] PASSED (4 expectations, 8.500 s simulated)\n"));
  CHECK(mentions(r.out, spec + ":8:16: error: the workcell has no sensor 'eye'\n"));
  CHECK(mentions(r.out, "  hint: the workcell's devices: feeder parts\n"));
}

TEST_CASE("cell scenarios: in a run of one robot, a label names that robot or is an error at it",
          "[testrun][cell-run]") {
  const TempDir dir;
  // Two robots, no PROGRAMs: the program runs on left alone (its `; robot:` line).
  dir.write("two.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left\n  ROBOT rhino-xr4 AT 3000 750 0 AS right\nEND\n");
  const std::string program = dir.write("p.rsp",
                                        "; test: cell two.rsd\n"
                                        "; robot: left\n"
                                        "; expect: left.motors F=0\n"        // holds: it never moves
                                        "; expect: right.motors F=0\n"       // 4
                                        "; expect: ghost.output 1 off\n"     // 5
                                        "        END\n");
  const CliResult r = runCli({"test", program});
  INFO(r.out);
  CHECK(r.code == 1);
  CHECK(mentions(r.out, program + ":4:11: error: robot right runs no program in this test: it has no run to check\n"));
  CHECK(mentions(r.out, "  hint: the robot with a program: `left`\n"));
  CHECK(mentions(r.out, program + ":5:11: error: workcell two has no robot labelled `ghost`\n"));
  CHECK(!mentions(r.out, program + ":3:"));
  const std::string alone = dir.write("q.rsp", "; expect: arm.output 1 off\n        END\n");
  const CliResult q = runCli({"test", alone});
  CHECK(q.code == 1);
  CHECK(mentions(q.out, alone + ":1:11: error: the run has no workcell: 'arm.' names a robot of one\n"));
}

TEST_CASE("cell scenarios: one robot's line before another robot's", "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  // The interlock's timeline: left's output 1 ON at 2 s, right's input 1
  // ON at 2 s too (a wire without AFTER), right's output 1 ON at 4 s and
  // OFF at 4.25 s, left's input 1 ON at 4.25 s and OFF at 4.5 s.
  const std::string spec = dir.write("t.rstest",
                                     "test: cell interlock.rsd\n"
                                     "scenario a\n"
                                     "expect: left.output 1 on before right.output 1 on\n"    // 3: holds
                                     "expect: right.output 1 on before left.output 1 on\n"    // 4
                                     "expect: left.output 1 on before right.input 1 on\n"     // 5
                                     "expect: right.output 1 off before left.input 1 off\n"   // 6: holds
                                     "expect: left.output 2 on before right.output 1 on\n"    // 7
                                     "expect: left.output 1 on before ghost.output 1 on\n");  // 8
  const CliResult r = runCli({"test", spec});
  INFO(r.out);
  CHECK(r.code == 1);
  CHECK(mentions(r.out, spec + ":4:1: error: expected right.output 1 ON before left.output 1 ON; left.output 1 ON came "
                               "first, at 2.000 s (right.output 1 ON at 4.000 s)\n"));
  CHECK(mentions(r.out, spec + ":5:1: error: expected left.output 1 ON before right.input 1 ON; right.input 1 ON came at "
                               "the same time, at 2.000 s (left.output 1 ON at 2.000 s)\n"));
  CHECK(mentions(r.out, spec + ":7:1: error: expected left.output 2 ON before right.output 1 ON; left.output 2 ON never "
                               "happened (the run ended at 8.500 s)\n"));
  CHECK(mentions(r.out, spec + ":8:33: error: workcell interlock has no robot labelled `ghost`\n"));
  CHECK(!mentions(r.out, spec + ":3:"));
  CHECK(!mentions(r.out, spec + ":6:"));
}

TEST_CASE("cell scenarios: a cell's golden trace is what run --cell --trace prints, --update writes it",
          "[testrun][cell-run]") {
  const TempDir dir;
  interlockIn(dir);
  std::filesystem::create_directory(dir.file("golden"));
  const std::string spec = dir.write("t.rstest", "test: cell interlock.rsd\nscenario a\nexpect: finished\n"
                                                 "expect: trace golden/interlock.trace\n");
  const CliResult missing = runCli({"test", spec});
  CHECK(missing.code == 1);
  CHECK(mentions(missing.out, "  hint: robotsim test --update writes it from the run\n"));
  // --update refuses to write in CI (CI set): this test writes on purpose.
  const char* ci = std::getenv("CI");
  const std::string ciValue = ci ? ci : "";
  ::unsetenv("CI");
  const CliResult update = runCli({"test", spec, "--update"});
  if (ci) ::setenv("CI", ciValue.c_str(), 1);
  INFO(update.out);
  CHECK(update.code == 0);
  // The golden file: every robot's lines, labelled, as `run --cell --trace`
  // prints them before its summary ("run of cell ..." and what follows).
  const CliResult run = runCli({"run", "--cell", dir.file("interlock.rsd"), "--trace"});
  const std::string golden = rs::testing::readBytes(dir.file("golden/interlock.trace"));
  REQUIRE(run.out.find("run of cell interlock:") != std::string::npos);
  CHECK(golden == run.out.substr(0, run.out.find("run of cell interlock:")));
  CHECK(mentions(golden, "right:      4.250      7     10  OUTSIG  1 OFF"));  // right answers at 4.25 s
  CHECK(runCli({"test", spec}).code == 0);
  // A line changed: a failure at the first line that differs.
  std::string changed = golden;
  changed.replace(changed.find("right:      4.250"), 17, "right:      4.500");
  dir.write("golden/interlock.trace", changed);
  const CliResult differs = runCli({"test", spec});
  CHECK(differs.code == 1);
  CHECK(mentions(differs.out, "error: the trace differs from "));
}

TEST_CASE("robotsim test --coverage of a cell: each robot's program, counted over every scenario",
          "[testrun][cli][robots]") {
  const TempDir dir;
  interlockIn(dir);
  // Scenario 1 (the interlock as it is): left runs its 9 instruction lines,
  // lines 7-13 twice (the JMPVAR jumps once, goes on once), SET and END
  // once; right the same, its SET once. Scenario 2: both robots run
  // right.rsp, each does SET (line 4) and waits at line 5 for ever (a
  // deadlock: a WAITFOR that never ends is not counted). So right.rsp's
  // SET ran 3 times, its other lines as in scenario 1; left.rsp only in
  // scenario 1. The paths differ (PROGRAM beside the cell, `program` beside
  // the scenario file) yet name one file: listed once.
  const std::string spec = dir.write("s.rstest",
                                     "test: cell interlock.rsd\n"
                                     "scenario turns\n"
                                     "expect: finished\n"
                                     "scenario both wait\n"
                                     "program left right.rsp\n"
                                     "expect: deadlock\n");
  const std::string info = dir.file("c.info");
  const CliResult r = runCli({"test", spec, "--coverage", "--lcov", info});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(mentions(r.out, "left.rsp: 9 of 9 instruction lines ran, 2 of 2 jump directions taken\n"));
  CHECK(mentions(r.out, "right.rsp: 10 of 10 instruction lines ran, 2 of 2 jump directions taken\n"));
  CHECK(mentions(r.out, "        3:     4:         SET TURNS 0\n"));
  CHECK(mentions(r.out, "        2:    12:         JMPVAR TURNS < 2 again   [jumped 1, went on 1]\n"));
  // Not the scenario file's lines: the programs'.
  CHECK_FALSE(mentions(r.out, "coverage of " + spec));
  std::size_t listings = 0;
  for (std::size_t at = r.out.find("coverage of "); at != std::string::npos; at = r.out.find("coverage of ", at + 1))
    ++listings;
  CHECK(listings == 2);
  const std::string lcov = rs::testing::readBytes(info);
  CHECK(mentions(lcov, "left.rsp\nBRDA:13,0,0,1\nBRDA:13,0,1,1\nDA:6,1\nDA:7,2\n"));
  CHECK(mentions(lcov, "right.rsp\nBRDA:12,0,0,1\nBRDA:12,0,1,1\nDA:4,3\nDA:5,2\n"));
}
