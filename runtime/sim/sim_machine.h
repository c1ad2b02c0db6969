// The simulated machine: motors that move at their configured speeds (and
// accelerations: runtime/sim/motion.h) on the cell's virtual clock
// (runtime/cell/scheduler.h), eight outputs, and eight inputs driven by the stimuli.
// Deterministic: the same calls with the same stimuli give the same results
// on every run. Time is integer microseconds and only moves forward.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "runtime/cell/scheduler.h"
#include "runtime/sim/input_schedule.h"
#include "runtime/sim/motion.h"
#include "compiler/stimuli/stimuli.h"
#include "vm/image.h"
#include "vm/machine.h"

namespace rs::runtime {

/// Three accumulated camera values (WINDOW shift, VIEW rotation).
struct CameraTriple {
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  bool operator==(const CameraTriple&) const = default;
};

class SimMachine final : public vm::Machine {
 public:
  /// Motors start at encoder 0, outputs and inputs OFF, the clock at 0
  /// (stimuli due at time 0 have already applied).
  SimMachine(std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli);
  /// The same on a cell's clock (which must outlive the machine): its
  /// moves and delays advance it, and whatever else the cell scheduled
  /// happens during them. Without one the machine is a cell of one robot
  /// and makes that cell's clock itself.
  SimMachine(std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli, Scheduler& clock);

  /// From here on a move, a DELAY or a WAITFOR that must wait answers
  /// NotYet (vm::Status::notYet) instead of moving the clock: the
  /// scheduler moves it, and `resume` finishes the call once the clock has
  /// reached its end (for a WAITFOR, once the input reads as asked).
  void waitOnScheduler(bool on) { cooperative_ = on; }
  /// Waiting on the scheduler, a move or a DELAY with nothing else due in
  /// the cell by its end finishes at once, the clock moved to its end, as
  /// a robot alone does: nothing else acts meanwhile, so nothing could tell
  /// (the same bytes out), and a plain run does not pay a round trip through
  /// the scheduler for each move. For a robot whose cell has no other
  /// robot (Run sets it). A straight line's knots always wait: the debugger
  /// and a pause slice a line by its knots.
  void finishAlone(bool on) { finishAlone_ = on; }
  /// The cell's part in it (its devices): `before` is called before it is
  /// decided (they look again at a take or a let-go, which puts an event
  /// on the clock now), `after` once the clock is at the end (the belts'
  /// parts are where they are then), as the robot's wake on the clock does.
  void onFinishAlone(std::function<void()> before, std::function<void()> after) {
    aloneBefore_ = std::move(before), aloneAfter_ = std::move(after);
  }
  bool waitsOnScheduler() const { return cooperative_; }
  vm::Status resume() override;
  /// The scheduler rules on the wait under way: the next `resume` answers
  /// `status` (a WAITFOR nothing can satisfy: waitDeadlock(); a fault of
  /// the cell's clock) and the wait is over.
  void endWait(vm::Status status);
  /// A WAITFOR under way that nothing scheduled will satisfy: the Deadlock
  /// a machine running alone answers (the same words).
  vm::Status waitDeadlock() const;
  /// The input a WAITFOR under way waits on (0: none), and for which value.
  int waitingInput() const { return waitInput_; }
  bool waitingOn() const { return waitOn_; }
  /// Called with (output, on) after an output changes (the devices read outputs).
  /// `listener` answers whether the change may turn an input at this same
  /// instant (a wire from the output with no AFTER): on a cell's scheduler
  /// the OUTSIG then waits for the instant's rounds, so that the robot's
  /// next read of that input sees it (docs/language.md).
  void onOutputChange(std::function<bool(int, bool)> listener) { outputListener_ = std::move(listener); }
  /// Input `input` turns `on` now because of `cause` (a wire): the stimuli
  /// due by now apply first, the listeners hear it. False out of range.
  bool setInputBy(int input, bool on, const InputCause& cause);

