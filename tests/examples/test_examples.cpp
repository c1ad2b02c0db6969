// The example programs (examples/*.rsp): each one runs in-process through
// the `robotsim run` command and its JSON summary must match values worked
// out BY HAND from the program text and the default robot's motor speeds
// (stdlib/default_robot.cpp):
//
//   motor  range           speed         so: 1 s is ...
//   E      -1000..1000     400 u/s       400 units
//   D       -550..550      400 u/s       400 units
//   C       -350..350      300 u/s       300 units
//   B       -700..700      500 u/s       500 units
//   A          0..120      200 u/s       200 units (open -> closed: 0.6 s)
//
// A move lasts as long as its slowest motor: ceil(|delta| * 10^6 / speed)
// microseconds. The derivation of every expected value is in the comments.
// Also checked: together the examples use all 23 instructions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/file_io.h"
#include "tools/cli/lib/app.h"
#include "tools/cli/lib/exit_codes.h"
#include "launch/program.h"
#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "tests/cli/cli_support.h"
#include "vm/opcodes.h"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kExamples = fs::path(ROBOTSIM_SOURCE_DIR) / "examples";

struct Expected {
  std::int64_t micros;                                     // simulated time
  std::uint64_t steps;                                     // instructions executed
  std::array<int, 5> motors;                               // E D C B A
  std::array<bool, 8> outputs;                             // output 1 first
  std::array<bool, 8> inputs;                              // input 1 first
  std::vector<std::pair<std::string, int>> variables;      // in slot order
};

using Result = rs::testing::CliResult;

Result robotsim(const std::vector<std::string>& args) { return rs::testing::runCli(args); }

// `robotsim run examples/NAME.rsp --format=json [--stimuli examples/STIM]`
Json runExample(const std::string& name, const std::string& stimuli = {}) {
  std::vector<std::string> args{"run", (kExamples / name).string(), "--format=json"};
  if (!stimuli.empty()) {
    args.push_back("--stimuli");
    args.push_back((kExamples / stimuli).string());
  }
  const Result r = robotsim(args);
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  REQUIRE(r.err.empty());  // no warnings either: examples are clean
  return Json::parse(r.out);
}

void checkSummary(const Json& j, const Expected& e) {
  CAPTURE(j.dump());
  CHECK(j.at("status") == "finished");
  CHECK(j.at("diagnostics").empty());
  // The summary prints seconds as a double; the clock counts microseconds.
  CHECK(std::llround(j.at("time").get<double>() * 1e6) == e.micros);
  CHECK(j.at("steps").get<std::uint64_t>() == e.steps);
  const std::array<const char*, 5> letters{"E", "D", "C", "B", "A"};
  REQUIRE(j.at("motors").size() == letters.size());
  for (std::size_t i = 0; i < letters.size(); ++i) {
    INFO("motor " << letters[i]);
    CHECK(j.at("motors").at(letters[i]).get<int>() == e.motors[i]);
  }
  for (std::size_t i = 0; i < 8; ++i) {
    INFO("line " << i + 1);
    CHECK(j.at("outputs").at(i).get<bool>() == e.outputs[i]);
    CHECK(j.at("inputs").at(i).get<bool>() == e.inputs[i]);
  }
  const Json& vars = j.at("variables");
  REQUIRE(vars.size() == e.variables.size());
  for (const auto& [name, value] : e.variables) {
    INFO("variable " << name);
    REQUIRE(vars.contains(name));
    CHECK(vars.at(name).get<int>() == value);
  }
}

constexpr std::array<bool, 8> kNone{};

