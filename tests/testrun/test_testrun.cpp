// `robotsim test` and the expectations it reads (tools/testrun/, docs/testing.md).
// Every expected time, value and position below is worked out by hand from
// the programs (motor speeds of the default Rhino SCARA: E and D 400, C 300,
// B 500, A 200 units per second).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "diag/source_file.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/suite.h"
#include "vm/stop_reason.h"
#include "tests/cli/cli_support.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;
using rs::testrun::ExpectKind;

const std::string kSource = ROBOTSIM_SOURCE_DIR;

rs::testrun::ParsedExpectations parse(const std::string& text) {
  return rs::testrun::parseExpectations(rs::diag::SourceFile("t.rsp", text));
}

// The output with the source folder and the wall time taken out.
std::string normalised(std::string text) {
  for (std::size_t at; (at = text.find(kSource + "/")) != std::string::npos;) text.erase(at, kSource.size() + 1);
  const std::size_t in = text.rfind(" in ");
  if (in != std::string::npos && text.size() > 3 && text.compare(text.size() - 3, 3, " s\n") == 0)
    text = text.substr(0, in) + " in S s\n";
  return text;
}

}  // namespace

TEST_CASE("expectations: every form is read into its parts", "[testrun]") {
  const auto p = parse(
      "; test: cell scara-pick\n"
      "; test: stimuli belt.stim\n"
      "; test: input 1=ON@2\n"
      "; test: max-time 60\n"
      "; test: max-steps 5000\n"
      "; expect: finished\n"
      "; EXPECT: Runtime Error at line 12\n"
      "; expect: time <= 40\n"
      "; expect: motors E=0 d=-20 within 2\n"
      "; expect: output 3 on during 2..5.5\n"
      "; expect: input 2 off at 1.25\n"
      "; expect: output 3 pulses 3 times\n"
      "; expect: variable N = -4\n"
      "; expect: tcp 1 2.5 -3 within 0.1\n"
      "; expect: object block at 10 20 30\n"
      "; expect: object block not held\n"
      "GOTO X ; expect-error: undefined label 'X'\n"
      "; an ordinary comment: expect nothing\n");
  REQUIRE(p.errors.empty());
  CHECK(p.settings.cell == "scara-pick");
  CHECK(p.settings.stimuliFile == "belt.stim");
  CHECK(p.settings.inputs == std::vector<std::string>{"1=ON@2"});
  CHECK(p.settings.maxTime == "60");
  CHECK(p.settings.maxSteps == std::optional<std::uint64_t>(5000));
  REQUIRE(p.expectations.size() == 12);
  const auto& e = p.expectations;
  CHECK(e[0].kind == ExpectKind::Status);
  CHECK(e[0].reason == rs::vm::StopReason::End);
  CHECK(e[0].pos == rs::diag::Pos{6, 3});
  CHECK(e[1].reason == rs::vm::StopReason::RuntimeError);
  CHECK(e[1].line == 12);
  CHECK(e[2].kind == ExpectKind::Time);
  CHECK(e[2].compare == rs::testrun::Compare::AtMost);
  CHECK(e[2].micros == 40'000'000);
  CHECK(e[3].kind == ExpectKind::Motors);
  CHECK(e[3].motors == std::vector<std::pair<char, std::int32_t>>{{'E', 0}, {'D', -20}});
  CHECK(e[3].within == 2);
  CHECK(e[4].kind == ExpectKind::Output);
  CHECK(e[4].number == 3);
  CHECK(e[4].on);
  CHECK(e[4].during == std::optional(std::pair<rs::vm::Micros, rs::vm::Micros>{2'000'000, 5'500'000}));
  CHECK(e[5].kind == ExpectKind::Input);
  CHECK_FALSE(e[5].on);
  CHECK(e[5].at == std::optional<rs::vm::Micros>(1'250'000));
  CHECK(e[6].kind == ExpectKind::Pulses);
  CHECK(e[6].count == 3);
  CHECK(e[7].kind == ExpectKind::Variable);
  CHECK(e[7].name == "N");
  CHECK(e[7].value == -4);
  CHECK(e[8].kind == ExpectKind::Tcp);
  CHECK(e[8].point == std::array<double, 3>{1, 2.5, -3});
  CHECK(e[8].tolerance == 0.1);
  CHECK(e[9].kind == ExpectKind::ObjectAt);
  CHECK(e[9].tolerance == 0.5);  // the default
  CHECK(e[10].kind == ExpectKind::ObjectHeld);
  CHECK_FALSE(e[10].on);
  CHECK(e[11].kind == ExpectKind::CompileError);
  CHECK(e[11].message == "undefined label 'X'");
  CHECK(e[11].pos == rs::diag::Pos{17, 10});
}