  /// Every motor moves at once, each with its own profile (motion.h);
  /// returns when the slowest arrives. Fault (no motion) on a wrong target count, a target
  /// outside a motor's range or a clock overflow.
  vm::Status moveTo(std::span<const std::int32_t> targets) override;
  /// Every motor at a constant rate, all arriving together when the
  /// slowest at full speed can (lockStepTime), the `lead` motors a count
  /// ahead (MotorSegment::lead); the same faults as moveTo.
  vm::Status moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) override;
  /// The line's lock-step moves are kept from here until the next move of
  /// another kind, so that positionAt answers inside any of them.
  void beginPath() override;
  std::span<const std::int32_t> positions() const override { return positions_; }

  /// When the output changes state, the rules for it schedule their inputs;
  /// Fault when a rule would leave more than kMaxPendingReactive changes
  /// waiting (an output switched faster than the rule's delay).
  vm::Status setOutput(int output, bool on) override;
  bool input(int input) override;
  /// Advances the clock to the first time the input reads `on`; Deadlock if
  /// no pending change ever makes it so (no output changes while waiting).
  vm::Status waitFor(int input, bool on) override;
  vm::Status delay(vm::Micros duration) override;

  /// moveTo(all zeros), at motor speed.
  vm::Status hardHome() override;
  /// Every motor back to encoder 0 instantly; outputs, inputs and the clock
  /// are unchanged.
  vm::Status reset() override;

  /// Shift the workcell by (x, y, z): adds to the previous shifts.
  void window(std::int32_t x, std::int32_t y, std::int32_t z) override;
  /// Rotate the workcell by (x, y, z) degrees: adds up, kept in 0..359.
  void view(std::int32_t x, std::int32_t y, std::int32_t z) override;

  /// Input `input` (1..vm::kIoCount) turns `on` now, as a timed stimulus at the
  /// present time would (after the changes already due now): what a
  /// debugger's `set input` does. Changes still to come may turn it back.
  /// False when the input is out of range or the schedule is full.
  bool setInputNow(int input, bool on);

  vm::Micros now() const override { return clock_->now(); }
  /// The clock the machine runs on.
  const Scheduler& clock() const { return *clock_; }
  /// Every moveLockStep made so far.
  std::uint64_t knots() const override { return knots_; }
  /// The wires that changed an input at this instant (kMaxStillWires at most).
  std::string stillReason() const override;
  static constexpr std::size_t kMaxStillWires = 8;
  vm::IoMask outputs() const override { return outputs_; }
  vm::IoMask inputs() const override { return inputs_; }

  const std::vector<vm::MotorSpec>& motors() const { return motors_; }
  /// The latest move of motor `motor` (index in motor-table order).
  const MotorSegment& segment(std::size_t motor) const { return segments_[motor]; }
  /// Encoder position of `motor` at time `t`: runtime::positionAt of its
  /// latest segment, or, inside a straight line, of the line's lock-step
  /// move under way at `t`. Before the segment (or the line) began it
  /// answers its start (older moves are not kept); 0 for a motor index out
  /// of range.
  std::int32_t positionAt(std::size_t motor, vm::Micros t) const;
  /// Appends to `out` everything positionAt answers from, its times
  /// counted from `origin`: the motion from `origin` on is the same
  /// whenever the words are (the motors' specs are the image's, fixed for
  /// a run). False (nothing appended) for a line of more than
  /// kMotionKeyKnots knots: too long a key to be worth keeping.
  bool motionKey(vm::Micros origin, std::vector<std::uint64_t>& out) const;
  static constexpr std::size_t kMotionKeyKnots = 64;
  /// Encoder counts `motor` covers from t0 to t1 (t0 <= t1) as positionAt
  /// has it: each knot of a line moves one way, so the counts between the
  /// knots' starts, added up (a motor may turn back from knot to knot).
  std::int64_t coveredBetween(std::size_t motor, vm::Micros t0, vm::Micros t1) const;

  CameraTriple windowShift() const { return windowShift_; }
  CameraTriple viewRotation() const { return viewRotation_; }

