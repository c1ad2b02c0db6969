#include "base/removed_on_signal.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>

namespace rs::base {

namespace {

// A slot is free (0), being filled or emptied (1), or names a file the
// handler removes (2). The handler reads only slots it sees at 2.
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
struct Slot {
  std::atomic<int> state{0};
  char path[kPathBytes] = {};
};
static_assert(std::atomic<int>::is_always_lock_free);
Slot gSlots[kSlots];

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Taking and giving back slots, installing and removing the handler: never
// in the handler itself.
std::mutex gMutex;
int gLive = 0;

extern "C" void removeTemporariesAndEnd(int sig) {
  const int saved = errno;
  for (Slot& s : gSlots)
    if (s.state.load(std::memory_order_acquire) == 2) ::unlink(s.path);
  // The default disposition, then the signal again: it is delivered once
  // this handler returns (it is blocked until then) and ends the process.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
  errno = saved;
}

bool ours(const struct sigaction& a) {
  return (a.sa_flags & SA_SIGINFO) == 0 && a.sa_handler == removeTemporariesAndEnd;
}

// Only over the default: a handler or SIG_IGN someone set stays theirs.
void install() {
  for (const int sig : kSignals) {
    struct sigaction current {};
    if (::sigaction(sig, nullptr, &current) != 0 || (current.sa_flags & SA_SIGINFO) != 0 ||
        current.sa_handler != SIG_DFL)
      continue;
    struct sigaction action {};
    action.sa_handler = removeTemporariesAndEnd;
    sigemptyset(&action.sa_mask);
    for (const int other : kSignals) sigaddset(&action.sa_mask, other);
    ::sigaction(sig, &action, nullptr);
  }
}

// Once no temporary is left: the default again where ours still stands,
// so that handlers installed later never see ours as one to chain to.
void uninstall() {
  for (const int sig : kSignals) {
    struct sigaction current {};
    if (::sigaction(sig, nullptr, &current) != 0 || !ours(current)) continue;
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    ::sigaction(sig, &action, nullptr);
  }
}

}  // namespace

RemovedOnSignal::RemovedOnSignal(const std::string& path) {
  if (path.empty() || path.size() >= kPathBytes || path.find('\0') != std::string::npos) return;
  const std::lock_guard<std::mutex> lock(gMutex);
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!gSlots[i].state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) continue;
    std::memcpy(gSlots[i].path, path.c_str(), path.size() + 1);
    gSlots[i].state.store(2, std::memory_order_release);
    slot_ = i;
    if (++gLive == 1) install();
    return;
  }
}

void RemovedOnSignal::release() {
  if (slot_ < 0) return;
  const std::lock_guard<std::mutex> lock(gMutex);
  gSlots[slot_].state.store(0, std::memory_order_release);
  slot_ = -1;
  if (--gLive == 0) uninstall();
}

}  // namespace rs::base