TEST_CASE("expectations: a bad line is an error at the word that is wrong, and every one is reported", "[testrun]") {
  const auto p = parse(
      "; expect: output 9 on\n"              // 1: col 18
      "; expect: time < 4\n"                 // 2: col 16
      "; expect: motors E100\n"              // 3: col 18
      "; expect: output 1 on during 5..2\n"  // 4: col 30
      "; expect: teleport\n"                 // 5: col 11
      "; expect: finished now\n"             // 6: col 20
      "; test: colour red\n"                 // 7: col 9
      "; expect-error:\n"                    // 8: col 16, the end of the line
      "; expect:\n");                        // 9: col 10
  std::vector<std::pair<rs::diag::Pos, std::string>> got;
  for (const auto& d : p.errors) got.emplace_back(d.pos, d.message);
  REQUIRE(got.size() == 9);
  CHECK(got[0] == std::pair<rs::diag::Pos, std::string>{{1, 18}, "expected an output number (1..8), got '9'"});
  CHECK(got[1] == std::pair<rs::diag::Pos, std::string>{{2, 16}, "expected <=, >= or = after 'time'"});
  CHECK(got[2].first == rs::diag::Pos{3, 18});
  CHECK(got[2].second == "expected a motor and its encoder value, e.g. E=100, got 'E100'");
  CHECK(got[3].first == rs::diag::Pos{4, 30});
  CHECK(got[4].first == rs::diag::Pos{5, 11});
  CHECK(got[4].second.rfind("unknown expectation 'teleport'", 0) == 0);
  CHECK(got[5] == std::pair<rs::diag::Pos, std::string>{{6, 20}, "unexpected 'now' after the end of the expectation"});
  CHECK(got[6].first == rs::diag::Pos{7, 9});
  CHECK(got[7].first == rs::diag::Pos{8, 16});
  CHECK(got[8].first == rs::diag::Pos{9, 10});
  CHECK(p.expectations.empty());
}

TEST_CASE("expectations: every way a run ends is read by its words in vm/stop_reason.h's table", "[testrun]") {
  // A reason added to the table, or a word changed there, must be what
  // `; expect:` reads and what docs/testing.md shows: the two cannot drift.
  std::ifstream docFile(kSource + "/docs/testing.md");
  const std::string doc((std::istreambuf_iterator<char>(docFile)), std::istreambuf_iterator<char>());
  REQUIRE_FALSE(doc.empty());
  int ends = 0;
  for (int i = 0; rs::vm::isOver(static_cast<rs::vm::StopReason>(i)); ++i, ++ends) {
    const auto reason = static_cast<rs::vm::StopReason>(i);
    const std::string words(rs::vm::stopReasonName(reason));
    INFO(words);
    const auto p = parse("; expect: " + words + "\n; expect: " + words + " at line 3\n");
    REQUIRE(p.errors.empty());
    REQUIRE(p.expectations.size() == 2);
    CHECK(p.expectations[0].kind == ExpectKind::Status);
    CHECK(p.expectations[0].reason == reason);
    CHECK(p.expectations[0].line == 0);
    CHECK(p.expectations[1].reason == reason);
    CHECK(p.expectations[1].line == 3);
    CHECK(doc.find("expect: " + words) != std::string::npos);
  }
  CHECK(ends == 7);
  // The list of subjects a bad line is told, as it read before the words
  // came from the table (written here by hand).
  const auto bad = parse("; expect: teleport\n");
  REQUIRE(bad.errors.size() == 1);
  CHECK(bad.errors[0].message ==
        "unknown expectation 'teleport': expect one of finished, deadlock, step limit, time limit, clock standing "
        "still, knot limit, runtime error, time, motors, motor, output, input, variable, tcp, object, trace, no collision, "
        "collides with, sensor, conveyor, feeder, sink");
  // A stop's first word alone still names it, and says which word is missing.
  const auto step = parse("; expect: step limits\n; expect: time\n");
  REQUIRE(step.errors.size() == 2);
  CHECK(step.errors[0].message == "expected 'limit', got 'limits'");
  CHECK(step.errors[1].message == "expected <=, >= or = after 'time'");
}

TEST_CASE("robotsim test: the examples and the passing tests pass", "[testrun][cli]") {
  const CliResult passing = runCli({"test", kSource + "/examples/tests/passing"});
  INFO(passing.out);
  CHECK(passing.code == 0);
  // 3 programs, 5 scenarios (adept_production.rstest's and adept_hour.rstest's two on a conveyor cell)
  CHECK(normalised(passing.out).find("8 passed, 0 failed, 0 errors in S s\n") != std::string::npos);
  std::vector<std::string> args{"test"};
  for (const char* name : {"counted_loop", "first_moves", "gantry_pick", "nested_subroutines", "pick_and_place",
                           "sensor_branching", "soft_home", "workcell_view", "adept_hour"})
    args.push_back(kSource + "/examples/" + name + ".rsp");
  const CliResult examples = runCli(args);
  INFO(examples.out);
  CHECK(examples.code == 0);
  CHECK(normalised(examples.out).find("9 passed, 0 failed, 0 errors in S s\n") != std::string::npos);
  // adept_hour's own expectations: an hour of production, 600 blocks taken (worked out in the program).
  CHECK(examples.out.find("adept_hour.rsp PASSED (7 expectations, 3599.") != std::string::npos);
}

