// robotsim debug at a real terminal (a pseudo-terminal, forkpty): the
// prompt reads lines through libedit, so the arrow keys recall history and
// a backspace edits the line; Ctrl-C at the prompt gives a new prompt and
// in a long run pauses it; quit ends with 0. The batch transcripts cover
// the commands; this covers the prompt around them.
#include <catch2/catch.hpp>

#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "tests/debug/debug_test_util.h"
#include "tests/support/build_facts.h"

namespace {

class Terminal {
 public:
  explicit Terminal(std::vector<std::string> args) {
    winsize size{};
    size.ws_row = 40;
    size.ws_col = 200;
    pid_ = forkpty(&fd_, nullptr, nullptr, &size);
    REQUIRE(pid_ >= 0);
    if (pid_ == 0) {
      setenv("TERM", "xterm", 1);
      setenv("HOME", "/nonexistent", 1);  // no ~/.editrc
      const std::string binary = rs::testing::robotsimBinary();
      args.insert(args.begin(), {binary, "debug"});
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(binary.c_str(), argv.data());
      _exit(127);
    }
  }
  ~Terminal() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (fd_ >= 0) close(fd_);
  }
  void type(const std::string& keys) { REQUIRE(write(fd_, keys.data(), keys.size()) == static_cast<ssize_t>(keys.size())); }
  // Everything printed until `text` appears (after what was read before), or fails after 20 s.
  std::string until(const std::string& text) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (seen_.find(text, from_) == std::string::npos) {
      INFO("waiting for: " << text << "\nthe terminal so far:\n" << seen_);
      REQUIRE(std::chrono::steady_clock::now() < end);
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 100) <= 0) continue;
      char buffer[4096];
      const ssize_t n = read(fd_, buffer, sizeof buffer);
      if (n <= 0) break;
      seen_.append(buffer, static_cast<std::size_t>(n));
    }
    const std::size_t at = seen_.find(text, from_);
    INFO(seen_);
    REQUIRE(at != std::string::npos);
    std::string out = seen_.substr(from_, at + text.size() - from_);
    from_ = at + text.size();
    return out;
  }
  // Waits until the debugger's terminal is in line mode (`cooked`: the
  // prompt is not reading keys) or in libedit's key-by-key mode, as asked.
  // After a line is entered, line mode again says libedit has taken the
  // line and given the terminal back: the command runs.
  void waitForMode(bool cooked) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    for (;;) {
      termios mode{};
      REQUIRE(tcgetattr(fd_, &mode) == 0);  // a pty's master reports its slave's modes
      if (((mode.c_lflag & ICANON) != 0) == cooked) return;
      REQUIRE(std::chrono::steady_clock::now() < end);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  int exitStatus() {
    int status = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (waitpid(pid_, &status, WNOHANG) != pid_) {
      REQUIRE(std::chrono::steady_clock::now() < end);
      char buffer[4096];
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 50) > 0 && read(fd_, buffer, sizeof buffer) <= 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    reaped_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  bool reaped_ = false;
  std::string seen_;
  std::size_t from_ = 0;
};

}  // namespace

TEST_CASE("robotsim debug at a terminal: the prompt, history on the up arrow, a backspace, quit",
          "[debug][terminal]") {
  Terminal t({debugtest::kExamples + "nested_subroutines.rsp"});
  t.until("(rsdb) ");
  t.type("break grip\r");
  CHECK(t.until("(rsdb) ").find("breakpoint 1: label grip, line 38") != std::string::npos);
  t.type("continue\r");
  CHECK(t.until("(rsdb) ").find("step 4, clock 0.500 s") != std::string::npos);
  t.type("\x1b[A\r");  // the up arrow brings back "continue": the second grip
  CHECK(t.until("(rsdb) ").find("step 22, clock 5.700 s") != std::string::npos);
  t.type("print GRIPSX\x7f\r");  // a backspace takes the X away
  CHECK(t.until("(rsdb) ").find("GRIPS = 1") != std::string::npos);
  t.type("quit\r");
  CHECK(t.exitStatus() == 0);
}

TEST_CASE("robotsim debug at a terminal: Ctrl-C at the prompt gives a new prompt",
          "[debug][terminal]") {
  // Waits for ever a millisecond at a time: to the default step limit,
  // 100 million instructions, it would run for seconds.
  Terminal t({rendertest::kSourceDir + "/tests/debug/programs/wait_forever.rsp", "--max-time", "1000000"});
  t.until("(rsdb) ");
  // One Ctrl-C, the moment the prompt shows (libedit may not be reading
  // keys yet): a new prompt, nothing run.
  t.type("\x03");
  t.until("(rsdb) ");
  t.type("print clock\r");
  CHECK(t.until("(rsdb) ").find("clock = 0.000 s (step 0)") != std::string::npos);
  t.type("quit\r");
  CHECK(t.exitStatus() == 0);
}

TEST_CASE("robotsim debug at a terminal: Ctrl-C in a long run pauses it", "[debug][terminal]") {
  Terminal t({rendertest::kSourceDir + "/tests/debug/programs/wait_forever.rsp", "--max-time", "1000000"});
  t.until("(rsdb) ");
  t.waitForMode(false);
  t.type("continue\r");
  // The echo of "continue" is no sign the line was taken: libedit echoes
  // each key as it reads it, and a Ctrl-C before it has read the Enter
  // makes the terminal drop the Enter (SIGINT flushes unread input) and
  // cancels the line, as in a shell; under load that is what happened.
  // Line mode back means libedit has the line: the run begins.
  t.until("continue");
  t.waitForMode(true);
  t.type("\x03");  // once: a Ctrl-C is never lost
  CHECK(t.until("(rsdb) ").find("interrupted") != std::string::npos);
  t.type("print clock\r");
  const std::string clock = t.until("(rsdb) ");
  CHECK(clock.find("clock = 0.000 s") == std::string::npos);  // it ran
  CHECK(clock.find("the run is over") == std::string::npos);
  t.type("quit\r");
  CHECK(t.exitStatus() == 0);
}
