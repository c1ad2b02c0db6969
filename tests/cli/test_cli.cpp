// The `robotsim` command, run in-process through rs::cli::runCommand:
// exit codes (0 ok, 1 runtime failure, 2 compile error / bad input / bad
// usage), the JSON summary, diagnostics on stderr. Bad files, options and
// names: test_cli_bad_input.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_programs.h"
#include "tests/cli/cli_support.h"
#include "tools/cli/lib/report.h"
#include "runtime/run/trace.h"
#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "diag/source_file.h"
#include "launch/program.h"
#include "runtime/run/run.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"

namespace {

using nlohmann::json;
using rs::testing::CliResult;
using rs::testing::kBadProgram;
using rs::testing::kGood;
using rs::testing::kRuntimeError;
using rs::testing::parseJson;
using rs::testing::runCli;
using rs::testing::TempDir;

// The documented shape of the --format=json summary.
void checkSummaryShape(const json& j) {
  REQUIRE(j.is_object());
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  std::sort(keys.begin(), keys.end());
  CHECK(keys == std::vector<std::string>{"diagnostics", "inputs", "motors", "outputs", "status", "steps", "time",
                                         "variables"});
  CHECK(j["status"].is_string());
  CHECK((j["status"] == "finished" || j["status"] == "error"));
  CHECK(j["time"].is_number());
  CHECK(j["steps"].is_number_unsigned());
  CHECK(j["motors"].is_object());
  for (const auto& m : j["motors"].items()) CHECK(m.value().is_number_integer());
  REQUIRE(j["outputs"].is_array());
  CHECK(j["outputs"].size() == 8);
  for (const auto& b : j["outputs"]) CHECK(b.is_boolean());
  REQUIRE(j["inputs"].is_array());
  CHECK(j["inputs"].size() == 8);
  for (const auto& b : j["inputs"]) CHECK(b.is_boolean());
  CHECK(j["variables"].is_object());
  for (const auto& v : j["variables"].items()) CHECK(v.value().is_number_integer());
  REQUIRE(j["diagnostics"].is_array());
  for (const auto& d : j["diagnostics"]) {
    REQUIRE(d.is_object());
    // Five fields always; "code" and "hint" when there is one.
    CHECK(d.size() == std::size_t{5} + d.contains("code") + d.contains("hint"));
    if (d.contains("hint")) CHECK(d["hint"].is_string());
    CHECK(d["file"].is_string());
    CHECK(d["line"].is_number_unsigned());
    CHECK(d["column"].is_number_unsigned());
    CHECK((d["severity"] == "error" || d["severity"] == "warning" || d["severity"] == "note"));
    CHECK(d["message"].is_string());
  }
}

}  // namespace

TEST_CASE("cli: exit codes of run", "[cli]") {
  TempDir dir;
  const CliResult ok = runCli({"run", dir.write("good.rsp", kGood)});
  CHECK(ok.code == 0);
  CHECK(ok.err.empty());
  CHECK(runCli({"run", dir.write("rt.rsp", kRuntimeError)}).code == 1);
  CHECK(runCli({"run", dir.write("bad.rsp", kBadProgram)}).code == 2);
  CHECK(runCli({"run", dir.write("dl.rsp", "WAITFOR 1 ON\nEND\n")}).code == 1);
  CHECK(runCli({"run", dir.file("missing.rsp")}).code == 2);
}

TEST_CASE("cli: the text summary of run", "[cli]") {
  TempDir dir;
  const std::string file = dir.write("good.rsp", kGood);
  const CliResult r = runCli({"run", file});
  REQUIRE(r.code == 0);
  CHECK(r.out == "run of " + file +
                     " on rhino-scara: finished\n"
                     "  simulated time  0.750 s\n"
                     "  instructions    12 executed\n"
                     "  motors          E=300  D=0  C=0  B=0  A=0\n"
                     "  outputs         .2......  (ON: 2)\n"
                     "  inputs          ........  (ON: none)\n"
                     "  variables       N=3\n");
}