std::vector<fs::path> exampleSources() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kExamples))
    if (entry.path().extension() == ".rsp") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("example first_moves: absolute and relative moves", "[examples]") {
  // MOVETO 400 200 0 0 0       from 0: E 400/400 = 1 s, D 200/400 = 0.5 s   -> 1 s
  // MOVETO 400 200 -300 500 0  C 300/300 = 1 s, B 500/500 = 1 s             -> 1 s   (2)
  // MOVE -800 0 0 0 120        E 400 -> -400: 800/400 = 2 s, A 120/200 = 0.6 -> 2 s   (4)
  // MOVE 0 -400 300 -500 -120  D 200 -> -200: 1 s; C -300 -> 0: 1 s;
  //                            B 500 -> 0: 1 s; A 120 -> 0: 0.6 s          -> 1 s   (5)
  // MOVE 0 0 100 0 0           C 100/300 s = 333333.3 us, rounded up to 333334 us
  // END                        total 5 s + 333334 us; 6 instructions
  // Final: E -400, D 200 - 400 = -200, C -300 + 300 + 100 = 100, B 0, A 0.
  checkSummary(runExample("first_moves.rsp"), {5'333'334, 6, {-400, -200, 100, 0, 0}, kNone, kNone, {}});
}

TEST_CASE("example counted_loop: SET, ADD and JMPVAR with <, > and =", "[examples]") {
  // Loop 1 (instr 2..4) runs 5 times: COUNT 1..5, leaves when COUNT = 5.
  //   Each MOVE 100 0 0 0 0: E 100/400 = 0.25 s  -> 1.25 s, E = 500.
  //   Steps: SET (1) + 5 * 3 = 16.
  // Loop 2 (down: MOVE, ADD, JMPVAR >) runs 5 times: COUNT 4..0.
  //   Each MOVE 0 0 0 -100 0: B 100/500 = 0.2 s  -> 1.0 s, B = -500.
  //   Steps: 5 * 3 = 15 (31).
  // SET POS 500: 1 step (32).
  // Loop 3 (back: JMPVAR =, MOVE, ADD, GOTO): POS 500 -> 250 -> 0, two full
  //   passes of 4 steps, then the test jumps to done: 9 steps (41).
  //   Each MOVE -250 0 0 0 0: E 250/400 = 0.625 s -> 1.25 s, E = 0.
  // END (42). Time 1.25 + 1.0 + 1.25 = 3.5 s.
  // Variables in order of first appearance: COUNT, POS.
  checkSummary(runExample("counted_loop.rsp"),
               {3'500'000, 42, {0, 0, 0, -500, 0}, kNone, kNone, {{"COUNT", 0}, {"POS", 0}}});
}

TEST_CASE("example nested_subroutines: GOSUB three levels deep", "[examples]") {
  // One "serve" (GOSUB serve included):
  //   GOSUB serve, GOSUB pick, MOVE C -150 (0.5 s), GOSUB grip, MOVE A +120
  //   (0.6 s), ADD GRIPS, RETURN, MOVE C +150 (0.5 s), RETURN, MOVE D +200
  //   (0.5 s), GOSUB drop, MOVE C -150 (0.5 s), MOVE A -120 (0.6 s), MOVE C
  //   +150 (0.5 s), RETURN, MOVE D -200 (0.5 s), RETURN
  //   = 17 steps, 0.5+0.6+0.5+0.5+0.5+0.6+0.5+0.5 = 4.2 s; every motor ends
  //   where it started.
  // Main: serve (17, 4.2 s), MOVE E +400 (1 step, 400/400 = 1 s), serve
  //   (17, 4.2 s), HRDHOME from E=400 (1 step, 1 s), END (1 step).
  // Steps 17 + 1 + 17 + 1 + 1 = 37; time 4.2 + 1 + 4.2 + 1 = 10.4 s.
  // GRIPS counts one grip per serve: 2.
  checkSummary(runExample("nested_subroutines.rsp"), {10'400'000, 37, {0, 0, 0, 0, 0}, kNone, kNone, {{"GRIPS", 2}}});
}

