// The number of inputs and outputs is vm::kIoCount (vm/io_lines.h), and
// every reader of a line number says so from it: the last line is taken,
// the one after it is refused with the range in the message. Written from
// the constant, so a count changed in one place only (a literal 8 left in a
// reader) fails here: the expectations of `robotsim test`, the teach
// pendant, the emulator's console and its help.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "diag/source_file.h"
#include "tests/cli/cli_support.h"
#include "tests/teach/gantry_pendant.h"
#include "tools/testrun/expectation.h"
#include "vm/io_lines.h"

namespace {

constexpr int kLast = rs::vm::kIoCount, kPast = rs::vm::kIoCount + 1;

std::vector<std::string> expectationErrors(const std::string& text) {
  const rs::testrun::ParsedExpectations p = rs::testrun::parseExpectations(rs::diag::SourceFile("t.rsp", text));
  std::vector<std::string> out;
  for (const rs::diag::Diagnostic& d : p.errors) out.push_back(d.message);
  return out;
}

}  // namespace

TEST_CASE("io count: expectations take input and output 1..kIoCount", "[testrun][io]") {
  CHECK(expectationErrors(fmt::format("; expect: input {0} on\n; expect: output {0} off\n"
                                      "; expect: output {0} on before input {0} on\n",
                                      kLast))
            .empty());
  CHECK(expectationErrors(fmt::format("; expect: input {} on\n", kPast)) ==
        std::vector<std::string>{fmt::format("expected an input number (1..{}), got '{}'", kLast, kPast)});
  CHECK(expectationErrors(fmt::format("; expect: output 1 on before output {} on\n", kPast)) ==
        std::vector<std::string>{fmt::format("expected an output number (1..{}), got '{}'", kLast, kPast)});
}

TEST_CASE("io count: the pendant switches inputs and outputs 1..kIoCount", "[teach][io]") {
  rs::testing::GantryPendant f("p.rsp", "        END\n");
  rs::teach::Pendant& p = *f.pendant;
  REQUIRE(p.toggleInput(kLast).ok);
  CHECK(rs::vm::lineIsOn(p.state().inputs, kLast));
  REQUIRE(p.setOutput(kLast, true).ok);
  CHECK(rs::vm::lineIsOn(p.state().outputs, kLast));
  const rs::teach::Outcome in = p.toggleInput(kPast), out = p.setOutput(kPast, true);
  CHECK_FALSE(in.ok);
  CHECK(in.message == fmt::format("inputs are 1..{}, not {}", kLast, kPast));
  CHECK_FALSE(out.ok);
  CHECK(out.message == fmt::format("outputs are 1..{}, not {}", kLast, kPast));
}

TEST_CASE("io count: the emulator's console sets inputs 1..kIoCount, and its help says so", "[serial][io]") {
  rs::testing::TempDir dir;
  const std::string script =
      dir.write("in.txt", fmt::format("in {} on\nin {} on\nin 0 on\nin x on\nquit\n", kLast, kPast));
  const rs::testing::CliResult r = rs::testing::runCli({"emulate", "--no-stdin", "--script", script, "--duration", "5"});
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains(fmt::format("input {} ON\n", kLast)));
  CHECK_THAT(r.out, Catch::Contains(fmt::format("{}:2: in N on|off: N is an input 1..{}, not '{}'", script, kLast, kPast)));
  CHECK_THAT(r.out, Catch::Contains(fmt::format("{}:3: in N on|off: N is an input 1..{}, not '0'", script, kLast)));
  CHECK_THAT(r.out, Catch::Contains(fmt::format("{}:4: in N on|off: N is an input 1..{}, not 'x'", script, kLast)));
  // The status line's lamps: only the last input on.
  CHECK_THAT(r.out, Catch::Contains(fmt::format("in {}{}", std::string(kLast - 1, '.'), kLast % 10)));
  const rs::testing::CliResult help = rs::testing::runCli({"emulate", "--help"});
  CHECK_THAT(help.out, Catch::Contains(fmt::format("in N on|off              set input N (1..{})\n", kLast)));
}
