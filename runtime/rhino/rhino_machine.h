// The Machine that drives a real Rhino controller in lock-step: each motion
// instruction is sent and the VM waits until the controller reports it done;
// positions() then holds the encoder counts the controller reported (Mark IV
// reads them back, Mark III tracks them from the steps it reports done).
// Safety first: every target is checked against the motor's encoder range
// (and what the protocol can carry) before a byte is sent; any failure of
// the controller sends stop to every motor and ends the run, and every call
// after that fails at once without touching the line.
//
// Time: now() is the real time elapsed since open(), read from the Clock
// (tests pass a manual clock): a move takes what the robot took, DELAY waits
// for real. docs/serial.md, "Time".
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/rhino/link.h"
#include "runtime/rhino/serial_log.h"
#include "runtime/rhino/controller_session.h"
#include "runtime/rhino/settings.h"
#include "vm/image.h"
#include "vm/machine.h"

namespace rs::rhino {

/// Where a run that ended in a controller failure left the robot, as far as
/// the host knows: for each motor the last position the controller
/// confirmed and the last one the program commanded (they differ for a
/// motor that was moving, or had a move sent, when the controller failed:
/// it may be anywhere between them), and the outputs last set ON.
struct FaultState {
  struct Motor {
    char letter = 0;
    std::int32_t confirmed = 0;
    std::int32_t commanded = 0;
    bool uncertain() const { return confirmed != commanded; }
  };
  std::vector<Motor> motors;
  vm::IoMask outputsOn = 0;
  std::string failure;
};

class RhinoMachine final : public vm::Machine {
 public:
  /// `link`, `clock`, `log` and `interrupt` must outlive the machine (or be
  /// handed to keepAlive); `log` and `interrupt` may be null.
  RhinoMachine(std::vector<vm::MotorSpec> motors, RhinoSettings settings, Link& link, Clock& clock,
               SerialLog* log = nullptr, const std::atomic<bool>* interrupt = nullptr);
  ~RhinoMachine() override;

  /// First contact; a run may start only when this is Ok. Starts the clock.
  vm::Status open();
  /// WAITFOR gives up (Deadlock) once now() passes this; default 1 hour.
  void setWaitLimit(Micros limit) { waitLimit_ = limit; }
  /// The machine owns `thing` from now on (the port, the log, ...); owned
  /// things go after everything that uses them.
  void keepAlive(std::shared_ptr<void> thing) { owned_.push_back(std::move(thing)); }

  vm::Status moveTo(std::span<const std::int32_t> targets) override;
  /// One small move of a straight line: sent as a move like any other, each
  /// motor at the speed the controller gives it (the controllers have no
  /// command that makes motors arrive together: docs/serial.md, "Straight
  /// lines").
  vm::Status moveLockStep(std::span<const std::int32_t> targets, std::uint32_t /*lead*/) override {
    return moveTo(targets);
  }
  std::span<const std::int32_t> positions() const override { return positions_; }
  vm::Status setOutput(int output, bool on) override;
  bool input(int input) override;
  vm::Status waitFor(int input, bool on) override;
  vm::Status delay(vm::Micros duration) override;
  /// Each motor homed against its switch (Mark III: one at a time, as the
  /// protocol notes describe; Mark IV: HH).
  vm::Status hardHome() override;
  /// Drives every motor back to where open() found it (a real arm cannot
  /// jump): takes the time the move takes.
  vm::Status reset() override;
  /// The controller's encoder counts become positions() (a teach pendant's
  /// "read position"); a Mark III cannot report them and keeps the tracked ones.
  vm::Status readPositions();
  /// Whether the controller can report its encoder counts (Mark IV).
  bool reportsPositions() const { return settings_.dialect == Dialect::Mark4; }
  void window(std::int32_t, std::int32_t, std::int32_t) override {}
  void view(std::int32_t, std::int32_t, std::int32_t) override {}
  vm::Micros now() const override;
  vm::IoMask outputs() const override { return outputs_; }
  vm::IoMask inputs() const override { return inputs_; }

  const std::vector<vm::MotorSpec>& motors() const { return motors_; }
  /// The fault that stopped the machine ("" while it is healthy).
  const std::string& failure() const { return failure_; }
  /// After a failure: what is known and what is not; nullopt while healthy.
  std::optional<FaultState> faultState() const;
  /// After open() failed: how to get past it, when the machine can tell
  /// ("the controller answers as a Mark IV: run with --dialect mark4"), else "".
  const std::string& openHint() const { return openHint_; }

 private:
  vm::Status fail(vm::Status status);
  vm::Status ready();
  vm::Status readInputs();
  std::string probeOtherDialect();

  std::vector<std::shared_ptr<void>> owned_;  // first member: destroyed last
  std::vector<vm::MotorSpec> motors_;
  RhinoSettings settings_;
  Clock& clock_;
  SerialLog* log_;
  ControllerSession session_;
  std::unique_ptr<Controller> controller_;
  std::vector<std::int32_t> positions_;
  std::vector<std::int32_t> start_;
  std::vector<std::int32_t> commanded_;  // the last targets sent (a move's, or 0 for HRDHOME)
  Micros origin_ = 0;
  Micros waitLimit_ = Micros{3600} * 1'000'000;
  vm::IoMask outputs_ = 0;
  vm::IoMask written_ = 0;  // outputs written at least once
  vm::IoMask inputs_ = 0;
  bool opened_ = false;
  std::string failure_;
  std::string openHint_;
};

}  // namespace rs::rhino
