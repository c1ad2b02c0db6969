// Issue 36: stimuli that name a robot of the cell by its label
// (`at 1.5 input right.3 on`, `--input right.3=ON@1.5`). The reader keeps
// the label and its column; the run checks it against the cell, keeps what
// the driven robot reads and warns about the rest. Columns counted by hand
// (1-based) from the lines below.
#include <catch2/catch.hpp>

#include <string>

#include "compiler/stimuli/stimuli.h"
#include "tests/cli/cli_support.h"

namespace stimuli_robots_test {

const char* const kTwoRobots =
    "WORKCELL two\n"
    "  ROBOT rhino-xr4 AT 0 750 0 AS left\n"
    "  ROBOT rhino-xr4 AT 3000 750 0 AS right\n"
    "END\n";

// `robotsim run p.rsp` (WAITFOR 3 ON) in `dir` with ARGS after it.
rs::testing::CliResult runWaiting(const rs::testing::TempDir& dir, std::vector<std::string> args) {
  dir.write("p.rsp", "        WAITFOR 3 ON\n        END\n");
  args.insert(args.begin(), {"run", dir.file("p.rsp")});
  return rs::testing::runCli(args);
}

}  // namespace stimuli_robots_test

using namespace stimuli_robots_test;

TEST_CASE("stimuli robots: a label before the line number is kept with its column", "[stimuli][labels]") {
  const auto parsed = rs::stimuli::parseStimuli(
      "at 1.5 input right.3 on\n"
      "when output left.1 on then input Right.2 off after 0.5\n"
      "at 2 input 4 on\n",
      "s.stim");
  REQUIRE(parsed);
  REQUIRE(parsed->changes.size() == 2);
  CHECK(parsed->changes[0].robot == "right");
  CHECK(parsed->changes[0].input == 3);
  CHECK(parsed->changes[0].robotColumn == 14);  // `right.3` starts after "at 1.5 input "
  CHECK(parsed->changes[1].robot.empty());
  CHECK(parsed->changes[1].robotColumn == 0);
  REQUIRE(parsed->rules.size() == 1);
  CHECK(parsed->rules[0].outputRobot == "left");
  CHECK(parsed->rules[0].outputRobotColumn == 13);  // after "when output "
  CHECK(parsed->rules[0].inputRobot == "Right");
  CHECK(parsed->rules[0].inputRobotColumn == 34);  // after "when output left.1 on then input " (33 bytes)
  CHECK(parsed->rules[0].input == 2);
  CHECK_FALSE(parsed->rules[0].inputOn);

  const auto arg = rs::stimuli::parseStimulusArg("right.3=ON@2");
  REQUIRE(arg);
  CHECK(arg->robot == "right");
  CHECK(arg->input == 3);
  CHECK(arg->at == 2'000'000);
}

TEST_CASE("stimuli robots: a bad label or number after the label is an error at its place", "[stimuli][labels]") {
  const auto parsed = rs::stimuli::parseStimuli(
      "at 1 input right.9 on\n"    // the number after the label: column 18
      "at 1 input r!ght.3 on\n"    // the label: column 12
      "at 1 input 3.5 on\n",       // a number, not a label: column 12
      "s.stim");
  REQUIRE_FALSE(parsed);
  const auto& f = parsed.failures();
  REQUIRE(f.size() == 3);
  CHECK(f[0].pos.line == 1);
  CHECK(f[0].pos.col == 18);
  CHECK(f[0].message == "input number must be 1..8, got 9");
  CHECK(f[1].pos.col == 12);
  CHECK(f[1].message.find("expected a robot's label before '.'") == 0);
  CHECK(f[2].pos.col == 12);
  CHECK(f[2].message == "expected an input number 1..8, got '3.5'");
}

TEST_CASE("stimuli robots: the driven robot's labelled stimulus drives it, another's is a warning", "[stimuli][labels]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kTwoRobots);
  dir.write("s.stim", "at 1.5 input left.3 on\nat 2 input right.3 on\n");
  const auto r = runWaiting(dir, {"--cell", dir.file("c.rsd"), "--stimuli", dir.file("s.stim")});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(r.out.find("simulated time  1.500 s") != std::string::npos);  // left's input 3 ended the WAITFOR
  CHECK(r.err.find("s.stim:2:12: warning: this stimulus is for robot `right`, which runs no program") !=
        std::string::npos);

  // right's input alone never reaches left's WAITFOR: a deadlock, not left's input.
  const auto other = runWaiting(dir, {"--cell", dir.file("c.rsd"), "--input", "right.3=ON@1"});
  CHECK(other.code != 0);
  const auto own = runWaiting(dir, {"--cell", dir.file("c.rsd"), "--input", "LEFT.3=ON@1"});
  CHECK(own.code == 0);
}

TEST_CASE("stimuli robots: an unknown label, or a label without a cell, is a positioned error with a hint",
          "[stimuli][labels]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kTwoRobots);
  dir.write("s.stim", "at 1 input 3 on\nwhen output lefty.1 on then input 2 on\n");
  const auto r = runWaiting(dir, {"--cell", dir.file("c.rsd"), "--stimuli", dir.file("s.stim")});
  CHECK(r.code == 2);
  CHECK(r.err.find("s.stim:2:13: error: this rule's output names robot `lefty`, but workcell two has no robot "
                   "labelled so") != std::string::npos);
  CHECK(r.err.find("hint: the cell's robots are `left`, `right`") != std::string::npos);

  const auto none = runWaiting(dir, {"--input", "left.3=ON@1"});
  CHECK(none.code == 2);
  CHECK(none.err.find("--input: error: this stimulus names robot `left`, but the run has no cell") !=
        std::string::npos);
}
