// A run of a program: the one place where an image, its workcell, the input
// stimuli, the limits, a machine and the observers are put together. It can
// run to the end, or until a step count, an instruction, a source line, a
// simulated time or a condition (one RunUntil says which), pause (also when asked from another
// thread) and go on, and hand out what a debugger, a test runner or a
// teach pendant needs to look at. On the simulated machine its whole state
// can be saved and put back (snapshot/restore): the same run goes on the
// same way, byte for byte.
//
//   Run run({image, cell, stimuli, limits});
//   run.observe(trace);
//   vm::RunOutcome outcome = run.runToEnd();
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "compiler/stimuli/stimuli.h"
#include "model/workcell/model.h"
#include "runtime/run/rig.h"
#include "runtime/run/run_log.h"
#include "runtime/sim/collision_watch.h"
#include "vm/image.h"
#include "vm/interpreter.h"

namespace rs::runtime {

/// What a run is made of.
struct RunSpec {
  std::shared_ptr<const vm::Image> image;          ///< verified (vm::verify)
  std::shared_ptr<const workcell::Workcell> cell;  ///< may be null; Workcell::drivenRobot runs the program
  stimuli::Stimuli stimuli;
  vm::RunLimits limits;
  bool log = false;  ///< keep a RunLog (simulated machine only)
  /// How the log keeps straight lines' knots (run_log.h): every one by
  /// default; thinned for a page or a chart of a run of any length.
  LineThinning lines;
  /// On a workcell, on the simulated machine: what a collision during a
  /// move does (runtime/sim/collision_watch.h); a run with Off checks nothing.
  CollisionMode collisions = CollisionMode::Error;
};

/// Where a run pauses. Unset conditions cost nothing.
struct RunUntil {
  std::uint64_t steps = UINT64_MAX;        ///< total instructions executed reaches this
  std::uint64_t moreSteps = UINT64_MAX;    ///< this many instructions run in this call (a step: 1)
  vm::Micros time = INT64_MAX;             ///< the clock passes this (vm::PausePoints::afterTime)
  std::uint64_t knots = UINT64_MAX;        ///< the knots made in all reach this (vm::PausePoints::atKnots)
  // Every member has its initializer, so that `runUntil({.time = t})` names
  // only what it sets (GCC warns of a member left without one).
  std::vector<std::uint32_t> instructions{};  ///< before one of these runs (0-based), not the first
  std::vector<std::uint32_t> lines{};         ///< before the first instruction of one of these source lines
  std::function<bool(const class Run&)> when{};  ///< after a step, when this says so

  /// The total step count at which a call that starts at `now` pauses.
  std::uint64_t stepEnd(std::uint64_t now) const {
    return std::min(steps, now + std::min(moreSteps, UINT64_MAX - now));
  }
};

/// A call frame as a debugger shows it: the GOSUB that made it.
struct CallFrame {
  std::uint32_t gosub = 0;   ///< 0-based instruction of the GOSUB
  std::uint32_t line = 0;    ///< its source line
};

/// A read-only picture of a run at its current moment.
struct RunView {
  vm::Micros clock = 0;
  std::uint64_t steps = 0;
  std::uint32_t instruction = 0;  ///< the next to run (0-based); the last run when finished
  std::uint32_t line = 0;         ///< its source line
  bool finished = false;
  std::optional<vm::RunOutcome> outcome;  ///< when finished
  std::vector<CallFrame> callStack;        ///< outermost first
  std::vector<std::pair<std::string_view, std::int32_t>> variables;  ///< in slot order
  std::vector<std::int32_t> motors;
  std::optional<std::array<double, 3>> tcp;  ///< on a workcell: the tool centre point in the world
  vm::IoMask inputs = 0, outputs = 0;       ///< bit 0 = line 1
  std::vector<ObjectView> objects;
  const RunLog* events = nullptr;  ///< everything so far, when the run keeps a log
};

/// Everything that changes in a run on the simulated machine.
struct RunSnapshot {
  vm::InterpreterState vm;
  RigSnapshot rig;
  std::optional<RunLog::Mark> log;
  bool operator==(const RunSnapshot&) const = default;
};

/// The instruction a label of `image` names (as the source spells it, any
/// case), or nullopt.
std::optional<std::uint32_t> labelInstruction(const vm::Image& image, std::string_view label);

class Run {
 public:
  /// On a simulated rig made of the spec's cell, the image's motors and
  /// the spec's stimuli.
  explicit Run(RunSpec spec);
  /// On another machine (a real controller): no snapshots, no log; the
  /// spec's stimuli are not used.
  Run(RunSpec spec, std::unique_ptr<vm::Machine> machine);
  /// The same on a machine the caller keeps (it must outlive the run).
  Run(RunSpec spec, vm::Machine& machine);
  /// Robot `robot` of a cell run (runtime/run/cell_run.h): simulated, on
  /// `shared`'s clock and world (the spec's cell is the one `shared` was
  /// made of). Its waits return to the caller: runUntil answers an outcome
  /// with `waiting` set, and the cell run moves the clock. Its log (when
  /// the spec asks) keeps this robot's steps, moves and grasps. No
  /// snapshots yet. A `follower` (a real controller, which must outlive
  /// the run) is given the robot's motions and outputs (followed_machine.h).
  Run(RunSpec spec, Cell& shared, std::size_t robot, vm::Machine* follower = nullptr);
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;
  ~Run();

