// Byte-exact transcripts: what the backend sends and expects, per dialect,
// for a few small programs, on the in-process emulator and a manual clock
// (so the timestamps repeat too). Each golden file was checked by hand
// against docs/rhino-protocol.md; docs/serial.md explains the format.
// ROBOTSIM_UPDATE_GOLDEN=1 rewrites them.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "tests/cli/cli_support.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using namespace rs::rhino::testing;
namespace vm = rs::vm;

const char* const kMoves =
    "; two moves: absolute, then relative\n"
    "MOVETO 100 60\n"
    "MOVE -150 -20\n"
    "END\n";

const char* const kIo =
    "; outputs, a branch on input 2, a wait on input 5\n"
    "OUTSIG 1 ON\n"
    "OUTSIG 4 ON\n"
    "JMPIN 2 ON 5\n"
    "SET MISSED 1\n"
    "WAITFOR 5 ON\n"
    "OUTSIG 1 OFF\n"
    "END\n";

const char* const kHome =
    "; the arm is not where the host believes: HRDHOME finds the switches\n"
    "MOVETO 50 30\n"
    "HRDHOME\n"
    "END\n";

std::string goldenPath(const std::string& name) {
  return std::string(ROBOTSIM_SOURCE_DIR) + "/tests/rhino/golden/" + name;
}

std::string transcript(Dialect d, const char* program, std::array<std::int32_t, 8> start = {}) {
  const auto motors = twoMotors();
  const vm::Image image = compileFor(program, motors);
  EmulatorConfig emu = emulatorFor(testSettings(d), motors);
  emu.start = start;
  LoopbackRig rig(testSettings(d), motors, emu);
  rig.engine.setInput(2, true);
  rig.engine.setInput(5, true);
  REQUIRE(rig.machine.open());
  const RunResult r = runOn(image, rig.machine);
  INFO(r.outcome.message);
  REQUIRE(r.outcome.ok());
  return rig.logText.str();
}

void checkGolden(const std::string& name, const std::string& actual) {
  const std::string path = goldenPath(name);
  if (rs::testing::rewriteGolden(path, actual)) return;
  const std::string expected = rs::testing::readBytes(path);
  REQUIRE_FALSE(expected.empty());
  CHECK(actual == expected);
}

}  // namespace

TEST_CASE("Mark III transcript: moves in chunks, polled until done", "[serial]") {
  checkGolden("mark3_moves.log", transcript(Dialect::Mark3, kMoves));
}

TEST_CASE("Mark III transcript: outputs L/M and P, inputs through J and K", "[serial]") {
  checkGolden("mark3_io.log", transcript(Dialect::Mark3, kIo));
}

TEST_CASE("Mark III transcript: HRDHOME steps each motor to its switch, then X", "[serial]") {
  std::array<std::int32_t, 8> start{};
  start[4] = 75;  // E is 75 steps from home, the gripper A 10 (inside its switch)
  start[0] = 10;
  checkGolden("mark3_home.log", transcript(Dialect::Mark3, kHome, start));
}

TEST_CASE("Mark IV transcript: PD, MI, SA until 0, SE, PA", "[serial]") {
  checkGolden("mark4_moves.log", transcript(Dialect::Mark4, kMoves));
}

TEST_CASE("Mark IV transcript: OB outputs, IP inputs", "[serial]") {
  checkGolden("mark4_io.log", transcript(Dialect::Mark4, kIo));
}

TEST_CASE("Mark IV transcript: HH, SA until 0, SE, PA", "[serial]") {
  std::array<std::int32_t, 8> start{};
  start[4] = 75;
  start[0] = 10;
  checkGolden("mark4_home.log", transcript(Dialect::Mark4, kHome, start));
}

TEST_CASE("transcripts repeat byte for byte", "[serial]") {
  CHECK(transcript(Dialect::Mark3, kMoves) == transcript(Dialect::Mark3, kMoves));
  CHECK(transcript(Dialect::Mark4, kIo) == transcript(Dialect::Mark4, kIo));
}