  /// Called with (time, inputs after) whenever the input mask changes, at
  /// the time of the stimulus (which may fall inside a move or a DELAY).
  void onInputChange(std::function<void(vm::Micros, vm::IoMask)> listener) { inputListener_ = std::move(listener); }
  /// Called with (time, what changed which input and why) for the same
  /// changes, after onInputChange's listener.
  void onInputCause(std::function<void(vm::Micros, const InputCause&)> listener) { causeListener_ = std::move(listener); }
  /// Called after every move (and RESET) the machine makes, with its
  /// segments set: a straight line makes many within one instruction.
  void onMove(std::function<void()> listener) { moveListener_ = std::move(listener); }
  /// Called as a move begins, with the time it ends (its motors' segments
  /// are set, so positionAt answers for any moment of it): what the cell's
  /// sensors need to see the robot on the way (runtime/cell/robot_sight.h).
  void onMoveBegun(std::function<void(vm::Micros)> listener) { moveBegunListener_ = std::move(listener); }

  /// Everything that changes during a run, for snapshots.
  struct State {
    std::vector<std::int32_t> positions;
    std::vector<MotorSegment> segments;
    std::vector<MotorSegment> path;  ///< the line's lock-step moves, knot by knot (motors() each)
    vm::Micros now = 0;
    std::uint64_t knots = 0;
    vm::IoMask outputs = 0, inputs = 0;
    CameraTriple windowShift, viewRotation;
    InputSchedule::State schedule;
    /// A call begun that waits (waitOnScheduler): until when, or for which input.
    vm::Micros waitUntil = 0;
    int waitInput = 0;
    bool waitOn = false, waitMove = false;
    /// The wires that changed an input at `wiresAt` (stillReason).
    vm::Micros wiresAt = -1;
    std::vector<InputCause> instantWires;
    bool operator==(const State&) const = default;
  };
  State state() const;
  void restore(const State& state);

 private:
  SimMachine(std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli, std::unique_ptr<Scheduler> own,
             Scheduler* clock);
  vm::Status checkTargets(std::span<const std::int32_t> targets) const;
  vm::Micros travelTime(std::size_t motor, std::int32_t target) const;
  /// The clock moves by `duration`, or, waiting on the scheduler, the
  /// call answers NotYet until then (`move`: a move's listener is told at its end).
  vm::Status advanceBy(vm::Micros duration, bool move = false, bool knot = false);
  vm::Status waitForInput(int input, bool on);
  vm::Status fireRules(int output, bool on);
  void applyInputs();
  void noteWire(const InputCause& cause);

  std::vector<vm::MotorSpec> motors_;
  std::vector<stimuli::ReactiveRule> rules_;
  InputSchedule schedule_;
  std::vector<std::int32_t> positions_;
  std::vector<std::int32_t> home_;  // all zeros, for hardHome()
  std::vector<MotorSegment> segments_;
  // The current straight line's lock-step moves, knot-major (beginPath);
  // cleared, its capacity kept, by the next line or any other move.
  std::vector<MotorSegment> path_;
  std::unique_ptr<Scheduler> ownClock_;  // a robot alone: its cell of one's clock
  Scheduler* clock_ = nullptr;
  bool cooperative_ = false;
  bool finishAlone_ = false;
  std::function<void()> aloneBefore_, aloneAfter_;
  /// A wait to `until` that finishes alone now (finishAlone).
  bool finishesAlone(vm::Micros until, bool knot);
  vm::Micros waitUntil_ = 0;  // the wait begun (State::waitUntil, ...)
  int waitInput_ = 0;
  bool waitOn_ = false, waitMove_ = false;
  std::uint64_t knots_ = 0;
  vm::IoMask outputs_ = 0;
  vm::IoMask inputs_ = 0;
  vm::Micros wiresAt_ = -1;
  std::vector<InputCause> instantWires_;
  CameraTriple windowShift_;
  CameraTriple viewRotation_;
  std::function<void(vm::Micros, vm::IoMask)> inputListener_;
  std::function<void(vm::Micros, const InputCause&)> causeListener_;
  std::function<void()> moveListener_;
  std::function<void(vm::Micros)> moveBegunListener_;
  std::function<bool(int, bool)> outputListener_;
  std::optional<vm::Status> endWait_;  // not state: set and used between two calls
};

}  // namespace rs::runtime