TEST_CASE("robotsim test: the deliberately failing tests report what the hand-written file says", "[testrun][cli]") {
  const CliResult r = runCli({"test", kSource + "/examples/tests/failing"});
  CHECK(r.code == 2);  // one test could not start
  CHECK(r.err.empty());
  CHECK(normalised(r.out) == rs::testing::readBytes(kSource + "/examples/tests/failing/expected-output.txt"));
}

TEST_CASE("robotsim test: each kind of expectation fails with what happened, when and where", "[testrun][cli]") {
  const TempDir dir;
  // Output 1 is ON from 0.5 s to 1 s; E moves 200 units in 0.5 s (0.5 .. 1 s), then A closes 120 in 0.6 s.
  const std::string program = dir.write("p.rsp",
                                        "; expect: output 1 on during 0.25..0.75\n"   // 1: OFF at 0.25, from the start
                                        "; expect: output 1 on at 1\n"                // 2: OFF at 1, by line 10
                                        "; expect: motors E=210 within 5\n"           // 3: E is at 200
                                        "; expect: variable N = 2\n"                  // 4: N is 1
                                        "; expect: time >= 2\n"                       // 5: ends at 1.6 s
                                        "; expect: tcp 0 0 0\n"                       // 6: no workcell
                                        "DELAY 0.5\n"                                  // 7
                                        "OUTSIG 1 ON\n"                               // 8
                                        "MOVE 200 0 0 0 0\n"                          // 9
                                        "OUTSIG 1 OFF\n"                              // 10
                                        "MOVE 0 0 0 0 120\n"                          // 11
                                        "SET N 1\n"                                   // 12
                                        "END\n");                                     // 13
  const CliResult r = runCli({"test", program});
  CHECK(r.code == 1);
  const std::string f = program + ":";
  for (const std::string& want :
       {f + "1:3: error: expected output 1 ON during 0.250..0.750 s; it was OFF at 0.250 s (from the start)\n",
        f + "2:3: error: expected output 1 ON at 1.000 s; it was OFF then (set by line 10)\n",
        f + "3:18: error: expected motor E at 210 within 5 at the end; it is at 200 at line 13, 1.600 s\n",
        f + "4:3: error: expected variable N = 2 at the end; it is 1 at line 13, 1.600 s\n",
        f + "5:3: error: expected the run's simulated time >= 2.000 s; it ended at line 13, 1.600 s\n",
        f + "6:3: error: the run has no workcell: name one with '; test: cell NAME'\n"}) {
    INFO(want);
    CHECK(r.out.find(want) != std::string::npos);
  }
  CHECK(normalised(r.out).find("0 passed, 1 failed, 0 errors in S s\n") != std::string::npos);
}

TEST_CASE("robotsim test: one event before another", "[testrun][cli]") {
  // Input 2 turns ON at 1 s (the stimulus); output 3 turns ON at 1.5 s and OFF at 2 s.
  const TempDir dir;
  const std::string program = dir.write("o.rsp",
                                        "; test: input 2=ON@1\n"
                                        "; expect: input 2 on before output 3 on\n"    // 2: holds
                                        "; expect: output 3 on before input 2 on\n"    // 3: input first, at 1 s
                                        "; expect: output 3 off before output 3 on\n"  // 4: OFF after ON comes later
                                        "; expect: output 4 on before input 2 on\n"    // 5: output 4 never
                                        "WAITFOR 2 ON\n"
                                        "DELAY 0.5\n"
                                        "OUTSIG 3 ON\n"
                                        "DELAY 0.5\n"
                                        "OUTSIG 3 OFF\n"
                                        "END\n");
  const CliResult r = runCli({"test", program});
  CHECK(r.code == 1);
  CHECK(r.out.find(":2:3:") == std::string::npos);
  CHECK(r.out.find(program + ":3:3: error: expected output 3 ON before input 2 ON; input 2 ON came first, at 1.000 s "
                             "(output 3 ON at 1.500 s)\n") != std::string::npos);
  CHECK(r.out.find(program + ":4:3: error: expected output 3 OFF before output 3 ON; output 3 ON came first, at "
                             "1.500 s (output 3 OFF at 2.000 s)\n") != std::string::npos);
  CHECK(r.out.find(program + ":5:3: error: expected output 4 ON before input 2 ON; output 4 ON never happened") !=
        std::string::npos);
}

