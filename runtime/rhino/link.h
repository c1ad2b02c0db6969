// The two things the Rhino backend needs from the world: a byte channel to
// the controller (a Link: a serial port, or an in-process emulator in tests)
// and a clock it can read and sleep on (the wall clock, or a manual clock
// that makes test transcripts byte-for-byte repeatable).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "vm/machine.h"

namespace rs::rhino {

using vm::Micros;

/// A byte channel to a controller. Not thread-safe; one user at a time.
/// Each read or write answers the machine's own vm::Status: Ok, Timeout
/// (nothing arrived, or could be written, in time), Closed (the other end
/// went away: hang-up, device unplugged; the message says how) or Fault
/// (any other system error; the message says which). ControllerSession::ioFailure
/// is the one place these become what the run reports.
class Link {
 public:
  virtual ~Link() = default;
  /// Writes every byte or fails; waits at most `timeout` for room.
  virtual vm::Status write(std::span<const std::uint8_t> bytes, Micros timeout) = 0;
  /// Reads what has arrived, up to `buffer.size()` bytes, and sets `count`
  /// (at least one when Ok, else 0); waits at most `timeout` for the first
  /// byte. A zero timeout only looks.
  virtual vm::Status read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) = 0;
  /// A name for messages: the device path, "emulator", ...
  virtual std::string name() const = 0;
};

/// Monotonic time for the backend, and sleeping on it.
class Clock {
 public:
  virtual ~Clock() = default;
  virtual Micros now() const = 0;
  virtual void sleepFor(Micros duration) = 0;
};

/// std::chrono::steady_clock in microseconds (its own epoch): the one
/// reading of the wall clock, for SteadyClock and the port's deadlines.
std::int64_t steadyMicros();

/// The wall clock (std::chrono::steady_clock), zero when it was made.
class SteadyClock final : public Clock {
 public:
  SteadyClock();
  Micros now() const override;
  void sleepFor(Micros duration) override;

 private:
  std::int64_t origin_;  // steady_clock ticks in microseconds
};

/// A clock that only moves when told: sleepFor() advances it at once.
class ManualClock final : public Clock {
 public:
  Micros now() const override { return now_; }
  void sleepFor(Micros duration) override {
    if (duration > 0) now_ += duration;
  }
  void advanceTo(Micros t) {
    if (t > now_) now_ = t;
  }

 private:
  Micros now_ = 0;
};

}  // namespace rs::rhino
