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
// One emergency stop a guard that set one: its port and the bytes for it.
struct StopSlot {
  std::atomic<int> fd{-1};
  char bytes[256];
  std::atomic<std::size_t> length{0};
};
StopSlot gStops[InterruptGuard::kStopSlots];
struct sigaction gPrevious;
int gDepth = 0;  // guards alive; only the outermost installs

static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onInterrupt(int) {
  if (!gInterrupted.exchange(true)) return;
  static const char stopped[] = "\nrobotsim: interrupted twice: stop written to the controller, exiting\n";
  static const char plain[] = "\nrobotsim: interrupted twice, exiting\n";
  bool wrote = false;
  for (StopSlot& slot : gStops) {
    const int fd = slot.fd.load();
    if (fd < 0) continue;
    const ssize_t ignored = ::write(fd, slot.bytes, slot.length.load());
    (void)ignored;
    wrote = true;
  }
  const ssize_t ignored =
      wrote ? ::write(STDERR_FILENO, stopped, sizeof stopped - 1) : ::write(STDERR_FILENO, plain, sizeof plain - 1);
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
  if (slot_ >= 0) gStops[slot_].fd = -1;  // its port closes after this
  if (--gDepth > 0) return;
  ::sigaction(SIGINT, &gPrevious, nullptr);
}

void InterruptGuard::setEmergencyStop(int fd, const std::string& bytes) {
  for (int k = 0; slot_ < 0 && k < kStopSlots; ++k)
    if (gStops[k].fd.load() < 0) slot_ = k;
  if (slot_ < 0) return;  // more controllers than slots: the first ones are stopped
  StopSlot& slot = gStops[slot_];
  slot.fd = -1;  // the handler never writes half-copied bytes
  const std::size_t n = std::min(bytes.size(), sizeof slot.bytes);
  std::memcpy(slot.bytes, bytes.data(), n);
  slot.length = n;
  slot.fd = fd;
}

const std::atomic<bool>& InterruptGuard::flag() const { return gInterrupted; }

void InterruptGuard::clear() { gInterrupted = false; }

}  // namespace rs::rhino