TEST_CASE("example soft_home: SETSOFT and GOSOFT", "[examples]") {
  // GOSOFT before any SETSOFT: soft home 0 0 0 0 0 = where we are: 0 s.
  // SETSOFT 200 -100 150 0 0: no motion, 0 s.
  // GOSOFT: E 200/400 = 0.5, D 100/400 = 0.25, C 150/300 = 0.5      -> 0.5 s
  // MOVEP BIN_A (600 -100 150 250 0): E 400/400 = 1, B 250/500 = 0.5 -> 1 s
  // GOSOFT back: same distances                                     -> 1 s
  // MOVEP BIN_B (-200 -300 150 -250 0): E 400 -> 1, D 200 -> 0.5,
  //   B 250 -> 0.5                                                  -> 1 s
  // GOSOFT back                                                     -> 1 s
  // SETSOFT -200 100 150 0 0: 0 s.
  // GOSOFT from (200 -100 150 0 0): E 400 -> 1, D 200 -> 0.5        -> 1 s
  // HRDHOME from (-200 100 150 0 0): E 0.5, D 0.25, C 0.5           -> 0.5 s
  // END. Time 0.5 + 4 * 1 + 1 + 0.5 = 6 s; 11 instructions, no variables.
  checkSummary(runExample("soft_home.rsp"), {6'000'000, 11, {0, 0, 0, 0, 0}, kNone, kNone, {}});
}

TEST_CASE("example workcell_view: WINDOW, VIEW, DELAY, RESET, HRDHOME", "[examples]") {
  // WINDOW, VIEW: no time.
  // MOVETO 800 -400 0 0 0: E 800/400 = 2 s, D 400/400 = 1 s       -> 2 s
  // DELAY 1.5 (3.5), VIEW (0), DELAY 0.25 (3.75)
  // RESET: motors back to 0 instantly, no time (3.75)
  // DELAY 1 (4.75)
  // MOVETO 0 300 -300 0 120: D 300/400 = 0.75, C 300/300 = 1,
  //   A 120/200 = 0.6                                              -> 1 s (5.75)
  // HRDHOME: the same distances back                               -> 1 s (6.75)
  // WINDOW, VIEW, END: no time. 13 instructions, each runs once.
  checkSummary(runExample("workcell_view.rsp"), {6'750'000, 13, {0, 0, 0, 0, 0}, kNone, kNone, {}});
}

TEST_CASE("example sensor_branching: JMPIN polling and branching", "[examples]") {
  // Stimuli: input 3 ON at 0, OFF at 4, ON at 8; input 1 ON at 1, 5 and 8,
  // OFF whenever output 1 turns ON; input 4 (STOP) ON at 14.
  // Poll = JMPIN 4, JMPIN 1, DELAY 0.5, GOTO: 4 steps, 0.5 s.
  // Take = JMPIN 4, JMPIN 1 (jumps): 2 steps.
  // Large part: MOVEP PICK, MOVE close, OUTSIG ON, OUTSIG OFF, JMPIN 3
  //   (jumps), MOVEP LARGE_BIN, ADD, MOVE open, GOTO = 9 steps.
  // Small part: ... JMPIN 3 (falls through), MOVEP SMALL_BIN, ADD, GOTO
  //   release, MOVE open, GOTO = 10 steps.
  // Moves: PICK from home: D 300/400 = 0.75, C 200/300 = 0.67  -> 0.75 s
  //        PICK from a bin (+-500 -200 0 0 0): E 500/400 = 1.25,
  //          D 500/400 = 1.25, C 0.67                         -> 1.25 s
  //        PICK (A=120) to a bin: the same                    -> 1.25 s
  //        close / open the gripper: 120/200                  -> 0.6 s
  //        HRDHOME from LARGE_BIN: E 1.25, D 0.5              -> 1.25 s
  // t=0    poll (4 steps) -> 0.5; poll (8) -> 1.0
  // t=1.0  part 1 there (ON at 1): take (10); large: 0.75 + 0.6 + 1.25 + 0.6
  //        = 3.2 s -> 4.2 (19 steps); input 1 OFF at 2.35.
  // t=4.2  poll (23) -> 4.7; poll (27) -> 5.2
  // t=5.2  part 2 (ON at 5, small since 4): take (29); small: 1.25 + 0.6 +
  //        1.25 + 0.6 = 3.7 s -> 8.9 (39 steps)
  // t=8.9  part 3 (ON at 8, large): take (41); large: 1.25 + 0.6 + 1.25 +
  //        0.6 = 3.7 s -> 12.6 (50 steps)
  // t=12.6 poll (54) -> 13.1; poll (58) -> 13.6; poll (62) -> 14.1
  // t=14.1 STOP seen: JMPIN 4 jumps (63); HRDHOME 1.25 s -> 15.35 (64); END (65)
  // Final inputs: 1 OFF (taken), 3 ON (since 8), 4 ON. Outputs all OFF.
  checkSummary(runExample("sensor_branching.rsp", "sensor_branching.stim"),
               {15'350'000, 65, {0, 0, 0, 0, 0}, kNone, {false, false, true, true, false, false, false, false},
                {{"SMALL_PARTS", 1}, {"LARGE_PARTS", 2}}});
}

