// The `robotsim` command, run in-process through rs::cli::runCommand:
// exit codes (0 ok, 1 runtime failure, 2 compile error / bad input / bad
// usage), the JSON summary, diagnostics on stderr, bad files and options.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "cli/lib/report.h"
#include "cli/lib/trace.h"
#include "compiler/compiler.h"
#include "compiler/library.h"
#include "diag/source_file.h"
#include "launch/program.h"
#include "runtime/run/run.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"

namespace {

using nlohmann::json;
using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

constexpr const char* kGood =
    "; a good program\n"
    "SET N 0\n"
    "loop: ADD N 1\n"
    "MOVE 100 0 0 0 0\n"
    "JMPVAR N < 3 loop\n"
    "OUTSIG 2 ON\n"
    "END\n";
// Six instructions. Final state: E=300 after three 0.25 s moves, N=3,
// output 2 ON, 1 + 3 * 3 + 2 = 12 instructions executed.

constexpr const char* kRuntimeError =
    "SET N 1\n"
    "  MOVE 600 0 0 0 0\n"
    "  MOVE 600 0 0 0 0\n"
    "END\n";

constexpr const char* kBadProgram = "END\nGOTO 9\n";

// True if `s` is valid UTF-8 and has no control characters except newline
// and tab: safe to print on a terminal.
bool cleanText(const std::string& s) {
  if (rs::diag::findInvalidUtf8(s).found) return false;
  for (char c : s)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7F) return false;
  return true;
}

json parseJson(const std::string& text) {
  INFO(text);
  REQUIRE(json::accept(text));
  return json::parse(text);
}

// The documented shape of the --format=json summary.
void checkSummaryShape(const json& j) {
  REQUIRE(j.is_object());
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  std::sort(keys.begin(), keys.end());
  CHECK(keys == std::vector<std::string>{"diagnostics", "inputs", "motors", "outputs", "status", "steps", "time",
                                         "variables"});
  CHECK(j["status"].is_string());
  CHECK((j["status"] == "ok" || j["status"] == "error"));
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
    CHECK(w.err == dir.file("no/such/dir/x.rsb") + ": error: cannot write: No such file or directory\n");
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
  CHECK(nope.err == "robotsim: error: no instruction named 'NOPE' (robotsim help lists them)\n");
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
    CHECK(j["status"] == "ok");
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
    CHECK(j["status"] == "ok");
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

TEST_CASE("cli: unreadable and unsuitable files give a clean error and exit 2", "[cli]") {
  TempDir dir;
  const std::string good = dir.write("good.rsp", kGood);
  SECTION("missing") {
    const CliResult r = runCli({"run", dir.file("missing.rsp")});
    CHECK(r.code == 2);
    CHECK(r.err == dir.file("missing.rsp") + ": error: cannot read file: No such file or directory\n");
  }
  SECTION("not readable (a path through a regular file)") {
    const CliResult r = runCli({"check", good + "/x.rsp"});
    CHECK(r.code == 2);
    CHECK(r.err == good + "/x.rsp: error: cannot read file: Not a directory\n");
  }
  SECTION("a directory") {
    for (const char* cmd : {"run", "check", "disasm", "compile"}) {
      std::vector<std::string> args{cmd, dir.path().string()};
      if (std::string(cmd) == "compile") args.insert(args.end(), {"-o", dir.file("x.rsb")});
      const CliResult r = runCli(args);
      INFO(cmd);
      CHECK(r.code == 2);
      CHECK(r.err == dir.path().string() + ": error: cannot read file: is a directory\n");
    }
    const CliResult t = runCli({"tokens", dir.path().string()});
    CHECK(t.code == 2);
    CHECK(t.err == dir.path().string() + ": error: cannot read file: is a directory\n");
  }
  SECTION("empty") {
    const std::string f = dir.write("empty.rsp", "");
    const CliResult r = runCli({"run", f});
    CHECK(r.code == 2);
    CHECK(r.err.rfind(f + ":1:1: error: the program has no instructions\n", 0) == 0);
  }
  SECTION("invalid UTF-8") {
    const std::string f = dir.write("latin1.rsp", "END ; caf\xE9\n");
    const CliResult r = runCli({"check", f});
    CHECK(r.code == 2);
    CHECK(r.err.rfind(f + ":1:10: error: invalid UTF-8 (byte 0xE9): programs are UTF-8 text\n", 0) == 0);
  }
  SECTION("a corrupt image") {
    REQUIRE(runCli({"compile", good, "-o", dir.file("good.rsb")}).code == 0);
    std::string bytes = rs::testing::readBytes(dir.file("good.rsb"));
    bytes[bytes.size() - 1] ^= 0x40;
    const std::string f = dir.write("corrupt.rsb", bytes);
    for (const char* cmd : {"run", "check", "disasm"}) {
      const CliResult r = runCli({cmd, f});
      INFO(cmd);
      CHECK(r.code == 2);
      CHECK(r.err == f + ": error: image checksum mismatch (the file is corrupt)\n");
    }
  }
}

// Regression (a bug these tests found, fixed since): a binary file is reported as invalid UTF-8 (good), but the
// diagnostic then prints the offending "source line" verbatim: raw binary
// bytes, including terminal control characters, go to stderr.
TEST_CASE("cli: a 5 MB binary file gives a clean, printable error", "[cli]") {
  TempDir dir;
  std::mt19937 rng(12345);  // fixed seed: the same bytes every run
  std::string bytes(5u << 20, '\0');
  for (char& c : bytes) c = static_cast<char>(rng() & 0xFF);
  REQUIRE(bytes.substr(0, 4) != "\x89RSB");
  const std::string f = dir.write("random.bin", bytes);
  for (const char* cmd : {"run", "check", "disasm", "tokens", "ast"}) {
    const CliResult r = runCli({cmd, f});
    INFO(cmd);
    CHECK(r.code == 2);
    CHECK(r.err.rfind(f + ":", 0) == 0);
    CHECK(r.err.find("invalid UTF-8") != std::string::npos);
    CHECK(cleanText(r.err));
  }
}

TEST_CASE("cli: --input errors", "[cli]") {
  TempDir dir;
  const std::string good = dir.write("good.rsp", kGood);
  struct Case {
    const char* arg;
    const char* first;  // the first line of stderr
  };
  const Case cases[] = {
      {"9=ON", "--input:1:1: error: input number must be 1..8, got 9"},
      {"1=MAYBE@2", "--input:1:3: error: expected ON or OFF after '=', got 'MAYBE'"},
      {"1=ON@x", "--input:1:6: error: bad time 'x': expected seconds such as 2 or 1.5"},
      {"ON", "--input:1:3: error: expected '=' after the input number (the form is N=ON@T or N=OFF@T, e.g. 3=ON@1.5)"},
  };
  for (const Case& c : cases) {
    INFO(c.arg);
    const CliResult r = runCli({"run", good, "--input", c.arg});
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.substr(0, r.err.find('\n')) == c.first);
  }
}

