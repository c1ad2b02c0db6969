// A robotsim process for tests of the servers that talk on standard input
// and output (robotsim lsp, robotsim dap): started with a pipe on each (its
// standard error to /dev/null), and its exit awaited with a deadline.
#pragma once

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>
#include "tests/support/build_facts.h"

extern char** environ;

namespace rstest {

struct PipedProcess {
  pid_t pid = -1;
  int in = -1;   // its standard input, ours to write
  int out = -1;  // its standard output, ours to read
};

/// this build's robotsim with `args` after it.
inline PipedProcess spawnRobotsim(std::vector<std::string> args) {
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
  args.insert(args.begin(), rs::testing::robotsimBinary());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  PipedProcess p;
  REQUIRE(posix_spawn(&p.pid, argv[0], &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  close(toChild[0]);
  close(fromChild[1]);
  p.in = toChild[1];
  p.out = fromChild[0];
  return p;
}

/// The process's wait status within `seconds`, or -1 (then it is killed).
inline int waitForExit(pid_t pid, double seconds) {
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

}  // namespace rstest