TEST_CASE("example pick_and_place: WAITFOR/OUTSIG handshakes (the README demo)", "[examples]") {
  // Stimuli: input 1 ON 1.5 s after output 1 turns ON, OFF when output 2
  // turns ON; input 2 ON at 0, OFF when output 3 turns ON and ON again 8 s
  // later.
  // Moves: MOVEP ABOVE_PICK from home (400 -200 0 250 0): E 1 s, D 0.5,
  //          B 0.5 -> 1 s; from ABOVE_PRESS: E 800/400 = 2 s -> 2 s
  //        MOVEP ABOVE_PRESS (-400 200 0 -250 120) from ABOVE_PICK with A=120:
  //          E 800/400 = 2 s, D 1 s, B 1 s -> 2 s
  //        MOVE C -+150: 0.5 s; gripper 120: 0.6 s.
  // Cycle k starts at s_k (OUTSIG 1 ON): WAITFOR 1 -> s_k + 1.5;
  //   pick: MOVEP + 0.5 + 0.6 + 0.5; MOVEP ABOVE_PRESS 2 s;
  //   WAITFOR 2 ON; place 0.5 + 0.6 + 0.5 = 1.6 s; OUTSIG 3 ON at p_k.
  // Cycle 1: s=0, part at 1.5, ABOVE_PICK 2.5, lifted 4.1, over the press
  //   6.1, press ready (since 0), placed p1 = 7.7; press ready again 15.7.
  // Cycle 2: s=7.7, part 9.2, ABOVE_PICK 11.2, lifted 12.8, press 14.8,
  //   waits until 15.7, placed p2 = 17.3; press ready again 25.3.
  // Cycle 3: s=17.3, part 18.8, ABOVE_PICK 20.8, lifted 22.4, press 24.4,
  //   waits until 25.3, placed p3 = 26.9; press ready again 34.9.
  // HRDHOME from ABOVE_PRESS (A=0): E 400/400 = 1 s -> 27.9;
  // WAITFOR 2 ON -> 34.9; END.
  // Steps: SET, HRDHOME (2) + 3 cycles of instructions 3..20 (18 each: 54)
  //   + HRDHOME, WAITFOR, END (3) = 59.
  // Final: motors 0, outputs all OFF, input 1 OFF (the third part was taken
  //   at 21.9 and the conveyor was not restarted), input 2 ON; PARTS = 3.
  checkSummary(runExample("pick_and_place.rsp", "pick_and_place.stim"),
               {34'900'000, 59, {0, 0, 0, 0, 0}, kNone, {false, true, false, false, false, false, false, false},
                {{"PARTS", 3}}});
}

