// A description reader's memory is a small multiple of its input (issue
// 32): a 59 MB description of comment lines peaked at 1.46 GB, 25 bytes a
// byte, and one of bare ";" lines at 180 bytes a byte, because ANTLR's
// parser kept a rule context, a token and a tree node for every line of
// the whole file. `robotsim check --cell FILE` on 20 MB of each kind of
// line (then a robot, so that the file is read to its end and used) must
// peak under 4 times its size plus 30 MB (the process's own few MiB, the
// program and the run). Release only: scripts/test.sh leaves "peak memory"
// out of the sanitizer run, whose shadow memory is no measure of ours.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/support/measured_process.h"

namespace {

constexpr std::size_t kDescriptionMemoryInput = 20'000'000;

// `line` repeated to 20 MB, then the library's SCARA as a lone robot.
std::string paddedDescription(const std::string& line) {
  std::string text;
  text.reserve(kDescriptionMemoryInput + 4096);
  while (text.size() < kDescriptionMemoryInput) text += line;
  text += rs::testing::readBytes(std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/robots/rhino-scara.rsd");
  return text;
}

}  // namespace

TEST_CASE("description reader: peak memory under 4x a 20 MB input + 30 MB, comment lines or bare ones",
          "[models][memory]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("p.rsp", "        MOVE 10 0 0 0 0\n        END\n");
  for (const std::string& line : {std::string("; a comment line that says nothing, padded out to sixty bytes.\n"),
                                  std::string(";\n"), std::string("\n")}) {
    CAPTURE(line.size());
    const std::string text = paddedDescription(line);
    const std::string cell = dir.write("big.rsd", text);
    const rstest::Measured m = rstest::runMeasured({"check", program, "--cell", cell}, dir.file("out.txt"));
    INFO(rs::testing::readBytes(dir.file("out.txt")));
    REQUIRE(WIFEXITED(m.status));
    CHECK(WEXITSTATUS(m.status) == 0);  // read to its end: the robot after the padding was built
    const long boundKiB = static_cast<long>((4 * text.size() + 30'000'000) / 1024);
    INFO("peak " << m.peakKiB << " KiB for " << text.size() << " bytes; bound " << boundKiB << " KiB");
    CHECK(m.peakKiB > static_cast<long>(text.size() / 1024));  // the file was read whole: the check can fail
    CHECK(m.peakKiB < boundKiB);
  }
}