TEST_CASE("robotsim test: a variable at a time and during a window", "[testrun][cli]") {
  const TempDir dir;
  const std::string program = dir.write("v.rsp",
                                        "; expect: variable N = 1 at 0.5\n"      // 1: holds (set to 1 at 0)
                                        "; expect: variable N = 1 during 0..2\n"  // 2: 2 from 1 s on (line 9)
                                        "; expect: variable N = 2 at 1\n"        // 3: holds (ADD at 1 s)
                                        "; expect: variable N = 0 at 0\n"        // 4: already 1 at 0 (line 7)
                                        "; expect: variable N = 1\n"             // 5: 2 at the end
                                        "; expect: variable N = 2 during 1..5\n"  // 6: holds
                                        "SET N 1\n"                             // 7: at 0 s
                                        "DELAY 1\n"                             // 8: 0 .. 1 s
                                        "ADD N 1\n"                             // 9: at 1 s
                                        "DELAY 1\n"                             // 10: 1 .. 2 s
                                        "END\n");
  const CliResult r = runCli({"test", program});
  CHECK(r.code == 1);
  CHECK(r.out.find(":1:3:") == std::string::npos);
  CHECK(r.out.find(program + ":2:3: error: expected variable N = 1 during 0.000..2.000 s; it was 2 at 1.000 s (set by "
                             "line 9)\n") != std::string::npos);
  CHECK(r.out.find(":3:3:") == std::string::npos);
  CHECK(r.out.find(program + ":4:3: error: expected variable N = 0 at 0.000 s; it was 1 then (set by line 7)\n") !=
        std::string::npos);
  CHECK(r.out.find(program + ":5:3: error: expected variable N = 1 at the end; it is 2 at line 11, 2.000 s\n") !=
        std::string::npos);
  CHECK(r.out.find(":6:3:") == std::string::npos);
}

TEST_CASE("robotsim test: a motor that must never pass a value", "[testrun][cli]") {
  const TempDir dir;
  const std::string program = dir.write("m.rsp",
                                        "; expect: motor E never above 300\n"   // 1: E goes to 400 at line 5
                                        "; expect: motor E never below -100\n"  // 2: holds: E never goes below 0
                                        "; expect: motor C never below -50\n"   // 3: C goes to -60 at line 6
                                        "; expect: motor Q never above 1\n"     // 4: no such motor
                                        "MOVE 400 0 0 0 0\n"                    // 5: 0 .. 1 s
                                        "MOVE -400 0 -60 0 0\n"                 // 6: E 1 .. 2 s; C 60 units at 300/s: 1 .. 1.2 s
                                        "END\n");
  const CliResult r = runCli({"test", program});
  CHECK(r.code == 1);
  CHECK(r.out.find(program + ":1:3: error: expected motor E never above 300; it moved to 400 at line 5 (0.000..1.000 "
                             "s)\n") != std::string::npos);
  CHECK(r.out.find(":2:3:") == std::string::npos);
  CHECK(r.out.find(program + ":3:3: error: expected motor C never below -50; it moved to -60 at line 6 (1.000..1.200 "
                             "s)\n") != std::string::npos);
  CHECK(r.out.find(program + ":4:17: error: the robot has no motor Q\n") != std::string::npos);  // at the letter
}

TEST_CASE("robotsim test: objects and the tool centre point on a workcell", "[testrun][cli]") {
  // The gantry of stdlib/workcells/gantry-cell.rsd: its tool centre point
  // is (500 + X/10, 200 - Y/10, 400 + Z/10); block 1 (object 2) sits AT
  // 200 30 700, its centre at the TCP of MOVETO -2800 2800 1500 0, (220, 50, 680).
  const TempDir dir;
  const std::string program = dir.write("g.rsp",
                                        "; test: cell gantry-cell\n"
                                        "; expect: tcp 220 50 680 within 0.001\n"
                                        "; expect: object 2 held\n"
                                        "; expect: object block at 200 30 700 within 0.001\n"
                                        "; expect: object 3 held\n"
                                        "MOVETO -2800 2800 1500 0\n"
                                        "MOVE 0 0 0 100\n"
                                        "END\n");
  const CliResult r = runCli({"test", program, "--collisions=off"});  // the fingers graze the pallet
  CHECK(r.code == 1);
  CHECK(r.out.find(program + ":5:3: error: expected object 3 (block) held at the end; it is not held at line 8") != std::string::npos);
  CHECK(r.out.find(":2:3:") == std::string::npos);
  CHECK(r.out.find(":3:3:") == std::string::npos);
  CHECK(r.out.find(":4:3:") == std::string::npos);
}

