// Golden device run: `robotsim run belt_cell.rsp --cell belt_cell.rsd` with
// --trace, and with --trace=json --format json, must print exactly
// tests/golden/belt_cell.trace and belt_cell.trace.json: a whole run of a
// cell's belt, feeder, beam and sink, the same bytes on every machine.
//
// Checked by hand against the cell (belt x -750..750 at 100/s while output
// 1 is on; a block is 40 long; the feeder's spot x -740..-700; the beam at
// x = 300; the sink takes a block when its centre reaches x = 640; the
// feeder puts three blocks, at 0, 6 and 12 s):
// - block 2 (fed at 0): its front rides 1000 to the beam, 10.000 s: eye ON,
//   input 1 ON (wire from sensor eye, line 11), the WAITFOR ends, the belt
//   stops. Block 3 (fed at 6) has ridden 400 by then (front at -300).
// - DELAY 2: the belt runs again at 12.000 s, when block 4 is fed (its spot
//   is free: block 3 is 400 on). Block 2's back passes x = 300 after 40
//   more, 0.4 s: the beam is clear from the first whole microsecond it no
//   longer touches, 12.400001 (the text trace rounds to 12.400).
// - block 2's centre rides from 280 to 640, 3.6 s after 12.000: the sink
//   takes it at 15.600. Block 3's front rides from -300 to 300, 6 s: ON at
//   18.000; the belt stands 18..20 (block 4 at -140), OFF at 20.400001,
//   taken at 23.600; block 4's front from -100 to 300: ON at 24.000, the
//   belt stands 24..26, OFF at 26.400001, taken at 29.600.
// - the third WAITFOR 1 OFF ends the loop (PARTS = 3, 24 instructions: 1
//   before the loop, 7 in each of three rounds, DELAY 5 and END); DELAY 5
//   ends the run at 31.400001. No fourth block: COUNT 3.
// - the summary: eye OFF, ON 3 times; the belt running (output 1 on),
//   carried 3; fed 3; taken 3; 3 parts in 31.400001 s is 343.949 an hour;
//   the fed blocks are gone, so the conveyor is the one object listed.
//
// To regenerate after an intended change, run with ROBOTSIM_UPDATE_GOLDEN=1
// and check the new files by hand again, as above, before committing them.
#include <catch2/catch.hpp>

#include <string>

#include "tests/cli/cli_support.h"

// A named namespace: the unity build may put this file beside test_golden.cpp.
namespace golden_devices {

const std::string kGoldenDir = std::string(ROBOTSIM_SOURCE_DIR) + "/tests/golden/";

std::string withoutDir(std::string text) {
  for (std::size_t at = text.find(kGoldenDir); at != std::string::npos; at = text.find(kGoldenDir, at))
    text.erase(at, kGoldenDir.size());
  return text;
}

void checkDeviceRun(const std::string& goldenName, const std::vector<std::string>& options) {
  std::vector<std::string> args{"run", kGoldenDir + "belt_cell.rsp", "--cell", kGoldenDir + "belt_cell.rsd"};
  args.insert(args.end(), options.begin(), options.end());
  const rs::testing::CliResult r = rs::testing::runCli(args);
  INFO(goldenName);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  const std::string actual = withoutDir(r.out);
  const std::string expectedPath = kGoldenDir + goldenName;
  if (rs::testing::rewriteGolden(expectedPath, actual)) return;
  const std::string expected = rs::testing::readBytes(expectedPath);
  REQUIRE(!expected.empty());
  CHECK(actual == expected);
}

}  // namespace golden_devices

using golden_devices::checkDeviceRun;

TEST_CASE("golden: a device run's text trace and summary", "[golden][devices]") {
  checkDeviceRun("belt_cell.trace", {"--trace"});
}

TEST_CASE("golden: a device run's JSON trace and summary", "[golden][devices]") {
  checkDeviceRun("belt_cell.trace.json", {"--trace=json", "--format", "json"});
}
