#include "runtime/rhino/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

namespace rs::rhino {
namespace {

// Signal handlers can only reach globals. Lock-free atomics and plain
// writes of fixed buffers are async-signal-safe.
std::atomic<bool> gInterrupted{false};
std::atomic<int> gStopFd{-1};
char gStopBytes[256];
std::atomic<std::size_t> gStopLength{0};
struct sigaction gPrevious;
int gDepth = 0;  // guards alive; only the outermost installs

static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onInterrupt(int) {
  if (!gInterrupted.exchange(true)) return;
  static const char stopped[] = "\nrobotsim: interrupted twice: stop written to the controller, exiting\n";
  static const char plain[] = "\nrobotsim: interrupted twice, exiting\n";
  const int fd = gStopFd.load();
  if (fd >= 0) {
    const ssize_t ignored = ::write(fd, gStopBytes, gStopLength.load());
    (void)ignored;
  }
  const ssize_t ignored =
      fd >= 0 ? ::write(STDERR_FILENO, stopped, sizeof stopped - 1) : ::write(STDERR_FILENO, plain, sizeof plain - 1);
  (void)ignored;
  ::_exit(130);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  if (gDepth++ > 0) return;
  gInterrupted = false;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a blocked poll() returns at once
  ::sigaction(SIGINT, &action, &gPrevious);
}

InterruptGuard::~InterruptGuard() {
  if (--gDepth > 0) return;
  gStopFd = -1;
  ::sigaction(SIGINT, &gPrevious, nullptr);
}

void InterruptGuard::setEmergencyStop(int fd, const std::string& bytes) {
  gStopFd = -1;
  const std::size_t n = std::min(bytes.size(), sizeof gStopBytes);
  std::memcpy(gStopBytes, bytes.data(), n);
  gStopLength = n;
  gStopFd = fd;
}

const std::atomic<bool>& InterruptGuard::flag() const { return gInterrupted; }

void InterruptGuard::clear() { gInterrupted = false; }

}  // namespace rs::rhino