TEST_CASE("robotsim test: JUnit, JSON, filters and shards", "[testrun][cli]") {
  const TempDir dir;
  dir.write("a_pass.rsp", "; expect: time = 0.25\nMOVE 100 0 0 0 0\nEND\n");
  dir.write("b_fail.rsp", "; expect: time = 1\nMOVE 100 0 0 0 0\nEND\n");
  dir.write("c_error.rsp", "; expect: time = soon\nEND\n");
  std::filesystem::create_directories(dir.path() / "sub");
  dir.write("sub/d_pass.rsp", "END\n");  // no expectation: run as check
  dir.write("sub/notes.txt", "not a program\n");
  const std::string root = dir.path().string();

  const std::string junit = dir.file("report.xml");
  const CliResult r = runCli({"test", root, "--junit", junit});
  CHECK(r.code == 2);
  const std::string xml = rs::testing::readBytes(junit);
  CHECK(xml.find("<testsuites name=\"robotsim test\" tests=\"4\" failures=\"1\" errors=\"1\">") != std::string::npos);
  CHECK(xml.find("<failure message=\"" + root + "/b_fail.rsp:1:3: expected the run&apos;s simulated time = 1.000 s;") !=
        std::string::npos);
  CHECK(xml.find("<error message=\"" + root + "/c_error.rsp:1:18: bad time &apos;soon&apos;") != std::string::npos);
  CHECK(xml.find("<testcase classname=\"" + root + "/a_pass.rsp\" name=\"a_pass\"/>") != std::string::npos);

  const CliResult json = runCli({"test", root, "--format=json"});
  const nlohmann::json j = nlohmann::json::parse(json.out);
  CHECK(j["passed"] == 2);
  CHECK(j["failed"] == 1);
  CHECK(j["errors"] == 1);
  REQUIRE(j["tests"].size() == 4);
  CHECK(j["tests"][3]["file"] == root + "/sub/d_pass.rsp");
  CHECK(j["tests"][1]["problems"][0]["line"] == 1);

  const CliResult filtered = runCli({"test", root, "--filter", "pass"});
  CHECK(filtered.code == 0);
  CHECK(normalised(filtered.out).find("2 passed, 0 failed, 0 errors in S s\n") != std::string::npos);

  // Three shards: disjoint, and together the whole run, line for line.
  const auto lines = [](const std::string& out) {
    std::multiset<std::string> s;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
      if (line.find(" passed, ") == std::string::npos) s.insert(line);
    return s;
  };
  std::multiset<std::string> together;
  for (const char* shard : {"1/3", "2/3", "3/3"})
    for (const std::string& l : lines(runCli({"test", root, "--shard", shard}).out)) together.insert(l);
  CHECK(together == lines(r.out));
  CHECK(runCli({"test", root, "--shard", "4/3"}).code == 2);
  CHECK(runCli({"test", root, "--shard", "x"}).err.find("--shard takes K/N") != std::string::npos);

  // Any number of jobs, the same output in the same order.
  CHECK(lines(runCli({"test", root, "-j", "1"}).out) == lines(runCli({"test", root, "-j", "3"}).out));
  CHECK(runCli({"test", root + "/missing"}).code == 2);
}

TEST_CASE("shards: a file's shard depends on its path alone", "[testrun]") {
  std::set<std::uint32_t> seen;
  for (int i = 0; i < 200; ++i) {
    const std::string path = "submissions/student" + std::to_string(i) + ".rsp";
    const std::uint32_t s = rs::testrun::shardOf(path, 4);
    CHECK(s >= 1);
    CHECK(s <= 4);
    CHECK(rs::testrun::shardOf(path, 4) == s);
    seen.insert(s);
  }
  CHECK(seen.size() == 4);  // 200 paths reach every shard
}

TEST_CASE("robotsim test --coverage and --lcov: counts by hand, a tracefile genhtml reads", "[testrun][cli]") {
  const TempDir dir;
  const std::string program = dir.write("c.rsp",
                                        "SET N 0\n"             // 1: once
                                        "loop: ADD N 1\n"       // 2: 3 times
                                        "JMPVAR N < 3 loop\n"   // 3: 3 times: jumps twice, goes on once
                                        "JMPIN 1 ON never\n"    // 4: once: goes on (input 1 is OFF)
                                        "END\n"                 // 5: once
                                        "never: GOTO loop\n");  // 6: never
  const std::string info = dir.file("c.info");
  const CliResult r = runCli({"test", program, "--coverage", "--lcov", info});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("coverage of " + program + ": 5 of 6 instruction lines ran, 3 of 4 jump directions taken\n") !=
        std::string::npos);
  CHECK(r.out.find("        3:     3: JMPVAR N < 3 loop   [jumped 2, went on 1]\n") != std::string::npos);
  CHECK(r.out.find("    #####:     6: never: GOTO loop\n") != std::string::npos);
  CHECK(rs::testing::readBytes(info) == "TN:\nSF:" + program +
                                            "\nBRDA:3,0,0,2\nBRDA:3,0,1,1\nBRDA:4,0,0,0\nBRDA:4,0,1,1\n"
                                            "DA:1,1\nDA:2,3\nDA:3,3\nDA:4,1\nDA:5,1\nDA:6,0\n"
                                            "BRF:4\nBRH:3\nLF:6\nLH:5\nend_of_record\n");
  // Debian's genhtml (package lcov) makes its pages from the tracefile.
  const std::string html = dir.file("html");
  const int status = std::system(("genhtml --quiet --branch-coverage -o " + html + " " + info + " > " +
                                  dir.file("genhtml.log") + " 2>&1")
                                     .c_str());
  INFO(rs::testing::readBytes(dir.file("genhtml.log")));
  CHECK(status == 0);
  CHECK(std::filesystem::exists(html + "/index.html"));
}

