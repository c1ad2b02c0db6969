// One conversation with a controller: send a command line, ask a question
// and check the answer, wait while watching for Ctrl-C. Every way the
// controller can fail (silence, garbage, hang-up) comes back as a Fault
// status with a message that names the command; the caller stops the
// motors. Nothing is retried.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/rhino/link.h"
#include "runtime/rhino/serial_log.h"
#include "runtime/rhino/settings.h"
#include "vm/image.h"
#include "vm/machine.h"

namespace rs::rhino {

class ControllerSession {
 public:
  /// `log` and `interrupt` may be null. All must outlive the session.
  ControllerSession(Link& link, Clock& clock, const RhinoSettings& settings, SerialLog* log, const std::atomic<bool>* interrupt)
      : link_(link), clock_(clock), settings_(settings), log_(log), interrupt_(interrupt) {}

  /// Sends `command` and the line end; refuses once Ctrl-C was pressed.
  vm::Status send(std::string_view command);
  /// Sends even after Ctrl-C: for the stop commands.
  vm::Status sendUnchecked(std::string_view command);
  /// Mark III: sends `command`, reads exactly one byte.
  vm::Status queryByte(std::string_view command, std::uint8_t& reply);
  /// Mark IV: sends `command`, reads a decimal number ended by CR.
  vm::Status queryNumber(std::string_view command, long& value);
  /// Sleeps `duration`, in slices, returning early with a Fault on Ctrl-C.
  vm::Status pause(Micros duration);
  /// Fault "interrupted (Ctrl-C)" once the interrupt flag is set.
  vm::Status checkInterrupt() const;

  /// A garbage fault: `command` was answered with `reply`; `expected` says
  /// what a good answer looks like.
  vm::Status garbage(std::string_view command, std::span<const std::uint8_t> reply, std::string_view expected);
  /// Logs "! text" (no-op without a log).
  void note(std::string_view text);

  Micros now() const { return clock_.now(); }
  bool portGone() const { return gone_; }
  /// The last failure was a question that got no answer in time.
  bool lastFailureWasSilence() const { return silent_; }
  const RhinoSettings& settings() const { return settings_; }
  const std::string& device() const { return device_; }
  void setDevice(std::string name) { device_ = std::move(name); }

 private:
  vm::Status ioFailure(const vm::Status& r, std::string_view command, bool writing);
  vm::Status expectQuiet(std::string_view command);
  vm::Status readBy(std::span<std::uint8_t> buffer, Micros deadline, std::size_t& count);

  Link& link_;
  Clock& clock_;
  const RhinoSettings& settings_;
  SerialLog* log_;
  const std::atomic<bool>* interrupt_;
  std::vector<std::uint8_t> unread_;  // bytes that came after a Mark IV answer's CR
  std::string device_ = "the controller";
  bool gone_ = false;
  bool silent_ = false;
};

/// What a dialect does for the machine. Positions are updated in place as
/// the controller reports them, so a failure leaves the last known values.
class Controller {
 public:
  virtual ~Controller() = default;
  /// First contact: checks that the controller answers; may read positions.
  virtual vm::Status begin(std::span<std::int32_t> positions) = 0;
  /// Moves to absolute `targets` and returns once the controller reports
  /// every motor done.
  virtual vm::Status move(std::span<const std::int32_t> targets, std::span<std::int32_t> positions) = 0;
  /// Homes every motor against its switch; positions end at 0.
  virtual vm::Status home(std::span<std::int32_t> positions) = 0;
  virtual vm::Status readInputs(vm::IoMask& mask) = 0;
  /// The controller's encoder counts, where it can report them (Mark IV);
  /// a Mark III has no such query: the counts the host tracked stay.
  virtual vm::Status readPositions(std::span<std::int32_t> positions) = 0;
  /// Output `line` (1..vm::kIoCount) turns `on`; `mask` is every output after the change.
  virtual vm::Status writeOutput(int line, bool on, vm::IoMask mask) = 0;
  /// Sends stop to every motor, whatever state the line is in; returns
  /// what was done, for the error message.
  virtual std::string stopAll() = 0;
  /// What the protocol itself cannot carry ("" when fine); checked before a
  /// byte is sent.
  virtual std::string refuse(std::span<const std::int32_t> targets) const = 0;
};

std::unique_ptr<Controller> makeMark3(ControllerSession& session, const std::vector<vm::MotorSpec>& motors);
std::unique_ptr<Controller> makeMark4(ControllerSession& session, const std::vector<vm::MotorSpec>& motors);

/// The commands that stop every motor, one per line: Mark III "<m>X" for
/// each motor, Mark IV "MA". The one list for stopAll() and for the bytes a
/// second Ctrl-C writes from the signal handler.
std::vector<std::string> stopCommands(Dialect d, const std::vector<vm::MotorSpec>& motors);
/// Sends every stop command, even after Ctrl-C and after a failed one;
/// returns what was done, for the error message (Controller::stopAll).
std::string sendStop(ControllerSession& session, const std::vector<std::string>& commands);
/// "" when every motor is one a Rhino controller has (A..H), else which one
/// is not ("motor Z: a Mark III controller has motors A..H only").
std::string unsupportedMotor(Dialect d, const std::vector<vm::MotorSpec>& motors);

}  // namespace rs::rhino
