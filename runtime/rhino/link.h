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

/// What one read or write did.
struct IoResult {
  enum class Kind : std::uint8_t {
    Ok,       // `count` bytes moved (a read returns at least one)
    Timeout,  // nothing arrived (or could be written) in time
    Closed,   // the other end went away: hang-up, device unplugged
    Error,    // any other system error; `message` says which
  };
  Kind kind = Kind::Ok;
  std::size_t count = 0;
  std::string message;

  static IoResult ok(std::size_t n) { return {Kind::Ok, n, {}}; }
  static IoResult timeout() { return {Kind::Timeout, 0, {}}; }
  static IoResult closed(std::string m) { return {Kind::Closed, 0, std::move(m)}; }
  static IoResult error(std::string m) { return {Kind::Error, 0, std::move(m)}; }
  explicit operator bool() const { return kind == Kind::Ok; }
};

/// A byte channel to a controller. Not thread-safe; one user at a time.
class Link {
 public:
  virtual ~Link() = default;
  /// Writes every byte or fails; waits at most `timeout` for room.
  virtual IoResult write(std::span<const std::uint8_t> bytes, Micros timeout) = 0;
  /// Reads what has arrived, up to `buffer.size()` bytes; waits at most
  /// `timeout` for the first byte. A zero timeout only looks.
  virtual IoResult read(std::span<std::uint8_t> buffer, Micros timeout) = 0;
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