TEST_CASE("robotsim test: a scenario file checks one program in several worlds", "[testrun][cli]") {
  const std::string spec = kSource + "/examples/tests/passing/pick_and_place.rstest";
  const TempDir dir;
  const CliResult r = runCli({"test", spec, "--junit", dir.file("r.xml")});
  INFO(r.out);
  CHECK(r.code == 0);
  CHECK(r.out.find(spec + " [the cell works] PASSED (3 expectations, 34.900 s simulated)\n") != std::string::npos);
  CHECK(r.out.find(spec + " [no part ever arrives] PASSED (3 expectations, 0.000 s simulated)\n") != std::string::npos);
  const std::string xml = rs::testing::readBytes(dir.file("r.xml"));
  CHECK(xml.find("<testsuite name=\"" + spec + "\" tests=\"2\" failures=\"0\" errors=\"0\">") != std::string::npos);
  CHECK(xml.find("name=\"no part ever arrives\"/>") != std::string::npos);

  // Every bad line of a scenario file, in one run; the test cannot start.
  const std::string bad = dir.write("bad.rstest",
                                    "program p.rsp\n"
                                    "expect: finished\n"          // 2: before any scenario
                                    "scenario\n"                  // 3: no name
                                    "scenario one\n"
                                    "expect: output 0 on\n"       // 5: col 16
                                    "frobnicate\n"                // 6
                                    "program q.rsp\n");           // 7: twice
  const CliResult b = runCli({"test", bad});
  CHECK(b.code == 2);
  for (const std::string& want :
       {bad + ":2:1: error: expected 'scenario NAME' before the first expect: ('test:' lines before it are shared by "
              "every scenario; expectations are each scenario's own)\n",
        bad + ":3:9: error: expected the scenario's name after 'scenario'\n",
        bad + ":5:16: error: expected an output number (1..8), got '0'\n",
        bad + ":6:1: error: expected 'program FILE', 'scenario NAME', 'points N', 'test: ...' or 'expect: ...', got "
              "'frobnicate'\n",
        bad + ":7:1: error: the program is named twice\n"}) {
    INFO(want);
    CHECK(b.out.find(want) != std::string::npos);
  }
}

TEST_CASE("robotsim test --spec grades every submission, whatever each one does", "[testrun][cli]") {
  // examples/tests/grading, on rhino-scara (the shared `test: cell`): alice
  // does the task (3 s with a part: E out 1 s at 400 counts/s, the part at
  // 2 s, E back 1 s; 1 s then a wait without one); bob leaves E at 400 (the
  // part at 2 s, E out by 3 s; waits at 0 s without one); carol does not
  // compile (the compiler's own words, as `robotsim check` says them); dave
  // polls without letting the clock move and is stopped after grading's
  // 100,000 instructions at one instant. Points: the part's scenario gives
  // 1 (finished) + 3 (output 1 on) + 2 (motors E=0) = 6, expectation by
  // expectation; no part 4, all or nothing. So alice 6 + 4; bob 1 + 3 of the
  // first (E is at 400) + 4; carol nothing (nothing ran); dave 2 (his E
  // never moved: it is at 0 when the run is stopped) + 0.
  const std::string folder = kSource + "/examples/tests/grading";
  const CliResult r =
      runCli({"test", "--spec", folder + "/assignment.rstest", folder + "/submissions", "--format", "csv"});
  CHECK(r.code == 1);
  const std::string s = folder + "/submissions/";
  const std::string a = folder + "/assignment.rstest";
  CHECK(r.out ==
        "file,points,max_points,passed,scenarios,\"points [a part arrives at 2 s]\",\"simulated_seconds [a part "
        "arrives at 2 s]\",\"points [no part]\",\"simulated_seconds [no part]\",first_problem\n"
        "\"" + s + "alice.rsp\",10,10,2,2,6,3.000,4,1.000,\"\"\n"
        "\"" + s + "bob.rsp\",8,10,1,2,4,3.000,4,0.000,\"[a part arrives at 2 s] " + a +
            ":16:16: expected motor E at 0 at the end; it is at 400 at line 5, 3.000 s\"\n"
        "\"" + s + "carol.rsp\",0,10,0,2,0,,0,,\"[a part arrives at 2 s] " + s +
            "carol.rsp:3:18: expected ON or OFF, found 'ONN'\"\n"
        "\"" + s + "dave.rsp\",2,10,0,2,2,0.000,0,0.000,\"[a part arrives at 2 s] " + a +
            ":14:1: expected the run to end: finished; it ended: clock standing still at line 3, 0.000 s: 100000 "
            "instructions ran at 0.000 s without the simulated clock moving\"\n");
  const CliResult text = runCli({"test", "--spec", folder + "/assignment.rstest", folder + "/submissions"});
  CHECK(text.out.find("3 passed, 5 failed, 0 errors in ") != std::string::npos);
  CHECK(text.out.find("scenarios: [1] a part arrives at 2 s (6 points), [2] no part (4 points)\n") != std::string::npos);
  CHECK(text.out.find(s + "alice.rsp   10/10     2/2  6 3.000 s  4 1.000 s\n") != std::string::npos);
  CHECK(text.out.find(s + "carol.rsp    0/10     0/2        0 -        0 -  [a part") != std::string::npos);
  const CliResult json =
      runCli({"test", "--spec", folder + "/assignment.rstest", folder + "/submissions", "--format=json"});
  const nlohmann::json j = nlohmann::json::parse(json.out);
  REQUIRE(j["programs"].size() == 4);
  const nlohmann::json& bob = j["programs"][1];
  CHECK(bob["file"] == s + "bob.rsp");
  CHECK(bob["passed"] == 1);
  CHECK(bob["scenarios"] == 2);
  CHECK(bob["points"] == 8.0);
  CHECK(bob["max_points"] == 10.0);
  CHECK(bob["time"] == 3.0);
  REQUIRE(bob["by_scenario"].size() == 2);
  CHECK(bob["by_scenario"][0]["scenario"] == "a part arrives at 2 s");
  CHECK(bob["by_scenario"][0]["points"] == 4.0);
  CHECK(bob["by_scenario"][0]["max_points"] == 6.0);
  CHECK(bob["by_scenario"][0]["time"] == 3.0);
  CHECK(bob["by_scenario"][1]["status"] == "PASSED");
  CHECK(j["programs"][2]["by_scenario"][0]["time"].is_null());  // carol's never ran
  CHECK(j["tests"][2]["scenario"] == "a part arrives at 2 s");
  CHECK(j["tests"][2]["points"] == 4.0);
  CHECK(j["tests"][2]["max_points"] == 6.0);
}