  /// Called after every step, in the order added (after the world has
  /// reacted and the log has the step). Must outlive the run.
  void observe(vm::StepObserver& observer);
  /// Calls `listener` with (time, inputs after) whenever the simulated
  /// machine's inputs change, at the stimulus's time, which may fall inside
  /// a move or a DELAY (after the log, when kept, has heard of it): what a
  /// checker that keeps no log needs. False, and never called, on another
  /// machine.
  bool onInputChange(std::function<void(vm::Micros, vm::IoMask)> listener);

  /// Runs until `until` says to pause, or the program ends, fails or hits
  /// a limit (or a pause is requested): the outcome's reason is Paused
  /// when it did not finish. A step is `runUntil({.moreSteps = 1})`, a
  /// label's place `runUntil({.instructions = {*labelInstruction(...)}})`.
  vm::RunOutcome runUntil(const RunUntil& until);
  vm::RunOutcome runToEnd() { return runUntil({}); }
  /// Why the last call paused (vm/stop_reason.h): Step (RunUntil::steps
  /// or RunUntil::knots), Time, Breakpoint (an instruction or line),
  /// Condition or Pause (asked for); when it did not pause, its outcome's
  /// reason; Paused before any call and after a restore.
  vm::StopReason pauseCause() const { return cause_; }
  /// Makes a running call pause soon (from any thread): after at most a
  /// slice of 2^20 instructions or 2^14 knots, or the instruction under way.
  void requestPause() { pauseRequested_.store(true, std::memory_order_relaxed); }
  /// The knots of straight lines made so far (vm::Machine::knots).
  std::uint64_t knots() const;
  /// How the run finished (empty while it can go on).
  std::optional<vm::RunOutcome> outcome() const;
  bool finished() const { return interpreter_->finished(); }
  /// What the devices did after the last step (at END's instant, in a step
  /// cut short): the log's last step's, and what a trace's finish() shows.
  void takeRecordsAfterEnd();

  /// The run at its current moment, to look at.
  RunView view() const;
  /// What the program runs on: the cell, the machine, the world, the
  /// collisions, the clock, the motors. The program is `spec().image`.
  const Rig& rig() const { return *rig_; }
  Rig& rig() { return *rig_; }
  const RunSpec& spec() const { return spec_; }
  const vm::Interpreter& interpreter() const { return *interpreter_; }
  /// The log, or null when the spec did not ask for one.
  const RunLog* log() const { return logger_ ? &logger_->log() : nullptr; }

  /// The whole state (the simulated machine only: check rig().canSnapshot()).
  RunSnapshot snapshot() const;
  /// Back to a snapshot of this run; it then goes on exactly as it did.
  void restore(const RunSnapshot& snapshot);
  /// A debugger's change between instructions: variable `slot` holds
  /// `value` from now on. False on a finished run or a slot the image lacks.
  bool setVariable(std::uint32_t slot, std::int32_t value);

 private:
  class Observers;
  void build(std::unique_ptr<Rig> rig);
  /// The robot waits (`waiting` said so): the cell's clock runs to its
  /// next instant, or the wait is ruled on (nothing left to happen).
  void waitOnCell(const vm::RunOutcome& waiting);
  std::optional<vm::StopReason> causeOf(const vm::RunOutcome& outcome, const RunUntil& until,
                                        std::uint64_t stepEnd, std::uint64_t sliceEnd,
                                        std::uint64_t sliceKnots) const;

  RunSpec spec_;
  std::unique_ptr<Rig> rig_;
  std::optional<RunLogger> logger_;
  std::unique_ptr<vm::Interpreter> interpreter_;
  std::unique_ptr<Observers> observers_;
  std::vector<std::uint8_t> breakpoints_;  // scratch for RunUntil's instructions and lines
  std::vector<std::function<void(vm::Micros, vm::IoMask)>> inputListeners_;
  std::atomic<bool> pauseRequested_ = false;
  bool inCellRun_ = false;  // a robot of a cell run: a wait returns to it
  vm::StopReason cause_ = vm::StopReason::Paused;
};

}  // namespace rs::runtime