TEST_CASE("cli: check", "[cli]") {
  TempDir dir;
  const std::string good = dir.write("good.rsp", kGood);
  SECTION("a good program") {
    const CliResult r = runCli({"check", good});
    CHECK(r.code == 0);
    CHECK(r.out == good + ": ok (12 instructions executed, 0.750 s simulated)\n");
    CHECK(r.err.empty());
  }
  SECTION("a program that does not compile") {
    const std::string bad = dir.write("bad.rsp", kBadProgram);
    const CliResult r = runCli({"check", bad});
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err == bad + ":2:6: error: line number 9 does not exist (the program has 2 instructions)\n"
                         "  GOTO 9\n"
                         "       ^\n");
  }
  SECTION("a program that fails at run time") {
    const CliResult r = runCli({"check", dir.write("rt.rsp", kRuntimeError)});
    CHECK(r.code == 1);
    CHECK(r.out.find("runtime error at line 3") != std::string::npos);
  }
  SECTION("warnings pass, unless --strict") {
    const std::string warn = dir.write("warn.rsp", "END\nEND\n");
    const CliResult r = runCli({"check", warn});
    CHECK(r.code == 0);
    CHECK(r.err == warn + ":2:1: warning: unreachable code: nothing jumps here and END on line 1 does not continue\n"
                          "  END\n"
                          "  ^\n");
    // docs/cli.md (options table and exit codes): --strict makes the
    // warning an error, so nothing runs and the exit is 2.
    const CliResult strict = runCli({"check", warn, "--strict"});
    CHECK(strict.code == 2);
    CHECK(strict.err.find(":2:1: error: unreachable code") != std::string::npos);
    CHECK(strict.err.find("[--strict]") != std::string::npos);
  }
  SECTION("stimuli make a WAITFOR pass") {
    const std::string wait = dir.write("wait.rsp", "WAITFOR 3 ON\nEND\n");
    CHECK(runCli({"check", wait}).code == 1);
    CHECK(runCli({"check", wait, "--input", "3=ON@1.5"}).code == 0);
  }
}

