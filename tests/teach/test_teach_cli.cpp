// robotsim teach on the command line, run in-process: what it refuses
// before it serves (exit 2, a diagnostic naming the problem), --listen's
// syntax, and its --help. Serving itself is tested end to end by
// tests/browser/teach_test.mjs (it runs until Ctrl-C).
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/teach_command.h"

using rs::testing::runCli;

TEST_CASE("robotsim teach: refuses what it cannot teach, before serving", "[teach]") {
  const rs::testing::TempDir dir;
  const std::string prog = dir.write("p.rsp", "        END\n");
  auto r = runCli({"teach", prog});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--cell: error: teach needs a workcell to move the robot in"));
  CHECK_THAT(r.err, Catch::Contains("hint: name one with --cell"));
  r = runCli({"teach", dir.file("missing.rsp"), "--cell", "scara-pick"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("cannot read"));
  r = runCli({"teach", prog, "--cell", "no-such-cell"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("no-such-cell"));
  const std::string image = dir.file("p.rsb");
  REQUIRE(runCli({"compile", prog, "-o", image}).code == 0);
  r = runCli({"teach", image, "--cell", "scara-pick"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("teach edits a program's source: this is a compiled image"));
  r = runCli({"teach", prog, "--cell", "scara-pick", "--listen", "127.0.0.1:http"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--listen: error: '127.0.0.1:http' is not HOST or HOST:PORT"));
  r = runCli({"teach", prog, "--cell", "scara-pick", "--dialect", "mark4"});
  CHECK(r.code == 2);  // --dialect needs --device
}

TEST_CASE("robotsim teach: --listen's HOST[:PORT] and what counts as loopback", "[teach]") {
  std::string host;
  int port = -1;
  CHECK(rs::cli::parseListen("0.0.0.0", host, port));
  CHECK((host == "0.0.0.0" && port == 0));
  CHECK(rs::cli::parseListen("192.168.1.5:8080", host, port));
  CHECK((host == "192.168.1.5" && port == 8080));
  CHECK(rs::cli::parseListen("[::1]:9000", host, port));
  CHECK((host == "::1" && port == 9000));
  CHECK(rs::cli::parseListen("::", host, port));
  CHECK((host == "::" && port == 0));
  for (const char* bad : {"", ":80", "host:", "host:65536", "host:-1", "[::1", "[::1]x", "h:8x"}) {
    INFO(bad);
    CHECK_FALSE(rs::cli::parseListen(bad, host, port));
  }
  CHECK(rs::cli::isLoopback("127.0.0.1"));
  CHECK(rs::cli::isLoopback("127.1.2.3"));
  CHECK(rs::cli::isLoopback("::1"));
  CHECK(rs::cli::isLoopback("localhost"));
  CHECK_FALSE(rs::cli::isLoopback("0.0.0.0"));
  CHECK_FALSE(rs::cli::isLoopback("10.0.0.1"));
}

TEST_CASE("robotsim teach --help explains the command and each option", "[teach]") {
  const auto r = runCli({"teach", "--help"});
  CHECK(r.code == 0);
  for (const char* part : {"--cell", "--device", "--dialect", "--open", "--listen", "token", "Ctrl-C", "PROG.rsp.bak",
                           "docs/teach.md"})
    CHECK_THAT(r.out, Catch::Contains(part));
  CHECK_THAT(runCli({"--help"}).out, Catch::Contains("teach"));
}
