// A run of a cell of several robots, each running its own program on the
// cell's one clock (docs/models.md, "Several robots"): the one place where
// such a run is put together. Every robot is a process of one scheduler:
//
//   1. evaluate: each robot, in the cell's order, runs until it waits (a
//      move, a DELAY, a WAITFOR) or ends. What it writes (an output) reaches
//      another robot only through the cell (a wire), in the cell's update
//      phase, so what a robot reads at an instant does not depend on the
//      order the robots ran in;
//   2. the cell acts at now (the devices, the wires), then the clock runs
//      to the next instant something is due (a robot's wait ending, a
//      device's edge), and the robots run again.
//
// The run ends when every program has ended. A runtime error in one robot
// stops the cell (an emergency stop) and names the robot; when every robot
// still running waits on an input nothing can change any more, the run
// stops with one deadlock error naming each of them.
//
// A run can pause (runUntil: after a step a predicate picks, at a count of
// steps of all robots, before the clock passes a time) and go on exactly
// as if it had not: what a debugger of the cell needs.
//
//   CellRun run(spec);
//   run.observe(0, trace);
//   vm::RunOutcome outcome = run.runToEnd();
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/stimuli/stimuli.h"
#include "model/workcell/model.h"
#include "runtime/cell/cell.h"
#include "runtime/cell/devices.h"
#include "runtime/run/run.h"
#include "vm/image.h"
#include "vm/interpreter.h"

namespace rs::runtime {

/// One robot's program in a cell run.
struct CellProgram {
  std::size_t robot = 0;                   ///< its index in Workcell::robots
  std::shared_ptr<const vm::Image> image;  ///< verified, compiled for that robot
  /// A real controller that follows the robot's motions and outputs in
  /// lock-step (followed_machine.h), or null; it must outlive the run.
  vm::Machine* follower = nullptr;
};

/// What a cell run is made of.
struct CellRunSpec {
  std::shared_ptr<const workcell::Workcell> cell;  ///< as loaded (its feeders get their slots here)
  std::vector<CellProgram> programs;               ///< at most one per robot
  /// Every robot's stimuli: a change or rule names its robot by label
  /// (InputChange::robot), empty for the cell's first robot.
  stimuli::Stimuli stimuli;
  vm::RunLimits limits;  ///< per robot; maxTime is the cell's
  CollisionMode collisions = CollisionMode::Error;
  /// Every robot keeps its own RunLog (RunSpec::log, lines): what a still,
  /// a page or a chart of the cell draws each robot from.
  bool log = false;
  LineThinning lines;
};

/// Where a cell run pauses; unset members never pause it.
struct CellUntil {
  std::uint64_t steps = UINT64_MAX;  ///< the instructions of every robot together reach this
  /// Before the clock passes this: every instruction at an instant up to it is done.
  vm::Micros time = INT64_MAX;
  /// After each step of program p, in the cell's order of steps: yes pauses there.
  std::function<bool(const class CellRun&, std::size_t p)> afterStep{};
};

/// How one robot's program finished.
enum class RobotEnd { Running, Finished, Stopped };

class CellRun {
 public:
  /// Check the spec first (checkCellRunSpec): a program for a robot the
  /// cell lacks, or two for one robot, is a programming error here.
  explicit CellRun(CellRunSpec spec);
  CellRun(const CellRun&) = delete;
  CellRun& operator=(const CellRun&) = delete;
  ~CellRun();

  /// Observer `observer` hears every step of program `p` (an index in the
  /// spec's programs); it must outlive the run.
  void observe(std::size_t p, vm::StepObserver& observer) { runs_[p]->observe(observer); }
  /// Runs every program to its end, or until the cell stops. The outcome
  /// is the cell's: ok when every program ended well; else the first
  /// failure (its message names the robot), or the deadlock.
  vm::RunOutcome runToEnd() { return runUntil({}); }
  /// Runs until `until` pauses it (the outcome is Paused) or the cell's run
  /// is over (its outcome, as runToEnd's). Going on after a pause is the
  /// same run as one that never paused.
  vm::RunOutcome runUntil(const CellUntil& until);
  /// The cell's run is over (every program ended, or the cell stopped).
  bool finished() const { return outcome_.has_value(); }
  const std::optional<vm::RunOutcome>& outcome() const { return outcome_; }
  /// The instructions every robot has run, together.
  std::uint64_t steps() const;

  std::size_t size() const { return runs_.size(); }
  const Run& robot(std::size_t p) const { return *runs_[p]; }
  Run& robot(std::size_t p) { return *runs_[p]; }
  /// The robot's label in the cell (AS, or its description's name).
  const std::string& label(std::size_t p) const;
  /// Whether program `p` ran to its end (Finished), was stopped with the
  /// cell (Stopped: another robot failed, or the deadlock), or not yet.
  RobotEnd end(std::size_t p) const { return ends_[p]; }
  /// When program `p` ended or was stopped (the cell's clock now while it runs).
  vm::Micros endTime(std::size_t p) const { return ends_[p] == RobotEnd::Running ? clock() : endAt_[p]; }
  /// The program that stopped the cell (a runtime error), if one did.
  std::optional<std::size_t> failed() const { return failed_; }
  const workcell::Workcell& cell() const { return *cell_; }
  const Cell& running() const { return shared_; }
  const CellDevices* devices() const { return devices_.get(); }
  vm::Micros clock() const { return shared_.clock().now(); }

 private:
  /// Where runUntil goes on: a robot's turn at the instant (Evaluate), or
  /// the cell has acted at the instant and its clock runs on next (Due).
  enum class Phase { Evaluate, Due };
  vm::Status advanceCell(vm::Micros t);
  vm::RunOutcome over(vm::RunOutcome outcome);
  /// Every robot still running waits on an input nothing will change.
  std::string deadlockMessage() const;
  vm::RunOutcome stopAll(std::size_t failed, const vm::RunOutcome& outcome);
  /// The cell stops (a device's fault, the deadlock, the time limit): every robot still running is Stopped.
  vm::RunOutcome cellStops(vm::StopReason reason, std::string message);

  std::shared_ptr<const workcell::Workcell> cell_;  // with its feeders' slots
  Cell shared_;
  std::vector<std::unique_ptr<Run>> runs_;
  std::unique_ptr<CellDevices> devices_;
  std::vector<RobotEnd> ends_;
  std::vector<vm::Micros> endAt_;  // per program: when it ended (meaningful once it has)
  std::size_t lastEnded_ = 0;       // the program that ended last: the last instant's records are its
  std::vector<vm::Micros> wakeAt_;  // per program: its wait under way ends here (kNever: an input)
  std::optional<std::size_t> failed_;
  vm::RunLimits limits_;
  Phase phase_ = Phase::Evaluate;
  std::size_t turn_ = 0;     // Evaluate: the robot whose turn it is at this instant
  bool allForever_ = false;  // Due: every robot still running waits on an input
  std::uint64_t endedSteps_ = 0;  // the steps of the programs that ended
  std::optional<vm::RunOutcome> outcome_;
};

/// The stimuli of robot `robot` of `cell` (its label's, or unlabelled
/// ones for the first robot), with labels dropped. A rule whose output
/// and input name different robots belongs to none: checkCellRunSpec
/// refuses it.
stimuli::Stimuli stimuliOfRobot(const stimuli::Stimuli& all, const workcell::Workcell& cell, std::size_t robot);

/// What is wrong with a cell run's spec, in words (empty: nothing): a
/// program for a robot the cell lacks, two for one robot, a rule between
/// two robots' lines.
std::string checkCellRunSpec(const CellRunSpec& spec);

}  // namespace rs::runtime
