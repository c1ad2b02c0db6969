// The robotsim lsp process itself: a client that goes away while the
// server writes (EPIPE) or that closes its end (EOF) makes it exit cleanly
// with 1, never a signal or a hang.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <string>

#include "tests/support/piped_process.h"
#include "tools/lsp/jsonrpc.h"

namespace {

void writeAll(int fd, const std::string& bytes) {
  signal(SIGPIPE, SIG_IGN);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

const std::string kInitialize = rs::lsp::frameMessage(R"({"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}})");

}  // namespace

TEST_CASE("robotsim lsp: EPIPE on stdout (the client closed its end) exits 1", "[lsp][process]") {
  rstest::PipedProcess c = rstest::spawnRobotsim({"lsp", "--stdio"});
  close(c.out);  // nobody reads: the server's first write fails with EPIPE
  writeAll(c.in, kInitialize);
  const int status = rstest::waitForExit(c.pid, 20);
  close(c.in);
  REQUIRE(status != -1);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
}

TEST_CASE("robotsim lsp: EOF on stdin without shutdown exits 1, after shutdown and exit, 0", "[lsp][process]") {
  {
    rstest::PipedProcess c = rstest::spawnRobotsim({"lsp", "--stdio"});
    writeAll(c.in, kInitialize);
    close(c.in);
    const int status = rstest::waitForExit(c.pid, 20);
    close(c.out);
    REQUIRE(status != -1);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 1);
  }
  {
    rstest::PipedProcess c = rstest::spawnRobotsim({"lsp", "--stdio"});
    writeAll(c.in, kInitialize + rs::lsp::frameMessage(R"({"jsonrpc":"2.0","id":2,"method":"shutdown"})") +
                       rs::lsp::frameMessage(R"({"jsonrpc":"2.0","method":"exit"})"));
    const int status = rstest::waitForExit(c.pid, 20);
    close(c.in);
    close(c.out);
    REQUIRE(status != -1);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  }
}
