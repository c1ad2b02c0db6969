// Ctrl-C during a serial run. While an InterruptGuard lives, SIGINT only
// raises a flag: the Rhino machine sees it within one poll, sends stop to
// every motor and ends the run with "interrupted (Ctrl-C)". A second Ctrl-C
// (the program is busy without talking to the controller, or stuck) writes
// the prepared stop bytes straight to the port from the handler and exits
// with status 130. The previous handler is restored when the guard goes.
#pragma once

#include <atomic>
#include <string>

namespace rs::rhino {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// What a second Ctrl-C writes to `fd` before exiting (at most 255 bytes),
  /// until this guard goes. Each guard keeps its own: a cell run's
  /// controllers, one guard each, are all stopped (at most kStopSlots).
  void setEmergencyStop(int fd, const std::string& bytes);
  static constexpr int kStopSlots = 16;
  /// Set once SIGINT arrived.
  const std::atomic<bool>& flag() const;
  /// Clears the flag (tests).
  void clear();

 private:
  int slot_ = -1;  // this guard's emergency stop, once set
};

}  // namespace rs::rhino