// Regression (a bug these tests found, fixed since): errors in --input and in a --stimuli file are rendered
// with the PROGRAM's source line (same line number) and a caret under it,
// as if the error were in the program.
TEST_CASE("cli: stimulus errors are not shown against the program's source", "[cli]") {
  TempDir dir;
  const std::string good = dir.write("good.rsp", kGood);
  const CliResult input = runCli({"run", good, "--input", "9=ON"});
  CHECK(input.code == 2);
  CHECK(input.err.find("; a good program") == std::string::npos);

  const std::string stim = dir.write("bad.stim", "at x input 1 on\nwhen output 1 on then input 9 on\n");
  const CliResult file = runCli({"run", good, "--stimuli", stim});
  CHECK(file.code == 2);
  CHECK(file.err.find(stim + ":1:4: error: bad time 'x': expected seconds such as 2 or 1.5\n") != std::string::npos);
  CHECK(file.err.find(stim + ":2:29: error: input number must be 1..8, got 9\n") != std::string::npos);
  CHECK(file.err.find("; a good program") == std::string::npos);
  CHECK(file.err.find("SET N 0") == std::string::npos);
}

TEST_CASE("cli: a stimuli file drives WAITFOR through a reactive rule", "[cli]") {
  TempDir dir;
  const std::string prog = dir.write("hs.rsp", "OUTSIG 1 ON\nWAITFOR 2 ON\nOUTSIG 1 OFF\nWAITFOR 2 OFF\nEND\n");
  const std::string stim =
      dir.write("hs.stim", "when output 1 on then input 2 on after 0.5\nwhen output 1 off then input 2 off after 0.25\n");
  const CliResult r = runCli({"run", prog, "--format=json", "--stimuli", stim});
  CHECK(r.code == 0);
  const json j = parseJson(r.out);
  CHECK(j["time"].get<double>() == Approx(0.75));
  CHECK(j["inputs"][1] == false);
  CHECK(runCli({"run", prog, "--stimuli", dir.file("missing.stim")}).code == 2);
}

