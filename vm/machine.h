// The machine the VM drives. The VM only ever talks to this interface: the
// simulated machine (runtime/), a real controller behind a serial line and
// recorders all sit behind it. Calls return a Status instead of throwing, so
// a slow or failing controller is an ordinary outcome, not an exception.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace rs::vm {

/// Virtual time in microseconds since the start of the run.
using Micros = std::int64_t;

struct Status {
  enum class Code : std::uint8_t {
    Ok,
    Deadlock,   // a wait that nothing will ever satisfy
    Fault,      // the machine failed (limit, controller error, ...)
  };
  Code code = Code::Ok;
  std::string message;

  static Status ok() { return {}; }
  static Status deadlock(std::string m) { return {Code::Deadlock, std::move(m)}; }
  static Status fault(std::string m) { return {Code::Fault, std::move(m)}; }
  explicit operator bool() const { return code == Code::Ok; }
};

class Machine {
 public:
  virtual ~Machine() = default;

  /// Moves every motor to an absolute encoder target and returns once the
  /// last motor has arrived. Targets were already checked against the ranges.
  virtual Status moveTo(std::span<const std::int32_t> targets) = 0;
  /// Current encoder position of every motor, in motor-table order.
  virtual std::span<const std::int32_t> positions() const = 0;

  virtual Status setOutput(int output, bool on) = 0;  // output 1..8
  virtual bool input(int input) = 0;                   // input 1..8, now
  /// Returns once input `input` reads `on`; Deadlock if it never will.
  virtual Status waitFor(int input, bool on) = 0;
  virtual Status delay(Micros duration) = 0;

  /// Moves every motor to encoder 0 (HRDHOME). A real controller homes each
  /// motor against its switch; the simulation moves there at motor speed.
  virtual Status hardHome() = 0;

  /// Robot (and objects) back to where the run started; takes no time.
  virtual Status reset() = 0;

  virtual void window(std::int32_t x, std::int32_t y, std::int32_t z) = 0;
  virtual void view(std::int32_t x, std::int32_t y, std::int32_t z) = 0;

  virtual Micros now() const = 0;
  /// Outputs and inputs as bit masks, bit 0 = line 1.
  virtual std::uint8_t outputs() const = 0;
  virtual std::uint8_t inputs() const = 0;
};

}  // namespace rs::vm
