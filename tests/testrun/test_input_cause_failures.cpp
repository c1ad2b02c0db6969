// `robotsim test`: a failed expectation on an input says what set the
// input last and when (issue 35), in the trace's words, for all three
// kinds: at a moment, during a window, at the end.
//
// Worked out by hand. On stdlib/workcells/adept-cell.rsd (the top of
// test_device_expectations.cpp) OUTSIG 1 ON runs the infeed at 0 s and
// block 3's front breaks the beam, wired to input 1 (line 32), at 1.1 s;
// OUTSIG 1 OFF then stops it there, in the beam, so input 1 stays ON to
// the end, 1 s later (the DELAY): 2.1 s. With the stimuli file below and
// no cell: input 2 turns ON at 0.5 s by its line 1; the rule of its line 2
// turns input 3 ON 0.2 s after the OUTSIG 1 ON at 0 s; the run ends at 1 s.
// The line running at a moment is the last step's that began by then: at
// 1.1 s the DELAY's (the WAITFOR and OUTSIG 1 OFF end there, the DELAY
// begins).
#include <catch2/catch.hpp>

#include <string>

#include "tests/cli/cli_support.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

void checkHas(const CliResult& r, const std::string& want) {
  INFO(r.out << r.err);
  CAPTURE(want);
  CHECK(r.out.find(want) != std::string::npos);
}

}  // namespace

TEST_CASE("robotsim test: an input's failure names the wire that set it", "[testrun][input-causes]") {
  const TempDir dir;
  const std::string program = dir.write("beam.rsp",
                                        "; test: cell adept-cell\n"           // 1
                                        "; expect: input 1 off at 1.5\n"      // 2
                                        "; expect: input 1 off during 1..2\n" // 3
                                        "; expect: input 1 off\n"             // 4
                                        "        OUTSIG 1 ON\n"               // 5
                                        "        WAITFOR 1 ON\n"              // 6
                                        "        OUTSIG 1 OFF\n"              // 7
                                        "        DELAY 1\n"                   // 8
                                        "        END\n");                     // 9
  const CliResult r = runCli({"test", program});
  CHECK(r.code == 1);
  checkHas(r, program + ":2:3: error: expected input 1 OFF at 1.500 s; it was ON then (line 8 running; ON since 1.100 s: "
                        "wire from sensor eye)\n");
  checkHas(r, program + ":3:3: error: expected input 1 OFF during 1.000..2.000 s; it was ON at 1.100 s (line 8 "
                        "running; ON since 1.100 s: wire from sensor eye)\n");
  checkHas(r, program + ":4:3: error: expected input 1 OFF at the end; it is ON at line 9, 2.100 s (since 1.100 s: "
                        "wire from sensor eye)\n");
}

TEST_CASE("robotsim test: an input's failure names the stimulus or the rule that set it", "[testrun][input-causes]") {
  const TempDir dir;
  dir.write("s.stim", "at 0.5 input 2 on\nwhen output 1 on then input 3 on after 0.2\n");
  const std::string program = dir.write("stim.rsp",
                                        "; test: stimuli s.stim\n"            // 1
                                        "; expect: input 2 off at 0.7\n"      // 2
                                        "; expect: input 3 off during 0..1\n" // 3
                                        "; expect: input 2 off\n"             // 4
                                        "; expect: input 4 on\n"              // 5
                                        "        OUTSIG 1 ON\n"               // 6
                                        "        DELAY 1\n"                   // 7
                                        "        END\n");                     // 8
  const CliResult r = runCli({"test", program});
  CHECK(r.code == 1);
  checkHas(r, program + ":2:3: error: expected input 2 OFF at 0.700 s; it was ON then (line 7 running; ON since 0.500 s: "
                        "stimulus, line 1)\n");
  checkHas(r, program + ":3:3: error: expected input 3 OFF during 0.000..1.000 s; it was ON at 0.200 s (line 7 running; ON "
                        "since 0.200 s: rule of line 2)\n");
  checkHas(r, program + ":4:3: error: expected input 2 OFF at the end; it is ON at line 8, 1.000 s (since 0.500 s: "
                        "stimulus, line 1)\n");
  // Nothing changed input 4: no cause to give.
  checkHas(r, program + ":5:3: error: expected input 4 ON at the end; it is OFF at line 8, 1.000 s\n");
}