TEST_CASE("cli: --max-steps and --max-time", "[cli]") {
  TempDir dir;
  const std::string loop = dir.write("loop.rsp", "loop: DELAY 1\nGOTO loop\n");
  SECTION("limits stop a run with a clear error and exit 1") {
    const CliResult s = runCli({"run", loop, "--max-steps", "10"});
    CHECK(s.code == 1);
    CHECK(s.err.rfind(loop + ":1:7: error: step limit: step limit of 10 instructions reached (instruction 1)\n", 0) == 0);
    const CliResult t = runCli({"run", loop, "--max-time", "2.5"});
    CHECK(t.code == 1);
    CHECK(t.err.rfind(loop + ":1:7: error: time limit: simulated time limit of 2.500 s passed (clock at 3.000 s) "
                              "(instruction 1)\n",
                      0) == 0);
  }
  SECTION("bad values are usage errors") {
    const CliResult a = runCli({"run", loop, "--max-time", "abc"});
    CHECK(a.code == 2);
    CHECK(a.err == "--max-time: error: bad time 'abc': expected seconds such as 2 or 1.5\n");
    const CliResult n = runCli({"run", loop, "--max-time", "-1"});
    CHECK(n.code == 2);
    CHECK(n.err == "--max-time: error: time must not be negative, got '-1'\n");
    CHECK(runCli({"run", loop, "--max-steps", "x"}).code == 2);
    CHECK(runCli({"run", loop, "--max-steps", "1.5"}).code == 2);
    CHECK(runCli({"run", loop, "--max-steps"}).code == 2);
  }
}

// Regression (a bug these tests found, fixed since): "--max-steps -1" is accepted and wraps to 2^64-1, so the
// step limit is silently switched off (an endless loop then runs forever).
// A program that ends is used here so that the test cannot hang.
TEST_CASE("cli: a negative --max-steps is a usage error", "[cli]") {
  TempDir dir;
  const std::string f = dir.write("end.rsp", "END\n");
  CHECK(runCli({"run", f, "--max-steps", "-1"}).code == 2);
  CHECK(runCli({"check", f, "--max-steps", "-5"}).code == 2);
}

// Regression (a bug these tests found, fixed since): file names are not always UTF-8 (Linux allows any bytes), and
// the source name stored in an image is cut at 255 bytes, possibly inside a
// UTF-8 sequence. --format=json then puts the raw name into "file" and
// nlohmann::json::dump throws type_error 316: the robotsim process aborts
// (exit 134). Reproduction: robotsim run $'\xff.rsp' --format=json
TEST_CASE("cli: --format=json survives file names that are not UTF-8", "[cli]") {
  TempDir dir;
  CliResult r;
  SECTION("a missing file") {
    REQUIRE_NOTHROW(r = runCli({"run", dir.file("\xFF.rsp"), "--format=json"}));
    CHECK(r.code == 2);
    CHECK(json::accept(r.out));
  }
  SECTION("a program with a warning") {
    const std::string f = dir.write("\xFD.rsp", "END\nEND\n");
    REQUIRE_NOTHROW(r = runCli({"check", f, "--format=json"}));
    CHECK(r.code == 0);
    CHECK(json::accept(r.out));
  }
  SECTION("an image whose 255-byte source name ends inside a UTF-8 sequence") {
    // 254 ASCII bytes, then the two bytes of an e-acute: the cut keeps 0xC3.
    const std::string name = std::string(254, 'a') + "\xC3\xA9.rsp";
    const rs::compiler::CompileResult compiled = rs::compiler::compile(
        rs::diag::SourceFile(name, "MOVE 0 0 0 0 -1\n"),
        {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth});
    REQUIRE(compiled.ok());
    const std::vector<std::uint8_t> bytes = rs::vm::writeImage(*compiled.image);
    const std::string image = dir.write("cut.rsb", std::string(bytes.begin(), bytes.end()));
    REQUIRE_NOTHROW(r = runCli({"run", image, "--format=json"}));
    CHECK(r.code == 1);
    CHECK(json::accept(r.out));
  }
}

TEST_CASE("cli: an unknown command is named, with the nearest one and the list", "[cli]") {
  const CliResult typo = runCli({"chekc", "prog.rsp"});
  CHECK(typo.code == 2);
  CHECK(typo.out.empty());
  CHECK(typo.err.rfind("robotsim: error: unknown command 'chekc' (did you mean 'check'?)\n", 0) == 0);
  CHECK(typo.err.find("  commands: run, check, compile,") != std::string::npos);
  const CliResult far = runCli({"frobnicate"});
  CHECK(far.code == 2);
  CHECK(far.err.rfind("robotsim: error: unknown command 'frobnicate'\n", 0) == 0);
  // What a user typed is shown with its control bytes escaped.
  const CliResult control = runCli({"\x1b]0;x\x07"});
  CHECK(control.err.rfind("robotsim: error: unknown command '\\x1b]0;x\\x07'\n", 0) == 0);
  // Options before the command and real commands are CLI11's to parse.
  CHECK(runCli({"--help"}).code == 0);
  CHECK(runCli({"run"}).err.find("unknown command") == std::string::npos);
}

