// `robotsim test` keeps what its expectations need, not the run: a program
// of 100,000,000 instructions, whose expectations look at moments, windows,
// pulses, an order and a motor's bound all through the run, is tested by a
// `robotsim test` process whose peak memory stays under 100 MB (it reached
// 3.55 GB when every step was logged). Release only: scripts/test.sh skips
// it under the sanitizers, whose shadow memory and slower run say nothing
// of robotsim's own use.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/support/measured_process.h"

TEST_CASE("robotsim test: a 100,000,000-instruction program stays under 100 MB", "[testrun][memory]") {
  const rs::testing::TempDir dir;
  // 20,000,000 rounds of 5 instructions, 1 ms each: the default step
  // limit of 100,000,000 ends the run at the last GOTO, at 20,000 s. Round
  // i (from 1) adds 1 to N at (i - 1) ms and pulses output 1; input 1 comes
  // ON at 5 s. By hand: N = 10,001 at 10 s (the round starting at 10,000
  // ms), 20,000,000 pulses, input 1 ON first at 5 s, long after output 1
  // (at 0 s), and output 2 never.
  const std::string program = dir.write("long.rsp",
                                        "; test: input 1=ON@5\n"
                                        "; test: max-time 30000\n"
                                        "; expect: step limit\n"
                                        "; expect: variable N = 10001 at 10\n"
                                        "; expect: variable N = 1 during 0..0.001\n"
                                        "; expect: output 1 pulses 20000000 times\n"
                                        "; expect: output 1 on before input 1 on\n"
                                        "; expect: input 1 off during 0..5\n"
                                        "; expect: output 2 off during 0..30\n"
                                        "; expect: motor E never above 0\n"
                                        "; expect: time = 20000\n"
                                        "LOOP:   ADD N 1\n"
                                        "        OUTSIG 1 ON\n"
                                        "        OUTSIG 1 OFF\n"
                                        "        DELAY 0.001\n"
                                        "        GOTO LOOP\n");
  const std::string out = dir.file("out.txt");
  const rstest::Measured m = rstest::runMeasured({"test", program}, out);
  const std::string text = rs::testing::readBytes(out);
  INFO(text);
  REQUIRE(WIFEXITED(m.status));
  CHECK(WEXITSTATUS(m.status) == 0);
  CHECK(text.find(program + " PASSED (9 expectations, 20000.000 s simulated)") != std::string::npos);
  INFO("peak " << m.peakKiB << " KiB");
  CHECK(m.peakKiB > 0);
  CHECK(m.peakKiB < 100 * 1000);  // 100 MB
}
