// Determinism: the same image and the same stimuli give byte-identical
// output, run after run; compiling twice gives the same bytes; running the
// compiled image gives the same trace as running the source.
#include <catch2/catch.hpp>
#include <regex>

#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "compiler/program/compiler.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

// A pick-and-place loop with a handshake: OUTSIG asks the conveyor, a
// reactive rule answers on input 2, a timed stimulus on input 4 ends the
// loop early through JMPIN.
constexpr const char* kDeterminismProgram =
    "; pick and place with a handshake\n"
    "start: SET COUNT 0\n"
    "loop: MOVEP PICK\n"
    "  MOVETO 100 200 -100 0 120\n"
    "  OUTSIG 1 ON            ; ask the conveyor\n"
    "  WAITFOR 2 ON           ; a part is there\n"
    "  GOSUB place\n"
    "  OUTSIG 1 OFF\n"
    "  WAITFOR 2 OFF\n"
    "  ADD COUNT 1\n"
    "  JMPIN 4 ON done\n"
    "  JMPVAR COUNT < 5 loop\n"
    "done: HRDHOME\n"
    "  END\n"
    "place: MOVEP PLACE\n"
    "  DELAY 0.125\n"
    "  MOVE 0 0 50 0 -120\n"
    "  RETURN\n"
    "POINTS\n"
    "PICK 500 -200 -300 100 0\n"
    "PLACE -500 300 -300 -100 120\n";

constexpr const char* kStimuli =
    "when output 1 on then input 2 on after 0.5\n"
    "when output 1 off then input 2 off after 0.25\n"
    "at 9.5 input 4 on\n";

std::size_t countLines(const std::string& s, char first) {
  std::size_t n = 0;
  std::istringstream in(s);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] == first) ++n;
  return n;
}

}  // namespace

TEST_CASE("the same run twice gives byte-identical traces", "[vm][determinism]") {
  TempDir dir;
  const std::string prog = dir.write("pp.rsp", kDeterminismProgram);
  const std::string stim = dir.write("pp.stim", kStimuli);
  for (const char* trace : {"--trace", "--trace=json", "--trace=text"}) {
    INFO(trace);
    const std::vector<std::string> args{"run", prog, trace, "--stimuli", stim, "--input", "3=ON@0.1"};
    const CliResult first = runCli(args);
    const CliResult second = runCli(args);
    REQUIRE(first.code == 0);
    CHECK(first.err.empty());
    CHECK(first.out.size() > 1000);
    CHECK(first.out == second.out);
    CHECK(first.err == second.err);
  }
  // The JSON trace is one valid JSON object per executed instruction, and
  // the input on line 4 stopped the loop before five rounds.
  const CliResult json = runCli({"run", prog, "--trace=json", "--format=json", "--stimuli", stim});
  REQUIRE(json.code == 0);
  std::istringstream lines(json.out);
  std::vector<nlohmann::json> records;
  for (std::string line; std::getline(lines, line);) {
    INFO(line);
    REQUIRE(nlohmann::json::accept(line));
    records.push_back(nlohmann::json::parse(line));
  }
  REQUIRE(records.size() >= 2);
  const nlohmann::json summary = records.back();
  records.pop_back();
  // The input changes are event lines of their own, each with its cause.
  std::size_t inputEvents = 0;
  std::erase_if(records, [&](const nlohmann::json& r) {
    if (!r.contains("event")) return false;
    CHECK(r["event"] == "input");
    // Input 2 follows output 1 by the rules of lines 1 and 2; input 4 is line 3's.
    CHECK(r["cause"] == (r["input"] == 4 ? "stimulus" : "rule"));
    CHECK(r["cause_line"] == (r["input"] == 4 ? 3 : r["on"] == true ? 1 : 2));
    ++inputEvents;
    return true;
  });
  CHECK(inputEvents > 0);
  CHECK(summary["status"] == "finished");
  CHECK(records.size() == summary["steps"].get<std::size_t>());
  CHECK(summary["variables"]["COUNT"].get<int>() < 5);
  CHECK(records.back()["op"] == "END");
  for (const auto& r : records) {
    CHECK(r.contains("time"));
    CHECK(r.contains("instr"));
    CHECK(r.contains("line"));
  }
}

