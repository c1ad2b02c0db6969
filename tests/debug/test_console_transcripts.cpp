// The terminal debugger against golden transcripts: each
// tests/debug/transcripts/NAME.cmds is run with `robotsim debug ... -x`,
// and everything it prints must equal NAME.out byte for byte (the source
// directory written as <src>). Together they cover every command, every
// stop reason (entry, breakpoint, watch, step, time, start, end, deadlock,
// runtime error, limit) and bad commands, which get one message and leave
// the session going.
//
// How the goldens were checked: each .out was written by the program
// (ROBOTSIM_UPDATE_GOLDEN=1) and then read line by line against the
// program text, the disasm listing and the motor speeds of
// tests/examples/test_examples.cpp: the clock at every stop is the sum of
// the moves before it (a move lasts |delta| / speed of its slowest motor),
// the step counts are the instructions before it counted by hand, the
// call stacks follow the GOSUBs, and every error message says what was
// wrong with its command. Notes on the less obvious lines are in
// tests/debug/transcripts/README.md.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tests/debug/debug_test_util.h"
#include "tests/support/build_facts.h"

namespace {

const std::string kDir = rendertest::kSourceDir + "/tests/debug/";

std::string normalised(std::string text) {
  for (std::size_t at; (at = text.find(rendertest::kSourceDir)) != std::string::npos;)
    text.replace(at, rendertest::kSourceDir.size(), "<src>");
  return text;
}

void checkTranscript(const std::string& name, std::vector<std::string> args) {
  args.insert(args.begin(), "debug");
  args.push_back("-x");
  args.push_back(kDir + "transcripts/" + name + ".cmds");
  const rs::testing::CliResult r = rs::testing::runCli(args);
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  const std::string golden = kDir + "transcripts/" + name + ".out";
  const std::string actual = normalised(r.out);
  if (rs::testing::rewriteGolden(golden, actual)) return;
  CHECK(actual == rs::testing::readBytes(golden));
}

}  // namespace

TEST_CASE("debug transcript: stepping in, over, out and back through nested subroutines", "[debug][transcript]") {
  checkTranscript("stepping", {debugtest::kExamples + "nested_subroutines.rsp"});
}

TEST_CASE("debug transcript: every short form, instruction and variable breakpoints, a motor watch",
          "[debug][transcript]") {
  checkTranscript("short_forms", {debugtest::kExamples + "nested_subroutines.rsp"});
}

TEST_CASE("debug transcript: outputs, inputs, watches, hit counts, set input, goto-time", "[debug][transcript]") {
  checkTranscript("io", {debugtest::kExamples + "pick_and_place.rsp", "--stimuli", debugtest::kExamples + "pick_and_place.stim"});
}

TEST_CASE("debug transcript: a deadlock leaves the session inspectable", "[debug][transcript]") {
  checkTranscript("deadlock", {debugtest::kExamples + "pick_and_place.rsp"});
}

TEST_CASE("debug transcript: the step limit", "[debug][transcript]") {
  checkTranscript("limits", {kDir + "programs/count_forever.rsp", "--max-steps", "40"});
}

TEST_CASE("debug transcript: a runtime error", "[debug][transcript]") {
  checkTranscript("overflow", {kDir + "programs/overflow.rsp"});
}

TEST_CASE("debug transcript: set VAR = VALUE, replayed going back and forth", "[debug][transcript]") {
  checkTranscript("set_variable", {debugtest::kExamples + "nested_subroutines.rsp"});
}

TEST_CASE("debug transcript: bad commands get a message and the session goes on", "[debug][transcript]") {
  checkTranscript("bad", {debugtest::kExamples + "nested_subroutines.rsp"});
}

TEST_CASE("debug transcript: the worked session of docs/debugging.md finds the bug", "[debug][transcript]") {
  checkTranscript("gantry_bug", {debugtest::kExamples + "debugging/gantry_pick_bug.rsp", "--cell", "gantry-cell"});
}

TEST_CASE("the worked session's example: robotsim test fails the buggy copy and passes the fixed program",
          "[debug][transcript]") {
  const rs::testing::CliResult bug = rs::testing::runCli({"test", debugtest::kExamples + "debugging/gantry_pick_bug.rsp"});
  CHECK(bug.code == 1);
  CHECK(bug.out.find("expected object 3 (block) at (750.00, 30.00, 200.00) within 0.01 at the end; it is at (280.00, 30.00, 700.00)") !=
        std::string::npos);
  const rs::testing::CliResult fixed = rs::testing::runCli({"test", debugtest::kExamples + "gantry_pick.rsp"});
  CHECK(fixed.code == 0);
}

TEST_CASE("robotsim debug reads its commands from standard input when it is not a terminal", "[debug][transcript]") {
  const rs::testing::TempDir dir;
  const std::string out = dir.file("out.txt");
  const std::string command = "printf 'break grip\\ncontinue\\nprint GRIPS\\n' | '" + std::string(rs::testing::robotsimBinary()) +
                              "' debug '" + debugtest::kExamples + "nested_subroutines.rsp' > '" + out + "' 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);  // the end of input ends the session: exit 0
  const std::string text = rs::testing::readBytes(out);
  // Each command echoed after the prompt, then its answer: grip first runs
  // after pick's first move (0.5 s, step 4), before its ADD.
  CHECK(text.find("(rsdb) break grip\nbreakpoint 1: label grip, line 38\n") != std::string::npos);
  CHECK(text.find("(rsdb) continue\nbreakpoint 1 (label grip, line 38)\nline 38 @19, step 4, clock 0.500 s\n") !=
        std::string::npos);
  CHECK(text.find("(rsdb) print GRIPS\nGRIPS = 0\n") != std::string::npos);
}
