// The `robotsim` command on bad input, run in-process: unreadable and
// unsuitable files, bad options and stimuli, limits, file names and names
// in images that are not safe to print. Each gives a clean message and
// exit 2 (or a clean run), never a crash or raw control characters.
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
#include "tests/vm/image_support.h"
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
using rs::testing::cleanText;
using rs::testing::CliResult;
using rs::testing::kGood;
using rs::testing::kRuntimeError;
using rs::testing::parseJson;
using rs::testing::runCli;
using rs::testing::TempDir;

}  // namespace

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
    CHECK(a.err ==
          "--max-time: error: bad time 'abc': expected seconds such as 2 or 1.5\n"
          "  hint: a time is seconds with at most 6 decimals, from 0 to 1000000\n");
    const CliResult n = runCli({"run", loop, "--max-time", "-1"});
    CHECK(n.code == 2);
    CHECK(n.err.starts_with("--max-time: error: time must not be negative, got '-1'\n  hint: "));
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
        forge("label.rsb", "v.rsp", program, [&](rs::vm::Image& im) { rs::testing::setLabelName(im, 0, hostile); });
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
  cell->objects[0].name = "tray\x1b[1m";  // its AS name
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
  rs::runtime::TraceWriter textWriter(text, rs::runtime::TraceFormat::Text, run);
  rs::runtime::TraceWriter jsonWriter(jsonTrace, rs::runtime::TraceFormat::Json, run);
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
  CHECK(summary.str().find(" block\\x1b[31m AS tray\\x1b[1m at ") != std::string::npos);
  CHECK(summary.str().find("variables       N\\x1b[2J=1\n") != std::string::npos);
}