TEST_CASE("cli: compile, disasm, tokens, ast, help exit codes", "[cli]") {
  TempDir dir;
  const std::string good = dir.write("good.rsp", kGood);
  const std::string bad = dir.write("bad.rsp", kBadProgram);
  const std::string image = dir.file("good.rsb");
  SECTION("compile") {
    const CliResult r = runCli({"compile", good, "-o", image});
    CHECK(r.code == 0);
    CHECK(r.out == good + " -> " + image + " (6 instructions)\n");
    CHECK(rs::testing::readBytes(image).substr(0, 4) == "\x89RSB");
    // A failed compile writes nothing.
    const std::string none = dir.file("bad.rsb");
    CHECK(runCli({"compile", bad, "-o", none}).code == 2);
    CHECK_FALSE(std::filesystem::exists(none));
    // -o is required; an unwritable output is an error.
    CHECK(runCli({"compile", good}).code == 2);
    const CliResult w = runCli({"compile", good, "-o", dir.file("no/such/dir/x.rsb")});
    CHECK(w.code == 2);
    CHECK(w.err == dir.file("no/such/dir/x.rsb") + ": error: cannot write: cannot create a temporary file in " +
                       dir.file("no/such/dir") + ": No such file or directory\n");
  }
  SECTION("disasm") {
    CHECK(runCli({"disasm", good}).code == 0);
    CHECK(runCli({"disasm", bad}).code == 2);
    REQUIRE(runCli({"compile", good, "-o", image}).code == 0);
    CHECK(runCli({"disasm", image}).out == runCli({"disasm", good}).out);
  }
  SECTION("tokens and ast") {
    CHECK(runCli({"tokens", good}).code == 0);
    CHECK(runCli({"ast", good}).code == 0);
    CHECK(runCli({"ast", good, "--tree"}).code == 0);
    const std::string lexBad = dir.write("lex.rsp", "END @\n");
    CHECK(runCli({"tokens", lexBad}).code == 2);
    CHECK(runCli({"ast", lexBad}).code == 2);
    // Operand counts follow --cell's robot: the gantry has four motors, the default robot five.
    const std::string four = dir.write("four.rsp", "MOVE 1 2 3 4\nEND\n");
    CHECK(runCli({"ast", four, "--cell", "gantry-cell"}).code == 0);
    const CliResult five = runCli({"ast", four});
    CHECK(five.code == 2);
    CHECK(five.err.find("four.rsp:1:1: error: MOVE expects 5 values (one per motor: E D C B A), found 4") !=
          std::string::npos);
    const CliResult noCell = runCli({"ast", four, "--cell", "no-such-cell"});
    CHECK(noCell.code == 2);
    CHECK(noCell.err.find("no-such-cell") != std::string::npos);
    REQUIRE(runCli({"compile", good, "-o", image}).code == 0);
    const CliResult t = runCli({"tokens", image});
    CHECK(t.code == 2);
    CHECK(t.err == image + ": error: this is a compiled image; try robotsim disasm\n");
  }
  SECTION("usage errors") {
    CHECK(runCli({}).code == 2);
    CHECK(runCli({"frobnicate"}).code == 2);
    CHECK(runCli({"run"}).code == 2);
    CHECK(runCli({"run", good, "--format=xml"}).code == 2);
    const CliResult t = runCli({"run", good, "--trace=xml"});
    CHECK(t.code == 2);
    CHECK(t.err == "robotsim: error: --trace takes text or json, not 'xml'\n");
    CHECK(runCli({"--help"}).code == 0);
  }
}

TEST_CASE("cli: help", "[cli]") {
  const CliResult all = runCli({"help"});
  CHECK(all.code == 0);
  for (const char* op : {"MOVE ", "MOVETO ", "MOVEP ", "GOTO ", "JMPIN ", "OUTSIG ", "JMPVAR ", "GOSUB ", "RETURN ",
                         "WAITFOR ", "ADD ", "RESET ", "WINDOW ", "VIEW ", "DELAY ", "HRDHOME ", "SETSOFT ", "GOSOFT ",
                         "SET ", "END "})
    CHECK(all.out.find(std::string("\n  ") + op) != std::string::npos);

  const CliResult jmpvar = runCli({"help", "JMPVAR"});
  CHECK(jmpvar.code == 0);
  CHECK(jmpvar.out ==
        "JMPVAR <variable> <|>|= <value> <line>\n"
        "  jump if a variable compares true with a value.\n"
        "  Variables are 32-bit integers that start at 0; compares with <, > or =.\n"
        "Example:\n"
        "  JMPVAR N < 10 loop\n");
  CHECK(runCli({"help", "jmpvar"}).out == jmpvar.out);

  const CliResult nope = runCli({"help", "NOPE"});
  CHECK(nope.code == 2);
  CHECK(nope.out.empty());
  CHECK(nope.err == "robotsim: error: no instruction named 'NOPE'; did you mean 'MOVE'? (robotsim help lists them)\n");
}

