// --max-errors and long lines, through the whole command: a program full of
// errors prints at most N diagnostics (50 by default) and then how many more
// there were, each under an excerpt of its line, so the output stays small
// whatever the input. Sizes are asserted, never times: the benchmark
// `robotsim_bench --only errors` times the same inputs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

// One line of 10,000,003 bytes: END, then `errors` stray characters ('@' and
// '+' without digits, alternately), each padded with blanks to 100 bytes.
std::string oneLineOfErrors(std::size_t errors) {
  std::string text = "END";
  text.reserve(3 + errors * 100 + 1);
  for (std::size_t i = 0; i < errors; ++i) {
    text += i % 2 ? " +" : " @";
    text.append(98, ' ');
  }
  return text + "\n";
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

std::size_t longestLine(const std::string& text) {
  std::size_t longest = 0, start = 0;
  for (std::size_t nl = text.find('\n'); nl != std::string::npos; start = nl + 1, nl = text.find('\n', start))
    longest = std::max(longest, nl - start);
  return longest;
}

}  // namespace

TEST_CASE("cli: a 10 MB line with 100,000 errors prints 50 of them and the count of the rest", "[cli]") {
  constexpr std::size_t kErrors = 100'000;
  TempDir dir;
  const std::string text = oneLineOfErrors(kErrors);
  REQUIRE(text.size() == 10'000'004);
  const std::string path = dir.write("errors.rsp", text);
  const std::string note = "robotsim: note: " + std::to_string(kErrors - 50) +
                           " more errors not shown; --max-errors 0 shows all\n";
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"check", path},
           {"run", path},
           {"compile", path, "-o", dir.file("out.rsb")},
           {"disasm", path},
           {"tokens", path},
           {"ast", path}}) {
    INFO(args[0]);
    const CliResult r = runCli(args);
    CHECK(r.code == 2);
    CHECK(r.err.size() < 16 * 1024);
    CHECK(count(r.err, ": error: ") == 50);
    CHECK(r.err.ends_with(note));
    // Each source line shown is an excerpt: "…", 100 columns, "…".
    CHECK(longestLine(r.err) < 120 * 3);
    CHECK(count(r.err, "errors.rsp:1:") == 50);
  }
  // The last one shown is the 50th by position.
  const CliResult r = runCli({"check", path});
  CHECK(r.err.find("errors.rsp:1:4905: error: a sign must be followed by digits, found '+'\n") != std::string::npos);
  CHECK(r.err.find("errors.rsp:1:5005:") == std::string::npos);
}

TEST_CASE("cli: --max-errors N shows N, 0 shows all", "[cli]") {
  TempDir dir;
  // 7 errors on 7 lines.
  const std::string path = dir.write("seven.rsp", "FOO\nFOO\nFOO\nOUTSIG 9 ON\nFOO\nFOO\nGOTO 99\nEND\n");
  const CliResult three = runCli({"check", path, "--max-errors", "3"});
  CHECK(three.code == 2);
  CHECK(count(three.err, ": error: ") == 3);
  CHECK(three.err.find("seven.rsp:3:1:") != std::string::npos);
  CHECK(three.err.find("seven.rsp:4:") == std::string::npos);
  CHECK(three.err.ends_with("robotsim: note: 4 more errors not shown; --max-errors 0 shows all\n"));
  const CliResult six = runCli({"compile", path, "-o", dir.file("x.rsb"), "--max-errors", "6"});
  CHECK(count(six.err, ": error: ") == 6);
  CHECK(six.err.ends_with("robotsim: note: 1 more error not shown; --max-errors 0 shows all\n"));
  for (const char* n : {"0", "7"}) {
    const CliResult all = runCli({"check", path, "--max-errors", n});
    CHECK(count(all.err, ": error: ") == 7);
    CHECK(all.err.find("note:") == std::string::npos);
  }
  const CliResult tokens = runCli({"tokens", dir.write("bad.rsp", "END @ @ @\n"), "--max-errors", "1"});
  CHECK(count(tokens.err, ": error: ") == 1);
  CHECK(tokens.err.ends_with("robotsim: note: 2 more errors not shown; --max-errors 0 shows all\n"));
  CHECK(runCli({"check", path, "--max-errors", "-1"}).code == 2);  // not a count
}

TEST_CASE("cli: warnings count against --max-errors too", "[cli]") {
  TempDir dir;
  // Three variables only read: three warnings, no error.
  const std::string path = dir.write("w.rsp", "JMPVAR A = 1 4\nJMPVAR B = 1 4\nJMPVAR C = 1 4\nEND\n");
  const CliResult r = runCli({"check", path, "--max-errors", "1"});
  CHECK(r.code == 0);
  CHECK(count(r.err, ": warning: ") == 1);
  CHECK(r.err.ends_with("robotsim: note: 2 more warnings not shown; --max-errors 0 shows all\n"));
  // --strict makes them errors, those not shown included.
  const CliResult strict = runCli({"check", path, "--strict", "--max-errors", "1"});
  CHECK(strict.code == 2);
  CHECK(strict.err.ends_with("robotsim: note: 2 more errors not shown; --max-errors 0 shows all\n"));
  // Errors and warnings together: the first by position is shown.
  const CliResult both =
      runCli({"check", dir.write("e.rsp", "JMPVAR A = 1 4\nJMPVAR B = 1 4\nGOTO 99\nEND\n"), "--max-errors", "1"});
  CHECK(both.code == 2);
  CHECK(count(both.err, "e.rsp:1:8: warning: variable 'A' is never assigned") == 1);
  CHECK(count(both.err, "e.rsp:") == 1);
  CHECK(both.err.ends_with("robotsim: note: 1 more error and 1 warning not shown; --max-errors 0 shows all\n"));
}

TEST_CASE("cli: --format=json lists at most --max-errors diagnostics and counts the rest", "[cli]") {
  TempDir dir;
  const std::string path = dir.write("seven.rsp", "FOO\nFOO\nFOO\nOUTSIG 9 ON\nFOO\nFOO\nGOTO 99\nEND\n");
  const CliResult r = runCli({"check", path, "--format=json", "--max-errors", "2"});
  CHECK(r.code == 2);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["diagnostics"].size() == 2);
  CHECK(j["diagnostics_not_listed"] == nlohmann::json({{"errors", 5}, {"warnings", 0}}));
  const CliResult all = runCli({"check", path, "--format=json", "--max-errors", "0"});
  const nlohmann::json k = nlohmann::json::parse(all.out);
  CHECK(k["diagnostics"].size() == 7);
  CHECK(!k.contains("diagnostics_not_listed"));
}