TEST_CASE("robotsim test --spec: a spec without points, settings written once, points as a teacher writes them",
          "[testrun][cli]") {
  const TempDir dir;
  std::filesystem::create_directory(dir.file("sub"));
  // gantry-cell's motors X Z Y A: X at 1000 counts/s (docs/models.md).
  const std::string program = dir.write("sub/p.rsp", "        MOVE 1000 0 0 0\n        WAITFOR 1 ON\n        END\n");
  SECTION("an existing spec, no points: a point a scenario, passed or not") {
    const std::string spec = dir.write("old.rstest",
                                       "scenario on time\ntest: cell gantry-cell\ntest: input 1=ON@2\nexpect: finished\n"
                                       "scenario too slow\ntest: cell gantry-cell\ntest: input 1=ON@2\nexpect: time <= 1\n");
    const CliResult r = runCli({"test", "--spec", spec, dir.file("sub"), "--format=csv"});
    CHECK(r.code == 1);
    CHECK(r.out.find("\"" + program + "\",1,2,1,2,1,2.000,0,2.000,\"[too slow] ") != std::string::npos);
  }
  SECTION("test: lines before the first scenario are every scenario's; a scenario's own replace or add to them") {
    // Shared: the cell and input 1 ON at 2 s. "late" adds nothing: the
    // WAITFOR ends at 2 s. "both" adds input 2 ON at 0.5 s to the shared
    // input 1 (still 2 s). "elsewhere" replaces the cell with rhino-scara,
    // whose five motors the program's four-value MOVE does not fit.
    const std::string spec = dir.write("shared.rstest",
                                       "test: cell gantry-cell\ntest: input 1=ON@2\n"
                                       "scenario late\nexpect: time = 2\n"
                                       "scenario both\ntest: input 2=ON@0.5\nexpect: time = 2\nexpect: input 2 on\n"
                                       "scenario elsewhere\ntest: cell rhino-scara\nexpect: finished\n");
    const CliResult r = runCli({"test", "--spec", spec, dir.file("sub"), "--format=json"});
    INFO(r.out);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    REQUIRE(j["tests"].size() == 3);
    CHECK(j["tests"][0]["status"] == "PASSED");
    CHECK(j["tests"][0]["time"] == 2.0);
    CHECK(j["tests"][1]["status"] == "PASSED");
    CHECK(j["tests"][2]["status"] == "FAILED");
    REQUIRE(!j["tests"][2]["problems"].empty());
    CHECK(j["tests"][2]["problems"][0]["file"] == program);  // the program does not compile there
  }
  SECTION("whole and partial points, with decimals; a run that fails keeps what held") {
    const std::string spec = dir.write("points.rstest",
                                       "test: cell gantry-cell\n"
                                       "scenario whole\npoints 2.5\ntest: input 1=ON@2\nexpect: time = 2\n"
                                       "scenario partial\ntest: input 1=ON@2\n"
                                       "expect: time = 2      points 0.25\n"
                                       "expect: motors X=999  points 1.5   ; wrong: X is at 1000\n"
                                       "expect: finished\n");
    const CliResult r = runCli({"test", "--spec", spec, dir.file("sub"), "--format=csv"});
    INFO(r.out);
    // 2.5 + 0.25 of 2.5 + 1.75.
    CHECK(r.out.find("\"" + program + "\",2.75,4.25,1,2,2.5,2.000,0.25,2.000,") != std::string::npos);
  }
}