TEST_CASE("cli: a text file named .rsb is compiled as source, with a note that says so", "[cli]") {
  TempDir dir;
  const std::string f = dir.write("prog.rsb", "SET N 1\nEND\n");
  const CliResult r = runCli({"check", f});
  CHECK(r.code == 0);
  CHECK(r.err == f + ": note: this is not a compiled image (it does not start with the image magic number); "
                     "compiling it as source\n");
  // The same text named .rsp gets no note.
  CHECK(runCli({"check", dir.write("prog.rsp", "SET N 1\nEND\n")}).err.empty());
}

TEST_CASE("cli: a byte-order mark is ignored, a lone carriage return refused where it is", "[cli]") {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  const std::string prog = dir.write("bom.rsp", bom + "SET N 1\nWAITFOR 1 ON\nEND\n");
  const std::string stim = dir.write("bom.stim", bom + "at 1 input 1 on\n");
  const CliResult r = runCli({"check", prog, "--stimuli", stim});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  const std::string robot = dir.write("bom.rsd", bom + "ROBOT x\n");
  const CliResult d = runCli({"table", robot});
  CHECK(d.err.rfind(robot + ":1:1: error: ROBOT has no END", 0) == 0);  // not "unexpected character"

  const std::string mac = dir.write("mac.rsp", "SET N 1\rEND\r");
  const CliResult m = runCli({"check", mac});
  CHECK(m.code == 2);
  CHECK(m.err.rfind(mac + ":1:8: error: a carriage return without a line feed (old Mac line ends?): lines end in "
                          "LF or CR LF\n",
                    0) == 0);
  CHECK(m.err.find("  hint: save the file with Unix (LF) or Windows (CR LF) line ends\n") != std::string::npos);
  CHECK(runCli({"check", dir.write("dos.rsp", "SET N 1\r\nEND\r\n")}).code == 0);
}