TEST_CASE("cli: --format=json summary", "[cli]") {
  TempDir dir;
  SECTION("a good run") {
    const CliResult r = runCli({"run", dir.write("good.rsp", kGood), "--format=json"});
    CHECK(r.code == 0);
    const json j = parseJson(r.out);
    checkSummaryShape(j);
    // Keys in the documented order (ordered_json keeps the file's order).
    std::vector<std::string> order;
    const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(r.out);
    for (auto it = ordered.begin(); it != ordered.end(); ++it) order.push_back(it.key());
    CHECK(order == std::vector<std::string>{"status", "time", "steps", "motors", "outputs", "inputs", "variables",
                                            "diagnostics"});
    CHECK(j["status"] == "finished");
    CHECK(j["time"].get<double>() == Approx(0.75));
    CHECK(j["steps"] == 12);
    CHECK(j["motors"] == json::parse(R"({"E":300,"D":0,"C":0,"B":0,"A":0})"));
    CHECK(j["outputs"] == json::parse("[false,true,false,false,false,false,false,false]"));
    CHECK(j["inputs"] == json::parse("[false,false,false,false,false,false,false,false]"));
    CHECK(j["variables"] == json::parse(R"({"N":3})"));
    CHECK(j["diagnostics"].empty());
    CHECK(r.out.back() == '\n');
  }
  SECTION("inputs from stimuli, warnings keep status ok") {
    const std::string f = dir.write("w.rsp", "WAITFOR 3 ON\nEND\nEND\n");
    const CliResult r = runCli({"check", f, "--format=json", "--input", "3=ON@1.5"});
    CHECK(r.code == 0);
    const json j = parseJson(r.out);
    checkSummaryShape(j);
    CHECK(j["status"] == "finished");
    CHECK(j["time"].get<double>() == Approx(1.5));
    CHECK(j["inputs"][2] == true);
    REQUIRE(j["diagnostics"].size() == 1);
    CHECK(j["diagnostics"][0] == json{{"file", f},
                                      {"line", 3},
                                      {"column", 1},
                                      {"severity", "warning"},
                                      {"message", "unreachable code: nothing jumps here and END on line 2 does not continue"}, {"code", "unreachable-code"}});
  }
  SECTION("a runtime error carries the line and column of the instruction") {
    const std::string f = dir.write("rt.rsp", kRuntimeError);
    const CliResult r = runCli({"run", f, "--format=json"});
    CHECK(r.code == 1);
    const json j = parseJson(r.out);
    checkSummaryShape(j);
    CHECK(j["status"] == "error");
    CHECK(j["steps"] == 3);
    CHECK(j["motors"]["E"] == 600);
    CHECK(j["variables"] == json::parse(R"({"N":1})"));
    REQUIRE(j["diagnostics"].size() == 1);
    CHECK(j["diagnostics"][0] ==
          json{{"file", f},
               {"line", 3},
               {"column", 3},
               {"severity", "error"},
               {"code", "runtime-error"},
               {"message", "runtime error: MOVE takes motor E to 1200, outside its range -1000..1000 (instruction 3)"}});
    CHECK(r.err == f + ":3:3: error: runtime error: MOVE takes motor E to 1200, outside its range -1000..1000 "
                       "(instruction 3)\n"
                       "    MOVE 600 0 0 0 0\n"
                       "    ^\n");
  }
  SECTION("a deadlock") {
    const std::string f = dir.write("dl.rsp", "SET N 1\nWAITFOR 2 ON\nEND\n");
    const CliResult r = runCli({"check", f, "--format=json"});
    CHECK(r.code == 1);
    const json j = parseJson(r.out);
    checkSummaryShape(j);
    REQUIRE(j["diagnostics"].size() == 1);
    CHECK(j["diagnostics"][0]["line"] == 2);
    CHECK(j["diagnostics"][0]["column"] == 1);
    CHECK(j["diagnostics"][0]["message"] ==
          "deadlock: input 2 never turns ON: no stimulus is scheduled (instruction 2)");
    CHECK(j["diagnostics"][0]["hint"] == "inputs change only by --input N=ON@SECONDS or a --stimuli file");
  }
  SECTION("a compile error") {
    const std::string f = dir.write("bad.rsp", kBadProgram);
    const CliResult r = runCli({"run", f, "--format=json"});
    CHECK(r.code == 2);
    const json j = parseJson(r.out);
    CHECK(j["status"] == "error");
    CHECK(j["steps"] == 0);
    REQUIRE(j["diagnostics"].size() == 1);
    CHECK(j["diagnostics"][0] == json{{"file", f},
                                      {"line", 2},
                                      {"column", 6},
                                      {"severity", "error"},
                                      {"message", "line number 9 does not exist (the program has 2 instructions)"}, {"code", "undefined-line-number"}});
  }
}

