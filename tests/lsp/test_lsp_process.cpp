// The robotsim lsp process itself: a client that goes away while the
// server writes (EPIPE) or that closes its end (EOF) makes it exit cleanly
// with 1, never a signal or a hang.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "lsp/jsonrpc.h"

extern char** environ;

namespace {

struct Child {
  pid_t pid = -1;
  int in = -1;   // its stdin, ours to write
  int out = -1;  // its stdout, ours to read
};

Child spawnServer() {
  int toChild[2], fromChild[2];
  REQUIRE(pipe(toChild) == 0);
  REQUIRE(pipe(fromChild) == 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, toChild[0], 0);
  posix_spawn_file_actions_adddup2(&actions, fromChild[1], 1);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addclose(&actions, toChild[1]);
  posix_spawn_file_actions_addclose(&actions, fromChild[0]);
  Child c;
  const std::string binary = ROBOTSIM_BINARY;
  char* argv[] = {const_cast<char*>(binary.c_str()), const_cast<char*>("lsp"), const_cast<char*>("--stdio"), nullptr};
  REQUIRE(posix_spawn(&c.pid, binary.c_str(), &actions, nullptr, argv, environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  close(toChild[0]);
  close(fromChild[1]);
  c.in = toChild[1];
  c.out = fromChild[0];
  return c;
}

// The child's exit status within `seconds`, or -1 (then it is killed).
int waitFor(pid_t pid, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

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
  Child c = spawnServer();
  close(c.out);  // nobody reads: the server's first write fails with EPIPE
  writeAll(c.in, kInitialize);
  const int status = waitFor(c.pid, 20);
  close(c.in);
  REQUIRE(status != -1);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
}

TEST_CASE("robotsim lsp: EOF on stdin without shutdown exits 1, after shutdown and exit, 0", "[lsp][process]") {
  {
    Child c = spawnServer();
    writeAll(c.in, kInitialize);
    close(c.in);
    const int status = waitFor(c.pid, 20);
    close(c.out);
    REQUIRE(status != -1);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 1);
  }
  {
    Child c = spawnServer();
    writeAll(c.in, kInitialize + rs::lsp::frameMessage(R"({"jsonrpc":"2.0","id":2,"method":"shutdown"})") +
                       rs::lsp::frameMessage(R"({"jsonrpc":"2.0","method":"exit"})"));
    const int status = waitFor(c.pid, 20);
    close(c.in);
    close(c.out);
    REQUIRE(status != -1);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  }
}
