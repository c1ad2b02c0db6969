// The robotsim lsp process itself: a client that goes away while the
// server writes (EPIPE) or that closes its end (EOF) makes it exit cleanly
// with 1, never a signal or a hang.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/piped_process.h"
#include "tools/lsp/jsonrpc.h"
#include "tools/lsp/server.h"

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

TEST_CASE("robotsim lsp: serverInfo.version is the build's version, as robotsim --version prints it",
          "[lsp][process]") {
  // The version read independently, from CMakeLists.txt's project() line.
  std::ifstream cmake(std::string(ROBOTSIM_SOURCE_DIR) + "/CMakeLists.txt");
  const std::string text((std::istreambuf_iterator<char>(cmake)), std::istreambuf_iterator<char>());
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex(R"(project\(robotsim VERSION ([0-9.]+))")));
  rstest::PipedProcess c = rstest::spawnRobotsim({"lsp", "--stdio"});
  writeAll(c.in, kInitialize + rs::lsp::frameMessage(R"({"jsonrpc":"2.0","id":2,"method":"shutdown"})") +
                     rs::lsp::frameMessage(R"({"jsonrpc":"2.0","method":"exit"})"));
  close(c.in);
  std::string reply;
  char buffer[4096];
  for (ssize_t n; (n = read(c.out, buffer, sizeof buffer)) > 0;) reply.append(buffer, static_cast<std::size_t>(n));
  close(c.out);
  REQUIRE(rstest::waitForExit(c.pid, 20) != -1);
  CHECK(reply.find(R"("serverInfo":{"name":"robotsim","version":")" + m[1].str() + "\"") != std::string::npos);

  // In process: whatever version the server is given, and none when it is given none.
  std::ostringstream log;
  for (const std::string version : {"9.8.7", ""}) {
    std::string answer;
    rs::lsp::Server server([&](const rs::lsp::Json& message) { answer = message.dump(); return true; }, log, version);
    rs::lsp::FrameParser parser;
    parser.feed(kInitialize);
    std::vector<rs::lsp::Frame> frames;
    while (std::optional<rs::lsp::Frame> f = parser.next()) frames.push_back(std::move(*f));
    server.receive(frames);
    CHECK(answer.find(R"("serverInfo":{"name":"robotsim")") != std::string::npos);
    CHECK((answer.find("\"version\":\"9.8.7\"") != std::string::npos) == !version.empty());
  }
}