TEST_CASE("robotsim test: a scenario file's points lines are read and every bad one said", "[testrun][cli]") {
  const TempDir dir;
  const std::string bad = dir.write("bad.rstest",
                                    "points 3\n"                                   // 1: before any scenario
                                    "scenario one\n"
                                    "points x\n"                                   // 3: not a number
                                    "points 1.234\n"                               // 4: three decimals
                                    "scenario two\n"
                                    "points 2\n"                                   // 6
                                    "points 3\n"                                   // 7: twice
                                    "scenario three\n"
                                    "points 1\n"                                   // 9: and per expectation
                                    "expect: finished points 2\n"
                                    "scenario four\n"
                                    "expect: finished points -1\n"                 // 12: col 25
                                    "points 1 2\n");                               // 13: col 10
  const CliResult b = runCli({"test", bad});
  CHECK(b.code == 2);
  const std::string number = "expected points: a number of at most 1000000 with at most two decimals (4, 0.5, 2.25), got ";
  for (const std::string& want :
       {bad + ":1:1: error: 'points N' gives a scenario its points: put it after its 'scenario NAME'\n",
        bad + ":3:8: error: " + number + "'x'\n", bad + ":4:8: error: " + number + "'1.234'\n",
        bad + ":7:1: error: the scenario's points are given twice\n",
        bad + ":9:1: error: scenario 'three' gives its points whole ('points N') and per expectation ('expect: ... "
              "points N') too: keep one\n",
        bad + ":12:25: error: " + number + "'-1'\n", bad + ":13:10: error: expected 'points N' (one number)\n"}) {
    INFO(want);
    CHECK(b.out.find(want) != std::string::npos);
  }
  INFO(b.out);
}

TEST_CASE("robotsim test: a golden trace, written by --update, refused to be written when CI is set", "[testrun][cli]") {
  const TempDir dir;
  const std::string program = dir.write("t.rsp", "; expect: trace t.trace\nSET N 1\nMOVE 100 0 0 0 0\nEND\n");
  const std::string golden = dir.file("t.trace");
  // The golden file is the trace `robotsim run --trace` prints.
  const CliResult traced = runCli({"run", program, "--trace"});
  REQUIRE(traced.code == 0);
  const std::string trace = traced.out.substr(0, traced.out.find("run of "));
  REQUIRE(!trace.empty());

  const CliResult missing = runCli({"test", program});
  CHECK(missing.code == 1);
  CHECK(missing.out.find("error: cannot read the golden trace " + golden) != std::string::npos);
  CHECK(missing.out.find("  hint: robotsim test --update writes it from the run\n") != std::string::npos);

  ::unsetenv("CI");
  const CliResult update = runCli({"test", program, "--update"});
  CHECK(update.code == 0);
  CHECK(update.out.find("  updated " + golden + "\n") != std::string::npos);
  CHECK(rs::testing::readBytes(golden) == trace);
  CHECK(runCli({"test", program}).code == 0);

  // A changed run fails at the first line that differs.
  dir.write("t.rsp", "; expect: trace t.trace\nSET N 2\nMOVE 100 0 0 0 0\nEND\n");
  const CliResult changed = runCli({"test", program});
  CHECK(changed.code == 1);
  CHECK(changed.out.find("the trace differs from " + golden + " at its line 2: expected '") != std::string::npos);
  CHECK(changed.out.find("N=1', got '") != std::string::npos);

  ::setenv("CI", "true", 1);
  const CliResult refused = runCli({"test", program, "--update"});
  ::unsetenv("CI");
  CHECK(refused.code == 2);
  CHECK(refused.err == "robotsim: error: --update refuses to write golden traces when CI is set: a CI run checks them\n");
  CHECK(rs::testing::readBytes(golden) == trace);  // untouched
}

TEST_CASE("robotsim test --coverage of a scenario file lists its program, once over its scenarios", "[testrun][cli]") {
  const TempDir dir;
  // Two scenarios of one program: input 1 on (the JMPIN jumps) and off (it
  // goes on): each line's count is the two runs' sum.
  dir.write("p.rsp",
            "JMPIN 1 ON yes\n"  // 1: twice: jumps once, goes on once
            "END\n"             // 2: once (input off)
            "yes: END\n");      // 3: once (input on)
  const std::string spec = dir.write("s.rstest",
                                     "program p.rsp\n"
                                     "scenario on\ntest: input 1=on@0\nexpect: finished\n"
                                     "scenario off\nexpect: finished\n");
  const CliResult r = runCli({"test", spec, "--coverage"});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("p.rsp: 3 of 3 instruction lines ran, 2 of 2 jump directions taken\n") != std::string::npos);
  CHECK(r.out.find("        2:     1: JMPIN 1 ON yes   [jumped 1, went on 1]\n") != std::string::npos);
  CHECK(r.out.find("coverage of " + spec) == std::string::npos);
  CHECK(r.out.find("coverage of ") == r.out.rfind("coverage of "));  // one listing
}
