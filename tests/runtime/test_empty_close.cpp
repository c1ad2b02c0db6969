// A gripper that closes on nothing (runtime/run/empty_close.h): the trace
// says which object was nearest and which way its centre lies, and a run
// that closed but never took gets a warning in every front end.
//
// Worked out by hand from stdlib/workcells/gantry-cell.rsd and
// stdlib/objects/block.rsd: the gantry's tool centre point is at
// (500 + X/10, 200 - Y/10, 400 + Z/10); block 1 (object 2) spans x
// 200..240, y 30..70, z 660..700, centre (220, 50, 680); block 2 (object
// 3) x 280..320, same y and z, centre (300, 50, 680).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/debug/debug_test_util.h"
#include "tools/debug/debug_session.h"

namespace {

using rs::testing::runCli;
using rs::testing::TempDir;

// Over block 1, down 110 (not 149): the tool centre point at (220, 90,
// 680), 20 above the block's top (y 70) and 40 above its centre (y 50).
constexpr const char* kTooHigh =
    "        MOVETO -2800 2800 0 0\n"
    "        MOVE 0 0 1100 0\n"
    "        MOVE 0 0 0 100\n"     // line 3: closes on nothing
    "        MOVE 0 0 -1100 0\n"
    "        MOVE 0 0 0 -100\n"
    "        MOVE 0 0 0 100\n"     // line 6: closes on nothing again, at (220, 200, 680)
    "        END\n";

// At (250, 51, 680): between the blocks, 10 past block 1's side (x 240)
// and 30 short of block 2's (x 280); block 1's centre is 30 towards -x
// and 1 below.
constexpr const char* kBesideProgram =
    "        MOVETO -2500 2800 1490 0\n"
    "        MOVE 0 0 0 100\n"
    "        END\n";

// Closes on nothing, opens, goes down 39 more into the block (y 51) and
// takes it: the empty close is traced but there is nothing to warn of.
constexpr const char* kTakesLater =
    "        MOVETO -2800 2800 0 0\n"
    "        MOVE 0 0 1100 0\n"
    "        MOVE 0 0 0 100\n"
    "        MOVE 0 0 0 -100\n"
    "        MOVE 0 0 390 0\n"
    "        MOVE 0 0 0 100\n"
    "        END\n";

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a grasp 40 too high: the trace names the nearest block and says its centre is 40 below", "[grasp][cli]") {
  const TempDir dir;
  const std::string program = dir.write("high.rsp", kTooHigh);
  const auto r = runCli({"run", program, "--cell", "gantry-cell", "--trace"});
  CHECK(r.code == 0);
  CHECK(has(r.out, "closes on nothing (nearest: block (object 2), its centre 40 below the tool centre point, "
                   "which is 20 outside its box)"));
  // The second close, back up at y 200: 150 above the centre, 130 above the top.
  CHECK(has(r.out, "closes on nothing (nearest: block (object 2), its centre 150 below the tool centre point, "
                   "which is 130 outside its box)"));
  // The warning, at the first of the two closes (line 3, column 9), with the move that fixes it.
  CHECK(has(r.err, program + ":3:9: warning: the gripper closed 2 times but never took an object; here it closed on "
                             "nothing with the tool centre point at (220, 90, 680) (nearest: block (object 2)"));
  CHECK(has(r.err, "hint: a closing gripper takes the object whose box holds the tool centre point when the move "
                   "ends: move it 40 down to reach the centre of block (object 2)"));
  CHECK(has(r.out, "  gripper         closed 2 times, took nothing (the warning at line 3)\n"));

  const auto json = runCli({"run", program, "--cell", "gantry-cell", "--trace=json"});
  std::istringstream lines(json.out);
  std::string line;
  int found = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.contains("closes_on_nothing") || j["line"] != 3) continue;
    ++found;
    const auto& e = j["closes_on_nothing"];
    CHECK(e["nearest"] == 2);
    CHECK(e["name"] == "block");
    CHECK(e["distance"] == 20.0);
    CHECK(e["tcp"] == nlohmann::json::array({220.0, 90.0, 680.0}));
    CHECK(e["centre_offset"] == nlohmann::json::array({0.0, -40.0, 0.0}));
  }
  CHECK(found == 1);

  const auto summary = runCli({"run", program, "--cell", "gantry-cell", "--format=json"});
  const auto s = nlohmann::json::parse(summary.out);
  REQUIRE(s["diagnostics"].size() == 1);
  CHECK(s["diagnostics"][0]["severity"] == "warning");
  CHECK(s["diagnostics"][0]["code"] == "gripper-took-nothing");
  CHECK(s["diagnostics"][0]["line"] == 3);
  CHECK(s["status"] == "finished");  // a warning, not a failure
}

TEST_CASE("a grasp beside the block: the centre's offset across as well as down", "[grasp][cli]") {
  const TempDir dir;
  const std::string program = dir.write("beside.rsp", kBesideProgram);
  const auto r = runCli({"run", program, "--cell", "gantry-cell", "--collisions=off", "--trace"});
  CHECK(has(r.out, "closes on nothing (nearest: block (object 2), its centre 1 below and 30 towards -x of the tool "
                   "centre point, which is 10 outside its box)"));
  CHECK(has(r.err, program + ":2:9: warning: the gripper closed once but never took an object"));
  CHECK(has(r.err, "move it 1 down and 30 towards -x to reach the centre of block (object 2)"));
}