// A forged image (any bytes, a valid checksum) must not send control
// characters to the terminal: its source name is kept and printed escaped,
// names the compiler could never write are refused with a message that does
// not quote them.
TEST_CASE("cli: names from a forged image never reach the terminal raw", "[cli]") {
  TempDir dir;
  const std::string hostile = "\x1b]0;pwned\x07";
  const std::string shown = "\\x1b]0;pwned\\x07";
  const auto forge = [&](const std::string& file, const std::string& sourceName, const std::string& text,
                         const auto& change) {
    const rs::compiler::CompileResult compiled = rs::compiler::compile(
        rs::diag::SourceFile(sourceName, text),
        {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth});
    REQUIRE(compiled.ok());
    rs::vm::Image im = *compiled.image;
    change(im);
    const std::vector<std::uint8_t> bytes = rs::vm::writeImage(im);
    return dir.write(file, std::string(bytes.begin(), bytes.end()));
  };
  const auto unchanged = [](rs::vm::Image&) {};
  const std::vector<std::vector<std::string>> commands = {
      {"run"}, {"run", "--trace"}, {"run", "--trace=json"}, {"run", "--format=json"}, {"check"}, {"disasm"}};
  const auto each = [&](const std::string& image, const auto& check) {
    for (std::vector<std::string> args : commands) {
      args.insert(args.begin() + 1, image);
      INFO(args[0] << " " << (args.size() > 2 ? args[2] : ""));
      const CliResult r = runCli(args);
      INFO(r.out << r.err);
      CHECK(cleanText(r.out));
      CHECK(cleanText(r.err));
      check(args, r);
    }
  };
  SECTION("an ESC and a BEL in the source name") {
    const std::string good = forge("good.rsb", hostile + ".rsp", kGood, unchanged);
    each(good, [&](const std::vector<std::string>& args, const CliResult& r) {
      CHECK(r.code == 0);
      if (args.size() == 2 && args[0] == "run")
        CHECK(r.out.rfind("run of " + shown + ".rsp on rhino-scara: finished\n", 0) == 0);
      if (args[0] == "check") CHECK(r.out.rfind(shown + ".rsp: ok (12 instructions executed", 0) == 0);
      if (args[0] == "disasm") CHECK(r.out.rfind("; " + shown + ".rsp (6 instructions", 0) == 0);
    });
    // A runtime error is reported against the source name.
    const std::string failing = forge("failing.rsb", hostile + ".rsp", kRuntimeError, unchanged);
    each(failing, [&](const std::vector<std::string>& args, const CliResult& r) {
      if (args[0] == "disasm") return;
      CHECK(r.code == 1);
      if (args.size() == 2 && args[0] == "run") CHECK(r.err.rfind(shown + ".rsp:3:3: error: runtime error: ", 0) == 0);
      if (args.size() == 3 && args[2] == "--format=json") {
        const json j = parseJson(r.out);
        REQUIRE(j["diagnostics"].size() == 1);
        CHECK(j["diagnostics"][0]["file"] == hostile + ".rsp");  // JSON escapes it itself
      }
    });
  }
  SECTION("an ESC or a BEL in a variable, label or point name is refused, not quoted") {
    const std::string program = "top: SET N 1\nMOVEP P\nEND\nPOINTS\nP 0 0 0 0 0\n";
    const std::string variable =
        forge("variable.rsb", "v.rsp", program, [&](rs::vm::Image& im) { im.variables[0] = "N" + hostile; });
    const std::string label =
        forge("label.rsb", "v.rsp", program, [&](rs::vm::Image& im) { im.labels[0].name = hostile; });
    const std::string point =
        forge("point.rsb", "v.rsp", program, [&](rs::vm::Image& im) { im.points[0].name = "P\x1b[2J"; });
    const std::string robot =
        forge("robot.rsb", "v.rsp", program, [&](rs::vm::Image& im) { im.robotName = "rhino" + hostile; });
    const std::pair<std::string, std::string> cases[] = {
        {variable, "malformed image: variable 1 has a bad name"},
        {label, "malformed image: label 1 has a bad name"},
        {point, "malformed image: point 1 has a bad name"},
        {robot, "malformed image: the robot name holds a control character"}};
    for (const auto& [image, message] : cases) {
      const std::string expected = image + ": error: " + message + "\n";
      each(image, [&](const std::vector<std::string>& args, const CliResult& r) {
        CHECK(r.code == 2);
        if (args.size() == 2) CHECK(r.err == expected);
      });
    }
  }
}

// The trace and the summary print names through base::safeText even for an
// image and a workcell that never passed the loader (built in memory here).
TEST_CASE("cli: the trace and the summary escape every name", "[cli]") {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> cell = library.workcell("scara-pick");
  REQUIRE(cell);
  REQUIRE(!cell->objects.empty());
  cell->objects[0].shape.name = "block\x1b[31m";
  const rs::compiler::CompileResult compiled =
      rs::compiler::compile(rs::diag::SourceFile("p.rsp", "SET N 1\nEND\n"), rs::launch::cellTarget(*cell));
  REQUIRE(compiled.ok());
  auto image = std::make_shared<rs::vm::Image>(*compiled.image);
  image->sourceName = "\x1b]0;pwned\x07.rsp";
  image->robotName = "robot\x07";
  image->variables[0] = "N\x1b[2J";
  rs::runtime::RunSpec spec;
  spec.image = image;
  spec.cell = std::make_shared<const rs::workcell::Workcell>(*cell);
  rs::runtime::Run run(std::move(spec));
  std::ostringstream text, jsonTrace, summary;
  rs::cli::TraceWriter textWriter(text, rs::cli::TraceFormat::Text, run);
  rs::cli::TraceWriter jsonWriter(jsonTrace, rs::cli::TraceFormat::Json, run);
  run.observe(textWriter);
  run.observe(jsonWriter);
  REQUIRE(run.runToEnd().ok());
  rs::cli::RunReport report;
  report.run = &run;
  rs::cli::printTextSummary(summary, report);
  INFO(text.str() << jsonTrace.str() << summary.str());
  CHECK(cleanText(text.str()));
  CHECK(cleanText(jsonTrace.str()));
  CHECK(cleanText(summary.str()));
  CHECK(text.str().find("SET     N\\x1b[2J 1") != std::string::npos);
  CHECK(text.str().find("N\\x1b[2J=1") != std::string::npos);
  CHECK(summary.str().rfind("run of \\x1b]0;pwned\\x07.rsp on robot\\x07: finished\n", 0) == 0);
  CHECK(summary.str().find(" block\\x1b[31m at ") != std::string::npos);
  CHECK(summary.str().find("variables       N\\x1b[2J=1\n") != std::string::npos);
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