// docs/cli.md: "When nothing ran, time and steps are 0, motors and
// variables are {} and outputs and inputs are []".
TEST_CASE("cli: the JSON summary when nothing ran", "[cli]") {
  TempDir dir;
  const std::string f = dir.write("bad.rsp", "END\nOUTSIG 9 ON\n");
  const CliResult r = runCli({"run", f, "--format=json"});
  CHECK(r.code == 2);
  CHECK(r.out == "{\"status\":\"error\",\"time\":0,\"steps\":0,\"motors\":{},\"outputs\":[],\"inputs\":[],"
                 "\"variables\":{},\"diagnostics\":[{\"file\":\"" + f +
                 "\",\"line\":2,\"column\":8,\"severity\":\"error\",\"message\":\"output 9 is outside 1..8\",\"code\":\"io-out-of-range\"}]}\n");
  // A rejected image: a diagnostic without a position has line and column 0.
  const CliResult img = runCli({"check", dir.write("bad.rsb", "\x89RSB\r\n\x1A\n\x01\x00"), "--format=json"});
  CHECK(img.code == 2);
  const json j = parseJson(img.out);
  REQUIRE(j["diagnostics"].size() == 1);
  CHECK(j["diagnostics"][0]["line"] == 0);
  CHECK(j["diagnostics"][0]["column"] == 0);
  CHECK(j["diagnostics"][0]["message"] == "truncated image header");
}

TEST_CASE("cli: a run that stops early says in a hint how to get past it", "[cli][hints]") {
  TempDir dir;
  SECTION("running on into a subroutine: the missing END") {
    const std::string f = dir.write("sub.rsp",
                                    "GOSUB sub\n"            // 1
                                    "MOVE 10 0 0 0 0\n"      // 2: no END after it
                                    "sub: MOVE 5 0 0 0 0\n"  // 3
                                    "RETURN\n");             // 4: the second time, nothing to return to
    const CliResult r = runCli({"run", f});
    CHECK(r.code == 1);
    CHECK(r.err == f + ":4:1: error: runtime error: RETURN without a GOSUB (instruction 4)\n"
                       "  RETURN\n"
                       "  ^\n"
                       "  hint: did the program run on into a subroutine? an END before the subroutine stops it "
                       "there\n");
  }
  const std::string loop = dir.write("loop.rsp", "loop: DELAY 1\nGOTO loop\n");
  SECTION("the step limit names --max-steps") {
    const CliResult r = runCli({"run", loop, "--max-steps", "10"});
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::EndsWith("\n  hint: allow more with --max-steps N\n"));
    const json j = parseJson(runCli({"run", loop, "--max-steps", "10", "--format=json"}).out);
    CHECK(j["diagnostics"][0]["hint"] == "allow more with --max-steps N");
  }
  SECTION("the time limit names --max-time") {
    const CliResult r = runCli({"run", loop, "--max-time", "2.5"});
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::EndsWith("\n  hint: allow more with --max-time SECONDS\n"));
  }
  SECTION("a deadlock names --input and --stimuli") {
    const std::string f = dir.write("dl.rsp", "WAITFOR 2 ON\nEND\n");
    const CliResult r = runCli({"run", f});
    CHECK(r.code == 1);
    CHECK(r.err == f + ":1:1: error: deadlock: input 2 never turns ON: no stimulus is scheduled (instruction 1)\n"
                       "  WAITFOR 2 ON\n"
                       "  ^\n"
                       "  hint: inputs change only by --input N=ON@SECONDS or a --stimuli file\n");
    // With the input given, the same program finishes.
    CHECK(runCli({"run", f, "--input", "2=ON@1"}).code == 0);
  }
}