TEST_CASE("a close on nothing followed by a take is traced but not warned of", "[grasp][cli]") {
  const TempDir dir;
  const std::string program = dir.write("later.rsp", kTakesLater);
  const auto r = runCli({"run", program, "--cell", "gantry-cell", "--trace"});
  CHECK(r.code == 0);
  CHECK(has(r.out, "closes on nothing (nearest: block (object 2)"));
  CHECK(has(r.out, "takes block (object 2)"));
  CHECK_FALSE(has(r.err, "gripper-took-nothing"));
  CHECK_FALSE(has(r.err, "warning"));
  CHECK_FALSE(has(r.out, "took nothing"));
}

TEST_CASE("a workcell without objects: closing on nothing is no mistake", "[grasp][cli]") {
  const TempDir dir;
  const std::string bare = dir.write("bare.rsd", "WORKCELL bare-gantry\n  ROBOT gantry AT 0 1000 0\nEND\n");
  const std::string program = dir.write("close.rsp", "        MOVE 0 0 0 100\n        END\n");
  const auto r = runCli({"run", program, "--cell", bare, "--trace"});
  CHECK(r.code == 0);
  CHECK_FALSE(has(r.out, "closes on nothing"));
  CHECK_FALSE(has(r.err, "warning"));
  // The robot alone (a library robot as the cell) has no objects either.
  const auto alone = runCli({"run", program, "--cell", "gantry", "--trace"});
  CHECK(alone.code == 0);
  CHECK_FALSE(has(alone.out, "closes on nothing"));
  CHECK_FALSE(has(alone.err, "warning"));
  // The same close on the cell with blocks is warned of (the check above can fail).
  const auto withBlocks = runCli({"run", program, "--cell", "gantry-cell", "--trace"});
  CHECK(has(withBlocks.out, "closes on nothing"));
  CHECK(has(withBlocks.err, program + ":1:9: warning: the gripper closed once but never took an object"));
}

TEST_CASE("robotsim test shows the warning of a test that passes, in text, JSON and JUnit", "[grasp][testrun][cli]") {
  const TempDir dir;
  const std::string program =
      dir.write("high.rsp", std::string(kTooHigh) + "; test: cell gantry-cell\n; expect: finished\n");
  const auto r = runCli({"test", program});
  CHECK(r.code == 0);
  CHECK(has(r.out, program + " PASSED (1 expectation, "));
  CHECK(has(r.out, " s simulated, 1 warning)\n"));
  CHECK(has(r.out, program + ":3:9: warning: the gripper closed 2 times but never took an object"));

  const auto json = runCli({"test", program, "--format=json"});
  const auto j = nlohmann::json::parse(json.out);
  REQUIRE(j["tests"].size() == 1);
  CHECK(j["tests"][0]["status"] == "PASSED");
  REQUIRE(j["tests"][0]["warnings"].size() == 1);
  CHECK(j["tests"][0]["warnings"][0]["code"] == "gripper-took-nothing");
  CHECK(j["tests"][0]["warnings"][0]["line"] == 3);

  const std::string junit = (dir.path() / "report.xml").string();
  CHECK(runCli({"test", program, "--junit", junit}).code == 0);
  CHECK(has(read(junit), "<system-out>" + program + ":3:9: warning: the gripper closed 2 times"));

  // A program whose grasp works has no warnings.
  const auto good = runCli({"test", debugtest::kExamples + "gantry_pick.rsp", "--format=json"});
  const auto g = nlohmann::json::parse(good.out);
  CHECK(g["tests"][0]["status"] == "PASSED");
  CHECK(g["tests"][0]["warnings"].empty());
}

TEST_CASE("the debugger's end of the run and the animation's page carry the warning", "[grasp][debug][render]") {
  const TempDir dir;
  const std::string program = dir.write("high.rsp", kTooHigh);
  rs::runtime::RunSpec spec;
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  spec.image = std::make_shared<const rs::vm::Image>(rendertest::compile(program, cell));
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  rs::debug::DebugSession session(std::move(spec));
  const rs::debug::Stop end = session.resume();
  CHECK(end.reason == rs::debug::StopReason::End);
  CHECK(has(end.message, "the program ended; warning at line 3: the gripper closed 2 times but never took an object"));

  const std::string page = (dir.path() / "high.html").string();
  const auto a = runCli({"animate", program, "--cell", "gantry-cell", "-o", page});
  CHECK(a.code == 0);
  CHECK(has(a.err, program + ":3:9: warning: the gripper closed 2 times"));
  CHECK(has(read(page), "\"warning\":\"line 3: the gripper closed 2 times but never took an object"));
  // The example's page has none.
  const std::string good = (dir.path() / "good.html").string();
  CHECK(runCli({"animate", debugtest::kExamples + "gantry_pick.rsp", "--cell", "gantry-cell", "-o", good}).code == 0);
  CHECK_FALSE(has(read(good), "\"warning\""));
}
