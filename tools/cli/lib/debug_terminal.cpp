#include "tools/cli/lib/debug_terminal.h"

#include <editline/readline.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>

namespace rs::cli {

namespace {

// Shared with the signal handler and libedit's key-reader hook, both plain
// C callbacks: one DebugTerminal lives at a time.
std::atomic<bool> interrupted = false;
int wake[2] = {-1, -1};       // the handler writes, the key reader polls
bool promptInterrupted = false;
struct sigaction previous {};

void onInterrupt(int) {
  const int saved = errno;
  interrupted.store(true);
  const char byte = 1;
  if (wake[1] >= 0 && ::write(wake[1], &byte, 1) < 0) {
    // the pipe is full: the reader is woken already
  }
  errno = saved;
}

void drainWake() {
  char bytes[64];
  while (::read(wake[0], bytes, sizeof bytes) > 0) {
  }
}

// libedit's key reader (rl_getc_function): one byte of the terminal, or
// EOF when Ctrl-C was pressed (before this prompt or during it). Polling
// the terminal and the pipe together leaves no moment where a signal can
// slip in unseen between looking at the flag and waiting for a key.
int readKey(FILE*) {
  for (;;) {
    if (interrupted.exchange(false)) {
      promptInterrupted = true;
      return EOF;
    }
    pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {wake[0], POLLIN, 0}};
    if (::poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return EOF;
    }
    if (fds[1].revents & POLLIN) drainWake();  // the flag, above, says what it was for
    if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    unsigned char key = 0;
    const ssize_t n = ::read(STDIN_FILENO, &key, 1);
    if (n < 0 && errno == EINTR) continue;
    return n == 1 ? key : EOF;
  }
}

}  // namespace

DebugTerminal::DebugTerminal() {
  interrupted.store(false);
  if (::pipe2(wake, O_CLOEXEC | O_NONBLOCK) != 0) wake[0] = wake[1] = -1;
  rl_getc_function = readKey;  // before the first readline(), which installs it
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, &previous);
}

DebugTerminal::~DebugTerminal() {
  ::sigaction(SIGINT, &previous, nullptr);
  for (int& fd : wake) {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
}

bool DebugTerminal::takeInterrupt() { return interrupted.exchange(false); }

TerminalLine DebugTerminal::readLine(const char* prompt) {
  promptInterrupted = false;
  char* raw = readline(prompt);
  if (!raw) {
    // libedit may also give up the line itself when its own handler (it
    // hands the signal on to ours) cuts a read short.
    if (promptInterrupted || takeInterrupt()) return {TerminalLine::Status::Interrupted, {}};
    return {};
  }
  TerminalLine line{TerminalLine::Status::Line, raw};
  std::free(raw);
  if (line.text.find_first_not_of(" \t") != std::string::npos) add_history(line.text.c_str());
  return line;
}

}  // namespace rs::cli
