// The machine the VM drives. The VM only ever talks to this interface: the
// simulated machine (runtime/), a real controller behind a serial line and
// recorders all sit behind it. Calls return a Status instead of throwing, so
// a slow or failing controller is an ordinary outcome, not an exception.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "vm/io_lines.h"

namespace rs::vm {

/// Virtual time in microseconds since the start of the run.
using Micros = std::int64_t;

/// What a machine call did, and what one read or write of the serial line
/// to a controller did (runtime/rhino's Link): one status for both, since
/// the line's failures become the machine's. A machine call answers Ok,
/// Deadlock or Fault, and a machine on a cell's scheduler NotYet; Timeout
/// and Closed are the line's own, which
/// rhino::ControllerSession turns into a Fault that says what the line was doing.
struct Status {
  enum class Code : std::uint8_t {
    Ok,
    Deadlock,  // a wait that nothing will ever satisfy
    NotYet,    // a wait has begun and ends later: the scheduler, not the machine, decides what runs meanwhile
    Fault,     // the machine failed (limit, controller error, a system error on the line, ...)
    Timeout,   // the line: nothing arrived (or could be written) in time
    Closed,    // the line: the other end went away (hang-up, device unplugged)
  };
  Code code = Code::Ok;
  std::string message;
  /// NotYet: the time the wait ends at the earliest (kNever: when an input
  /// changes, which the machine cannot foresee).
  std::int64_t until = 0;
  static constexpr std::int64_t kNever = INT64_MAX;

  static Status ok() { return {}; }
  static Status deadlock(std::string m) { return {Code::Deadlock, std::move(m)}; }
  static Status fault(std::string m) { return {Code::Fault, std::move(m)}; }
  static Status timeout() { return {Code::Timeout, {}}; }
  static Status closed(std::string m) { return {Code::Closed, std::move(m)}; }
  static Status notYet(std::int64_t until) { return {Code::NotYet, {}, until}; }
  bool notYet() const { return code == Code::NotYet; }
  explicit operator bool() const { return code == Code::Ok; }
};

class Machine {
 public:
  virtual ~Machine() = default;

  /// Moves every motor to an absolute encoder target and returns once the
  /// last motor has arrived. Targets were already checked against the ranges.
  virtual Status moveTo(std::span<const std::int32_t> targets) = 0;
  /// Moves every motor in lock-step to `targets` (one small move of a
  /// straight line): all start now, each at a constant rate, and all
  /// arrive together, as soon as the slowest motor at its full speed can.
  /// A motor whose bit is set in `lead` (bit 0 = the first motor) takes
  /// each whole count as soon as it is begun, the others when it is
  /// finished: the motors that carry the tool forward along the line step
  /// ahead, the others behind, so the tool never falls back along it (a
  /// block lifted off a pallet does not dip into it). Targets were already
  /// checked against the ranges.
  virtual Status moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) = 0;
  /// The lock-step moves of one straight line follow: a machine that can
  /// answer where a motor was at an earlier moment of the line (the
  /// simulated one, for a debugger stopped inside it) keeps them from here.
  virtual void beginPath() {}
  /// MOVES: the tool centre point along a straight line to the pose that
  /// `targets` put it at (APPRO, DEPART: `distance` length units along the
  /// tool's approach axis, back for a negative one). Only a machine that
  /// knows the robot's kinematics can (runtime/sim's CellMachine): the
  /// others answer a Fault.
  virtual Status moveLine(std::span<const std::int32_t> /*targets*/) { return Status::fault(kNeedsKinematics); }
  virtual Status moveAlongTool(std::int32_t /*distance*/) { return Status::fault(kNeedsKinematics); }
  static constexpr const char* kNeedsKinematics =
      "a straight-line move needs the robot's kinematics: run the program on a workcell or robot (--cell)";
  /// Current encoder position of every motor, in motor-table order.
  virtual std::span<const std::int32_t> positions() const = 0;

  virtual Status setOutput(int output, bool on) = 0;  // output 1..kIoCount
  virtual bool input(int input) = 0;                   // input 1..kIoCount, now
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

  /// A call that waits (a move, a delay, a WAITFOR) may answer NotYet on a
  /// machine that runs on a cell's scheduler (SimMachine::waitOnScheduler):
  /// the wait has begun, the clock is the scheduler's to move, and the
  /// interpreter calls `resume` to finish the call once it has (NotYet
  /// again while it still waits). A machine that never says NotYet never
  /// hears `resume`.
  virtual Status resume() { return Status::ok(); }

  virtual Micros now() const = 0;
  /// The lock-step moves (knots) of straight lines made so far: the work a
  /// line costs, which a run's knot limit bounds (vm::RunLimits::maxKnots)
  /// and a debugger's slices count. 0 on a machine that does not count them.
  virtual std::uint64_t knots() const { return 0; }
  /// Why the clock may be standing still now, where the machine knows (on
  /// a cell: the wires that changed its inputs at this instant, which a
  /// program answering its own inputs through them keeps doing): added to
  /// a clock-standing-still stop. Empty when it does not know.
  virtual std::string stillReason() const { return {}; }
  /// Outputs and inputs as bit masks, bit 0 = line 1.
  virtual IoMask outputs() const = 0;
  virtual IoMask inputs() const = 0;
};

}  // namespace rs::vm