TEST_CASE("the text trace has one line per executed instruction", "[vm][determinism]") {
  TempDir dir;
  const std::string prog = dir.write("pp.rsp", kDeterminismProgram);
  const std::string stim = dir.write("pp.stim", kStimuli);
  const CliResult r = runCli({"run", prog, "--trace", "--stimuli", stim});
  REQUIRE(r.code == 0);
  const CliResult summary = runCli({"run", prog, "--format=json", "--stimuli", stim});
  const std::size_t steps = nlohmann::json::parse(summary.out)["steps"].get<std::size_t>();
  // Every trace row starts with the right-aligned time, i.e. with blanks;
  // the header and the summary start otherwise, except the header's "time".
  std::istringstream in(r.out);
  std::string header;
  std::getline(in, header);
  CHECK(header.find("time") != std::string::npos);
  CHECK(header.find("instr") != std::string::npos);
  std::size_t rows = 0;
  std::size_t inputEvents = 0;  // an input's change is an event line of its own
  for (std::string line; std::getline(in, line) && line.rfind("run of ", 0) != 0;)
    ++(std::regex_search(line, std::regex(R"(^ +[0-9.]+  input [0-9] (ON|OFF): )")) ? inputEvents : rows);
  CHECK(rows == steps);
  CHECK(inputEvents > 0);
  CHECK(countLines(r.out, 'r') == 1);  // "run of ..." once
}

TEST_CASE("compiling twice gives identical image bytes", "[vm][determinism]") {
  TempDir dir;
  const std::string prog = dir.write("pp.rsp", kDeterminismProgram);
  REQUIRE(runCli({"compile", prog, "-o", dir.file("a.rsb")}).code == 0);
  REQUIRE(runCli({"compile", prog, "-o", dir.file("b.rsb")}).code == 0);
  const std::string a = rs::testing::readBytes(dir.file("a.rsb"));
  CHECK(a.size() > rs::vm::kImageHeaderBytes);
  CHECK(a == rs::testing::readBytes(dir.file("b.rsb")));

  // And through the library, from two separate SourceFiles.
  const rs::compiler::Target target{"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth, nullptr};
  const auto once = rs::compiler::compile(rs::diag::SourceFile(prog, kDeterminismProgram), target);
  const auto twice = rs::compiler::compile(rs::diag::SourceFile(prog, kDeterminismProgram), target);
  REQUIRE(once.ok());
  REQUIRE(twice.ok());
  const std::vector<std::uint8_t> bytes = rs::vm::writeImage(*once.image);
  CHECK(bytes == rs::vm::writeImage(*twice.image));
  CHECK(std::string(bytes.begin(), bytes.end()) == a);

  // Compiling an image verifies it and writes it again, byte for byte.
  REQUIRE(runCli({"compile", dir.file("a.rsb"), "-o", dir.file("c.rsb")}).code == 0);
  CHECK(rs::testing::readBytes(dir.file("c.rsb")) == a);
}

TEST_CASE("running the image gives the same output as running the source", "[vm][determinism]") {
  TempDir dir;
  const std::string prog = dir.write("pp.rsp", kDeterminismProgram);
  const std::string stim = dir.write("pp.stim", kStimuli);
  const std::string image = dir.file("pp.rsb");
  REQUIRE(runCli({"compile", prog, "-o", image}).code == 0);
  for (const char* trace : {"--trace", "--trace=json"}) {
    INFO(trace);
    const CliResult fromSource = runCli({"run", prog, trace, "--stimuli", stim});
    const CliResult fromImage = runCli({"run", image, trace, "--stimuli", stim});
    REQUIRE(fromSource.code == 0);
    CHECK(fromImage.code == 0);
    CHECK(fromImage.out == fromSource.out);
    CHECK(fromImage.err == fromSource.err);
  }
  // The image is recognised by its magic number, whatever its name.
  const std::string renamed = dir.write("image.rsp", rs::testing::readBytes(image));
  const CliResult a = runCli({"run", renamed, "--format=json", "--stimuli", stim});
  const CliResult b = runCli({"run", prog, "--format=json", "--stimuli", stim});
  CHECK(a.code == 0);
  CHECK(a.out == b.out);
}
