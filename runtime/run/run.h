// A run of a program: the one place where an image, its workcell, the input
// stimuli, the limits, a machine and the observers are put together. It can
// run to the end, step, run until an instruction, a source line, a
// simulated time or a condition, pause (also when asked from another
// thread) and go on, and hand out what a debugger, a test runner or a
// teach pendant needs to look at. On the simulated machine its whole state
// can be saved and put back (snapshot/restore): the same run goes on the
// same way, byte for byte.
//
//   Run run({image, cell, stimuli, limits});
//   run.observe(trace);
//   vm::RunOutcome outcome = run.runToEnd();
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/model.h"
#include "runtime/sim/cell_machine.h"
#include "runtime/sim/collision_watch.h"
#include "runtime/run/run_log.h"
#include "runtime/sim/sim_machine.h"
#include "compiler/stimuli/stimuli.h"
#include "runtime/sim/world.h"
#include "vm/image.h"
#include "vm/interpreter.h"

namespace rs::runtime {

/// What a run is made of.
struct RunSpec {
  std::shared_ptr<const vm::Image> image;          ///< verified (vm::verify)
  std::shared_ptr<const workcell::Workcell> cell;  ///< may be null; its first robot runs the program
  stimuli::Stimuli stimuli;
  vm::RunLimits limits;
  bool log = false;  ///< keep a RunLog (simulated machine only)
  /// On a workcell, on the simulated machine: what a collision during a
  /// move does (runtime/sim/collision_watch.h); a run with Off checks nothing.
  CollisionMode collisions = CollisionMode::Error;
};

/// Where a run pauses. Unset conditions cost nothing.
struct RunUntil {
  std::uint64_t steps = UINT64_MAX;        ///< total instructions executed reaches this
  vm::Micros time = INT64_MAX;             ///< the clock passes this (vm::PausePoints::afterTime)
  std::vector<std::uint32_t> instructions;  ///< before one of these runs (0-based), not the first
  std::vector<std::uint32_t> lines;         ///< before the first instruction of one of these source lines
  std::function<bool(const class Run&)> when;  ///< after a step, when this says so
};

/// Why a run paused (when its outcome is vm::StopReason::Paused).
enum class PauseCause : std::uint8_t { None, Steps, Time, Instruction, Condition, Requested };

/// A call frame as a debugger shows it: the GOSUB that made it.
struct CallFrame {
  std::uint32_t gosub = 0;   ///< 0-based instruction of the GOSUB
  std::uint32_t line = 0;    ///< its source line
};

/// An object of the workcell at the run's moment.
struct ObjectView {
  std::string_view name;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< F_world_design
  Eigen::Vector3d at = Eigen::Vector3d::Zero();            ///< its AT corner in the world
  bool held = false;                                       ///< by the gripper of the robot that runs the program
  bool moved = false;                                      ///< away from where the cell placed it
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
  std::uint8_t inputs = 0, outputs = 0;     ///< bit 0 = line 1
  std::vector<ObjectView> objects;
  const RunLog* events = nullptr;  ///< everything so far, when the run keeps a log
};

/// Everything that changes in a run on the simulated machine.
struct RunSnapshot {
  vm::InterpreterState vm;
  SimMachine::State machine;
  std::optional<World::State> world;
  std::optional<RunLog::Mark> log;
  /// Every collision found so far (in error mode one at most): restoring
  /// puts them back, whether the run is behind or ahead of the snapshot.
  /// What else the swept check keeps is a cache (runtime/sim/sweep_memo.h).
  std::vector<CollisionEvent> collisions;
  bool operator==(const RunSnapshot&) const = default;
};

class Run {
 public:
  /// On the simulated machine, with the spec's stimuli.
  explicit Run(RunSpec spec);
  /// On another machine (a real controller): no snapshots, no log; the
  /// spec's stimuli are not used.
  Run(RunSpec spec, std::unique_ptr<vm::Machine> machine);
  /// The same on a machine the caller keeps (it must outlive the run).
  Run(RunSpec spec, vm::Machine& machine);
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;
  ~Run();

  /// Called after every step, in the order added (after the world has
  /// reacted and the log has the step). Must outlive the run.
  void observe(vm::StepObserver& observer);

  /// Runs until the program ends, fails or hits a limit (or a pause is
  /// requested). The outcome's reason is Paused when it did not finish.
  vm::RunOutcome runToEnd() { return runUntil({}); }
  /// Runs `n` instructions (fewer if the run finishes).
  vm::RunOutcome step(std::uint64_t n = 1);
  vm::RunOutcome runUntil(const RunUntil& until);
  vm::RunOutcome runUntilTime(vm::Micros t);
  vm::RunOutcome runUntilLine(std::uint32_t line);
  /// Before the instruction a label names (as the source spells it, any
  /// case); nullopt, without running, when the program has no such label.
  std::optional<vm::RunOutcome> runUntilLabel(std::string_view label);
  /// The instruction a label names, any case.
  std::optional<std::uint32_t> labelInstruction(std::string_view label) const;
  /// Why the last call paused.
  PauseCause pauseCause() const { return cause_; }
  /// Makes a running call pause soon (from any thread).
  void requestPause() { pauseRequested_.store(true, std::memory_order_relaxed); }

