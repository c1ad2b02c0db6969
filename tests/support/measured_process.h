// A robotsim process whose peak memory a test bounds: this build's robotsim run
// with its output to a file, its high-water mark followed until it ends.
#pragma once

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>
#include "tests/support/build_facts.h"

extern char** environ;

namespace rstest {

/// The high-water mark of a process's resident memory (VmHWM, KiB), or -1
/// once it is gone. Its own, unlike wait4's ru_maxrss, which on Linux also
/// counts the memory of the process that spawned it.
inline long highWaterKiB(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

struct Measured {
  int status = -1;
  long peakKiB = 0;    // its VmHWM, read while it runs
  long rusageKiB = 0;  // wait4's ru_maxrss: the larger of its peak and the spawner's at the spawn
};

/// Runs this build's robotsim with `args` (standard output to `out`, standard
/// error to /dev/null) and follows its peak memory until it ends: the last
/// reading is its peak but for what it took in its last few milliseconds.
/// Killed, and the test failed, after `minutes`.
inline Measured runMeasured(std::vector<std::string> args, const std::string& out, int minutes = 5) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  args.insert(args.begin(), rs::testing::robotsimBinary());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  REQUIRE(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  Measured m;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(minutes);
  rusage usage{};
  while (std::chrono::steady_clock::now() < deadline) {
    m.peakKiB = std::max(m.peakKiB, highWaterKiB(pid));
    if (wait4(pid, &m.status, WNOHANG, &usage) == pid) {
      m.rusageKiB = usage.ru_maxrss;
      return m;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  wait4(pid, &m.status, 0, &usage);
  FAIL("robotsim did not end within " << minutes << " minutes");
  return m;
}

}  // namespace rstest