TEST_CASE("example pick_and_place: the readable text summary of the demo", "[examples]") {
  const Result r = robotsim({"run", (kExamples / "pick_and_place.rsp").string(), "--stimuli",
                             (kExamples / "pick_and_place.stim").string()});
  INFO(r.out << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  CHECK(r.err.empty());
  CHECK(r.out.find(": finished\n") != std::string::npos);
  CHECK(r.out.find("simulated time  34.900 s") != std::string::npos);
  CHECK(r.out.find("instructions    59 executed") != std::string::npos);
  CHECK(r.out.find("motors          E=0  D=0  C=0  B=0  A=0") != std::string::npos);
  CHECK(r.out.find("variables       PARTS=3") != std::string::npos);
}

TEST_CASE("example pick_and_place deadlocks without its stimuli", "[examples]") {
  // Without the conveyor nothing ever turns input 1 ON: the first WAITFOR
  // (instruction 4, source line 21) is a deadlock at time 0, after 4 steps.
  const Result r = robotsim({"run", (kExamples / "pick_and_place.rsp").string(), "--format=json"});
  CHECK(r.code == rs::cli::kExitRunFailed);
  const Json j = Json::parse(r.out);
  CHECK(j.at("status") == "error");
  CHECK(j.at("steps") == 4);
  REQUIRE(j.at("diagnostics").size() == 1);
  CHECK(j.at("diagnostics")[0].at("line") == 21);
  CHECK(j.at("diagnostics")[0].at("message").get<std::string>().rfind("deadlock: input 1 never turns ON", 0) == 0);
}

TEST_CASE("example gantry_pick: the gripper carries both blocks to the other pallet", "[examples]") {
  // The gantry cell (stdlib/workcells/gantry-cell.rsd, stdlib/robots/gantry.rsd):
  // motors X Z Y A; X and Z 1000 u/s, Y 800 u/s, A 200 u/s.
  // MOVETO -2800 2800 0 0     X 2.8 s, Z 2.8 s                           ->  2.8     (1)
  // GOSUB pick: MOVE Y +1490  1.8625 s; MOVE A +100 0.5 s; MOVE Y -1490
  //             1.8625 s; RETURN                                         ->  7.025   (6)
  // MOVETO 1700 -2200 0 100   X 4500: 4.5 s, Z 5000: 5 s                 -> 12.025   (7)
  // GOSUB place: 1.8625 + 0.5 + 1.8625                                   -> 16.25    (12)
  // MOVETO -2000 2800 0 0     X 3700: 3.7 s, Z 5 s (A already 0)         -> 21.25    (13)
  // GOSUB pick                                                           -> 25.475   (18)
  // MOVETO 2700 -2200 0 100   X 4700: 4.7 s, Z 5 s                       -> 30.475   (19)
  // GOSUB place                                                          -> 34.7     (24)
  // HRDHOME                   X 2700: 2.7 s, Z 2200: 2.2 s               -> 37.4     (25)
  // END                                                                              (26)
  // Block 1 (placed AT 200 30 700) is taken with the TCP at (220, 51, 680)
  // (1 mm above its middle) and let go at (670, 51, 180): moved by (450, 0,
  // -500), AT corner (650, 30, 200). Block 2 (AT 280 30 700): from (300,
  // 51, 680) to (770, 51, 180), by (470, 0, -500): (750, 30, 200). The
  // pallets stay. Centres: a block's AT corner + (20, 20, -20) (a 40 cube
  // drawn with that corner at (0, 0, 40)), a pallet's + (120, 15, -80)
  // (240 x 30 x 160, the same corner).
  const Result r = robotsim({"run", (kExamples / "gantry_pick.rsp").string(), "--cell", "gantry-cell", "--format=json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  REQUIRE(r.err.empty());
  const Json j = Json::parse(r.out);
  CHECK(j.at("status") == "finished");
  CHECK(std::llround(j.at("time").get<double>() * 1e6) == 37'400'000);
  CHECK(j.at("steps") == 26);
  CHECK(j.at("motors") == Json::parse(R"({"X": 0, "Z": 0, "Y": 0, "A": 0})"));
  const Json want = Json::parse(R"json([
    {"name": "pallet", "at": [150.0, 0.0, 760.0], "centre": [270.0, 15.0, 680.0], "held": false, "moved": false},
    {"name": "block",  "at": [650.0, 30.0, 200.0], "centre": [670.0, 50.0, 180.0], "held": false, "moved": true,
     "settled": {"on": "pallet (object 4)", "drop": 0.0}},
    {"name": "block",  "at": [750.0, 30.0, 200.0], "centre": [770.0, 50.0, 180.0], "held": false, "moved": true,
     "settled": {"on": "pallet (object 4)", "drop": 0.0}},
    {"name": "pallet", "at": [610.0, 0.0, 260.0], "centre": [730.0, 15.0, 180.0], "held": false, "moved": false}])json");
  // Each block let go with its bottom on the second pallet's deck (y 30, its top): settled there, no drop.
  CHECK(j.at("objects") == want);
}

TEST_CASE("example gantry_pick: the trace says when the gripper takes and lets go", "[examples]") {
  const Result r = robotsim({"run", (kExamples / "gantry_pick.rsp").string(), "--cell", "gantry-cell", "--trace"});
  REQUIRE(r.code == rs::cli::kExitOk);
  std::vector<std::string> events;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const auto at = line.find("takes block");
    const auto go = line.find("lets go of block");
    if (at != std::string::npos) events.push_back(line.substr(0, 10) + " " + line.substr(at));
    if (go != std::string::npos) events.push_back(line.substr(0, 10) + " " + line.substr(go));
  }
  // pick 1: down ends 4.6625, close ends 5.1625; place 1: 12.025 + 1.8625 = 13.8875, open ends 14.3875;
  // pick 2: 21.25 + 1.8625 = 23.1125, close ends 23.6125; place 2: 30.475 + 1.8625 = 32.3375, open ends
  // 32.8375 (the trace rounds half a millisecond up).
  // Each let go with its bottom on the second pallet's deck (its top, y 30): it settles there, no drop.
  const std::vector<std::string> want = {"     5.163 takes block (object 2)",
                                         "    14.388 lets go of block (object 2): it settles on pallet (object 4)",
                                         "    23.613 takes block (object 3)",
                                         "    32.838 lets go of block (object 3): it settles on pallet (object 4)"};
  CHECK(events == want);
}

TEST_CASE("example stack_blocks: points written as tool poses stack one block on another", "[examples]") {
  // scara-pick (stdlib/workcells/scara-pick.rsd): the front block, AT -150 780 20, a 40 cube
  // (x -150..-110, y 780..820, z -20..20), centred at x -130, z 0. The program takes it 1 below
  // its top (y 819) and lets go with the tool centre point at (-180, 859, -45), which whole counts
  // put at y 858.96 (the example's comment): the block's bottom 0.04 into the block AT -200 780 -25
  // (top y 820), within the rest tolerance, so it settles onto it: its AT corner at (-200, 820,
  // -25) to within the counts' rounding in x and z, and exactly 820 in y. Ten instructions.
  const Result r = robotsim({"run", (kExamples / "stack_blocks.rsp").string(), "--format=json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  const Json j = Json::parse(r.out);
  CHECK(j.at("status") == "finished");
  CHECK(j.at("steps") == 10);
  CHECK(j.at("motors") == Json::parse(R"({"E": 0, "D": 0, "C": 0, "B": 0, "A": 0})"));
  const Json& moved = j.at("objects")[4];
  CHECK(moved.at("moved") == true);
  CHECK(moved.at("held") == false);
  const std::array<double, 3> want{-200, 820, -25};
  for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(moved.at("at")[k].get<double>() - want[k]) < 0.6);
  CHECK(moved.at("at")[1].get<double>() == Approx(820).margin(1e-4));  // settled on the lower block
  CHECK(moved.at("settled").at("on") == "block (object 3)");
  CHECK(moved.at("settled").at("drop").get<double>() == Approx(-0.04).margin(0.005));
  CHECK(j.at("collisions") == Json::array());
  for (std::size_t o = 0; o < 4; ++o) CHECK(j.at("objects")[o].at("moved") == false);
}

TEST_CASE("example straight_lift: a block lifted straight off its pallet and put back", "[examples]") {
  // xr4-cell: the gripper goes straight down round the front block (object
  // 3, AT 220 780 -20; APPRO), takes it at point TAKE 10 below its top,
  // lifts it straight up 50 (DEPART) and brings it straight back to TAKE's
  // counts (MOVES), lets go and leaves straight up. No collision with the
  // default collision mode (an error), and the block ends exactly where it
  // stood: it was taken and set down with the arm on the same counts.
  // Eight instructions.
  const Result r = robotsim({"run", (kExamples / "straight_lift.rsp").string(), "--format=json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  const Json j = Json::parse(r.out);
  CHECK(j.at("status") == "finished");
  CHECK(j.at("steps") == 8);
  CHECK(j.at("collisions") == Json::array());
  const Json& block = j.at("objects")[2];
  CHECK(block.at("name") == "block");
  CHECK(block.at("held") == false);
  const std::array<double, 3> want{220, 780, -20};
  for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(block.at("at")[k].get<double>() - want[k]) < 1e-6);
}

TEST_CASE("example adept_production: ten blocks from the infeed's beam to the outfeed's sink", "[examples]") {
  // Each block breaks the beam once (the belt stops, the robot takes it
  // away): 10 ON edges. Each put on the outfeed rides it (10 carried) and
  // reaches the sink 3.6 s later (its centre from x 280 to 640 at 100/s);
  // cycles are 6 s apart (the feeder's period), and the last HRDHOME takes
  // well under 3.6 s: 9 taken when the run ends. The tenth block is the
  // eighth fed: at least 8 fed.
  const Result r = robotsim({"run", (kExamples / "adept_production.rsp").string(), "--cell", "adept-cell",
                             "--format=json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  const Json j = Json::parse(r.out);
  CHECK(j.at("variables").at("PARTS") == 10);
  const Json& d = j.at("devices");
  CHECK(d.at("sensors")[0].at("name") == "eye");
  CHECK(d.at("sensors")[0].at("turned_on") == 10);
  CHECK(d.at("conveyors")[1].at("carried") == 10);
  CHECK(d.at("feeders")[0].at("fed").get<int>() >= 8);
  CHECK(d.at("sinks")[0].at("taken") == 9);
  CHECK(j.at("collisions") == Json::array());
  // A block the feeder put in a slot a taken block used has no let-go of its
  // own: only the blocks the robot let go on the outfeed (z -600) say they
  // settled there; those still on the infeed (z 600) say nothing.
  for (const Json& o : j.at("objects")) {
    if (o.at("name") != "block") continue;
    INFO(o.dump());
    CHECK(o.contains("settled") == (std::abs(o.at("centre")[2].get<double>() + 600) < 1));
  }
}

TEST_CASE("example adept_hour: an hour of production on adept-cell, 600 blocks taken by the sink", "[examples]") {
  // The arithmetic is in the program's comments: the feeder puts a block
  // every 6 s and the robot's cycle (1.179 s) keeps up, so the 600th block
  // is the one fed at 3582 s; it breaks the beam 10..12.358 s later, and
  // the last cycle, HRDHOME and DELAY 4 end the run 5.306 s after that,
  // when the sink (4.661 s after the beam) has taken it: 600 taken, 600
  // fed (0 .. 3594 s), 600 ON edges, 600 carried on the outfeed.
  const Result r = robotsim({"run", (kExamples / "adept_hour.rsp").string(), "--cell", "adept-cell",
                             "--format=json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  const Json j = Json::parse(r.out);
  CHECK(j.at("status") == "finished");
  CHECK(j.at("variables").at("PARTS") == 600);
  const double end = j.at("time").get<double>();
  CHECK(end >= 3597.3);
  CHECK(end <= 3599.7);
  const Json& d = j.at("devices");
  CHECK(d.at("sensors")[0].at("turned_on") == 600);
  CHECK(d.at("conveyors")[1].at("carried") == 600);
  CHECK(d.at("feeders")[0].at("fed") == 600);
  CHECK(d.at("sinks")[0].at("taken") == 600);
  CHECK(j.at("collisions") == Json::array());
}

TEST_CASE("examples adept_production, scorobot_production and adept_hour pass check --strict: no part let go above its support",
          "[examples]") {
  // The let-go of a part more than 1 above what it settles on is a warning
  // (part-dropped), which --strict fails: the examples place their parts.
  for (const auto& [program, cell] : {std::pair<std::string, std::string>{"adept_production.rsp", "adept-cell"},
                                      std::pair<std::string, std::string>{"scorobot_production.rsp", "scorobot-cell"},
                                      std::pair<std::string, std::string>{"adept_hour.rsp", "adept-cell"}}) {
    const Result r = robotsim({"check", "--strict", (kExamples / program).string(), "--cell", cell});
    INFO(program << ": " << r.out << r.err);
    CHECK(r.code == rs::cli::kExitOk);
    CHECK(r.err.find("warning") == std::string::npos);
  }
}

TEST_CASE("example scorobot_production: five blocks from the belt into the pallet's sink corner", "[examples]") {
  // Each block breaks the beam once and is let go with its centre in the
  // sink's zone, which takes it at once: 5 edges, 5 taken; the fifth is the
  // fourth fed.
  const Result r = robotsim({"run", (kExamples / "scorobot_production.rsp").string(), "--cell", "scorobot-cell",
                             "--format=json"});
  INFO("stderr: " << r.err);
  REQUIRE(r.code == rs::cli::kExitOk);
  const Json j = Json::parse(r.out);
  CHECK(j.at("variables").at("PARTS") == 5);
  const Json& d = j.at("devices");
  CHECK(d.at("sensors")[0].at("turned_on") == 5);
  CHECK(d.at("sinks")[0].at("taken") == 5);
  CHECK(d.at("feeders")[0].at("fed").get<int>() >= 4);
  CHECK(j.at("collisions") == Json::array());
}

TEST_CASE("every example has a summary test above", "[examples]") {
  const std::set<std::string> tested{"first_moves.rsp",   "counted_loop.rsp",       "nested_subroutines.rsp",
                                     "soft_home.rsp",     "workcell_view.rsp",      "sensor_branching.rsp",
                                     "pick_and_place.rsp", "gantry_pick.rsp",       "stack_blocks.rsp",
                                     "straight_lift.rsp", "adept_production.rsp", "scorobot_production.rsp",
                                     "adept_hour.rsp"};
  std::set<std::string> found;
  for (const fs::path& p : exampleSources()) found.insert(p.filename().string());
  CHECK(found == tested);
}

TEST_CASE("the examples together use all 23 instructions", "[examples]") {
  std::set<rs::vm::Op> used;
  for (const fs::path& path : exampleSources()) {
    INFO(path.string());
    rs::base::FileRead text = rs::base::readFile(path.string(), rs::launch::kMaxInputBytes);
    REQUIRE(text.bytes);
    const rs::diag::SourceFile source(path.string(), std::move(*text.bytes));
    // gantry_pick runs on the gantry cell, stack_blocks on scara-pick, straight_lift on xr4-cell; the
    // others on the default robot.
    const std::string cellName = path.filename() == "gantry_pick.rsp"     ? "gantry-cell"
                                 : path.filename() == "stack_blocks.rsp"  ? "scara-pick"
                                 : path.filename() == "straight_lift.rsp" ? "xr4-cell"
                                 : path.filename() == "adept_production.rsp" ? "adept-cell"
                                 : path.filename() == "adept_hour.rsp" ? "adept-cell"
                                 : path.filename() == "scorobot_production.rsp" ? "scorobot-cell"
                                                                          : "";
    rs::compiler::Library library(rs::compiler::librarySearchPath({}));
    const std::optional<rs::workcell::Workcell> cell =
        cellName.empty() ? std::nullopt : library.workcell(cellName);
    REQUIRE(cell.has_value() == !cellName.empty());
    const rs::compiler::CompileResult compiled =
        rs::compiler::compile(source, cell ? rs::launch::cellTarget(*cell) : rs::launch::defaultTarget());
    REQUIRE(compiled.ok());
    CHECK(compiled.diagnostics.empty());
    for (const rs::vm::Instr& in : compiled.image->code) used.insert(in.op);
  }
  for (const rs::vm::OpInfo& op : rs::vm::kOps) {
    INFO("instruction " << op.name << " is used by no example");
    CHECK(used.count(op.op) == 1);
  }
  CHECK(used.size() == rs::vm::kOpCount);
}