  bool finished() const { return interpreter_->finished(); }
  /// How the run finished (empty while it can go on).
  std::optional<vm::RunOutcome> outcome() const;

  RunView view() const;
  vm::Micros clock() const { return machine().now(); }
  std::span<const std::int32_t> motors() const { return machine().positions(); }
  /// Every motor at time `t`, between the start of the last step and now
  /// (SimMachine::positionAt: a move in progress at t); now's on another machine.
  std::vector<std::int32_t> motorsAt(vm::Micros t) const;
  std::optional<std::array<double, 3>> tcp() const;
  std::vector<ObjectView> objects(vm::Micros at = INT64_MAX) const;
  /// The take or let-go of the step just run, or null (what a trace shows
  /// beside the step; right after a restore, null).
  const GraspEvent* graspOfLastStep() const { return lastStepGrasped_ ? &world_->lastEvent() : nullptr; }
  /// A closing move of the step just run that took nothing, or null.
  const EmptyClose* emptyCloseOfLastStep() const { return lastStepClosedEmpty_ ? &world_->lastEmptyClose() : nullptr; }
  /// The instruction of the first closing move that took nothing, and
  /// where it left the tool centre point.
  std::optional<std::pair<std::uint32_t, EmptyClose>> firstEmptyClose() const { return firstEmptyClose_; }
  /// Every collision found so far (in warn mode, every one; in error mode,
  /// the one that stopped the run), each with its instruction.
  std::span<const CollisionEvent> collisions() const;
  /// The collision checker, or null when the run checks none (no
  /// workcell, not simulated, or CollisionMode::Off).
  const CollisionWatch* collisionWatch() const { return watch_ ? &*watch_ : nullptr; }

  /// Input `input` turns `on` now (SimMachine::setInputNow; the log hears
  /// of it). False on a real machine or for an input outside 1..8.
  bool setInput(int input, bool on) { return sim_ && sim_->setInputNow(input, on); }
  /// Calls `listener` with (time, inputs after) whenever the simulated
  /// machine's inputs change, at the stimulus's time, which may fall inside
  /// a move or a DELAY (after the log, when kept, has heard of it): what a
  /// checker that keeps no log needs. False, and never called, on another
  /// machine.
  bool onInputChange(std::function<void(vm::Micros, std::uint8_t)> listener);

  bool canSnapshot() const { return sim_ != nullptr; }
  /// The whole state (the simulated machine only: check canSnapshot()).
  RunSnapshot snapshot() const;
  /// Back to a snapshot of this run; it then goes on exactly as it did.
  void restore(const RunSnapshot& snapshot);

  const vm::Image& image() const { return *spec_.image; }
  const workcell::Workcell* cell() const { return spec_.cell.get(); }
  const vm::RunLimits& limits() const { return spec_.limits; }
  const stimuli::Stimuli& stimuli() const { return spec_.stimuli; }
  const vm::Interpreter& interpreter() const { return *interpreter_; }
  /// The machine the program drives (with the world's reactions, on a cell).
  const vm::Machine& machine() const { return *front_; }
  vm::Machine& machine() { return *front_; }
  /// The simulated machine, or null on a real one.
  const SimMachine* sim() const { return sim_; }
  /// The world, or null without a workcell.
  const World* world() const { return world_ ? &*world_ : nullptr; }
  /// The log, or null when the spec did not ask for one.
  const RunLog* log() const { return logger_ ? &logger_->log() : nullptr; }

 private:
  class Observers;
  void build(vm::Machine& motion);
  PauseCause causeOf(const vm::RunOutcome& outcome, const RunUntil& until, std::uint64_t sliceEnd) const;

  RunSpec spec_;
  std::unique_ptr<vm::Machine> motion_;   // moves the motors, when the run owns them
  SimMachine* sim_ = nullptr;             // motion_, when simulated
  std::optional<World> world_;
  std::optional<CellMachine> cellMachine_;
  vm::Machine* front_ = nullptr;          // what the interpreter drives
  std::optional<RunLogger> logger_;
  std::unique_ptr<vm::Interpreter> interpreter_;
  std::unique_ptr<Observers> observers_;
  std::vector<std::uint8_t> breakpoints_;  // scratch for RunUntil's instructions and lines
  std::uint64_t graspEventsSeen_ = 0;  // the world's event count before the step being run
  bool lastStepGrasped_ = false;
  std::uint64_t emptyClosesSeen_ = 0;
  bool lastStepClosedEmpty_ = false;
  std::optional<std::pair<std::uint32_t, EmptyClose>> firstEmptyClose_;
  std::optional<CollisionWatch> watch_;
  void noteCollisions(std::uint32_t instruction);
  std::vector<std::function<void(vm::Micros, std::uint8_t)>> inputListeners_;
  std::atomic<bool> pauseRequested_ = false;
  PauseCause cause_ = PauseCause::None;
};

}  // namespace rs::runtime
