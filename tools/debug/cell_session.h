// A debugging session on a cell of several robots (runtime::CellRun), each
// robot a thread of the session: breakpoints per program (file), a stop
// stops the whole cell, `step` runs the current robot to its next
// instruction while the others go on in time, and reverse-step,
// reverse-next, reverse-continue and goto-time put the whole cell back,
// devices included. Breakpoints at a time, on a condition, at a device's
// event, and watches, look at the cell after every step of any robot.
//
// Going backwards re-runs the cell: it is deterministic, so a fresh run of
// the same spec paused at the same step (counted over all robots, or
// the same robot's Nth) is the same cell. A reverse step costs a run from
// the start to the present (bench/ measures it on the examples).
//
//   CellSession s(spec);
//   s.breakAtLine(s.robotOf("right.rsp"), 7);
//   CellStop stop = s.resume();
//   runtime::RunView v = s.view(stop.robot);
//   stop = s.reverseStep();
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/result.h"
#include "runtime/run/cell_run.h"
#include "tools/debug/debug_session.h"

namespace rs::debug {

/// Why the cell stopped, and which robot (program index) it is about: the
/// one whose step or breakpoint stopped it, or whose error ended it.
struct CellStop {
  StopReason reason = StopReason::Entry;
  std::string message;
  std::size_t robot = 0;
  std::vector<int> breakpoints;
  bool finished() const { return vm::isOver(reason); }
};

/// A breakpoint of the cell: before a line, a label or an instruction of
/// one robot's program (Line, Label, Instruction),
/// as the cell's clock passes a time, as a condition on a robot becomes
/// true, at a device's event; each with a condition and a hit count.
/// `robot` (a program index) is the robot whose program it stands in, or
/// whose values its conditions read (the current one when it was made).
struct CellBreakpoint : Breakpoint {
  std::size_t robot = 0;
};

/// A watch of one robot's value.
struct CellWatch {
  int id = 0;
  std::size_t robot = 0;
  Expression what;
};

class CellSession {
 public:
  /// The cell standing before any robot's first instruction (checked spec: checkCellRunSpec).
  explicit CellSession(runtime::CellRunSpec spec);
  ~CellSession();

  const runtime::CellRun& cell() const { return *run_; }
  std::size_t size() const { return run_->size(); }
  const std::string& label(std::size_t robot) const { return run_->label(robot); }
  /// The robot (program index) `name` names: its label, or its program's
  /// file (as given, or its last part); nullopt when none.
  std::optional<std::size_t> robotNamed(std::string_view name) const;
  /// Robot `robot`'s program file, its last part ("right.rsp"), as messages name it.
  std::string fileName(std::size_t robot) const;

  /// The current robot (the thread the commands that look or step are about).
  std::size_t current() const { return current_; }
  void select(std::size_t robot) { current_ = robot < size() ? robot : current_; }

  /// Robot `robot` at the session's moment: after goto-time, between two
  /// instants, its clock is that time and a move under way is shown there.
  runtime::RunView view(std::size_t robot) const;
  /// The cell's clock at the session's moment.
  vm::Micros clock() const { return at_ ? *at_ : run_->clock(); }
  /// Robot `robot` is in an instruction that has begun and not ended (a move, a DELAY, a WAITFOR).
  bool underWay(std::size_t robot) const;
  const CellStop& lastStop() const { return stop_; }

  // --- breakpoints and watches (one numbering) -------------------------------
  /// Before line `line` of robot `robot`'s program (or the first line with code after it).
  diag::Result<int> breakAtLine(std::size_t robot, std::uint32_t line);
  std::uint32_t lineWithCode(std::size_t robot, std::uint32_t line) const;
  /// Before label `label` (any case) of robot `robot`'s program.
  diag::Result<int> breakAtLabel(std::size_t robot, std::string_view label);
  /// Before instruction `index` (0-based) of robot `robot`'s program.
  diag::Result<int> breakAtInstruction(std::size_t robot, std::uint32_t index);
  /// Right after the cell's clock passes `t` (after the step of any robot that passes it).
  diag::Result<int> breakAtTime(vm::Micros t);
  /// As `condition` on robot `robot` becomes true (after a step of any robot: a wire may turn its input on).
  int breakWhen(std::size_t robot, Condition condition);
  /// After the step of any robot during which a device did what `point` says.
  int breakOnDevice(DevicePoint point);
  /// After the step of any robot during which a robot collided (a cell run
  /// with CollisionMode::Warn goes on after it; with Error, the default, the
  /// collision ends the run there).
  int breakOnCollision();
  /// After the step of any robot during which a gripper closed on nothing.
  int breakOnWarning();
  /// A condition (on breakpoint `id`'s robot) and a hit count for breakpoint `id`; false if none.
  bool qualify(int id, std::optional<Condition> condition, std::optional<HitCondition> hits);
  /// Stops when robot `robot`'s value `what` changes (after any robot's step).
  int watch(std::size_t robot, Expression what);
  /// A breakpoint or watch; false when there is none with that id.
  bool remove(int id);
  void removeAll() { breakpoints_.clear(), watches_.clear(); }
  const std::vector<CellBreakpoint>& breakpoints() const { return breakpoints_; }
  const std::vector<CellWatch>& watches() const { return watches_; }
  /// Breakpoint `b` as stops and lists say it: "right.rsp line 6", "at 2.000 s", "when out 1 = 1 on left".
  std::string describe(const CellBreakpoint& b) const;

  // --- forwards -------------------------------------------------------------
  /// The current robot runs `n` instructions, the others on in time with
  /// it (fewer at a breakpoint of any robot, or the cell's end). An error
  /// when the current robot's program is over.
  diag::Result<CellStop> step(std::uint64_t n = 1);
  /// The current robot's next instruction, over a GOSUB (until it returns); an error as step's.
  diag::Result<CellStop> next();
  /// Until the current robot's subroutine returns; an error when it is in none, or as step's.
  diag::Result<CellStop> finish();
  /// Until a breakpoint or the end.
  CellStop resume();
  /// Until the clock passes `t` (or a breakpoint, or the end): the cell stands at `t`.
  CellStop until(vm::Micros t);

  /// Asked every few thousand steps of a forward run; yes pauses it (Pause).
  void setInterrupt(std::function<bool()> interrupted) { interrupted_ = std::move(interrupted); }

  /// Input `input` of robot `robot` turns `on` at the cell's present moment
  /// and stays so until something else turns it: a stimulus at that time
  /// (the cell's clock, or the moment between two instants after
  /// goto-time), kept with the cell, so that every run of the cell from its
  /// start (going back) has it. The cell runs again from its start to the
  /// same count of steps of all robots (the moment shown kept). An error
  /// message when the run is over, the input is not 1..vm::kIoCount, or a
  /// wire of the cell drives it.
  std::optional<std::string> setInput(std::size_t robot, int input, bool on);

  // --- backwards ------------------------------------------------------------
  /// The whole cell back to where the current robot had run `n` fewer
  /// instructions (from inside one under way: that one is the first).
  CellStop reverseStep(std::uint64_t n = 1);
  /// Back over a GOSUB: to the moment before the current robot's previous
  /// instruction at this call depth or an outer one, else the start.
  CellStop reverseNext();
  /// Back to the last moment a breakpoint or watch would have stopped the
  /// cell going forwards (hit counts aside), else the start.
  CellStop reverseContinue();
  /// The whole cell to the moment `t`, forwards or back (breakpoints are not looked at).
  CellStop gotoTime(vm::Micros t);

 private:
  /// A fresh run of the spec, standing at its start.
  void restart();
  struct Probe;
  struct Found;
  /// The breakpoints and watches that stop the cell after robot `robot`'s
  /// step (`before`: the values after the step before); `counting` (going
  /// forwards) counts hits and applies hit conditions.
  Found matches(std::size_t robot, const Probe& before, bool counting);
  Probe probe() const;
  /// The collisions every robot has found so far.
  std::size_t probeCollisions() const;
  /// What a collision's or a warning's stop says happened (empty for the other kinds).
  std::string whatHappened(Breakpoint::Kind kind, const runtime::Run& stepped) const;
  CellStop foundStop(std::size_t robot, const Found& found) const;
  CellStop forward(const runtime::CellUntil& limits, std::function<bool(std::size_t)> done);
  /// Why the current robot takes no step (its program has ended), or nullopt.
  std::optional<std::string> cannotStep() const;
  /// A fresh run to the moment the current robot has run `target` instructions.
  CellStop backTo(std::uint64_t target);
  CellStop endStop() const;
  CellStop stopped(CellStop stop);
  int add(Breakpoint::Kind kind, CellBreakpoint b);
  /// `made` (a breakpoint of robot `robot`'s program) added, or why not.
  diag::Result<int> addOf(std::size_t robot, diag::Result<Breakpoint> made);

  runtime::CellRunSpec spec_;
  std::unique_ptr<runtime::CellRun> run_;
  std::vector<CellBreakpoint> breakpoints_;
  std::vector<CellWatch> watches_;
  int nextId_ = 1;
  std::size_t current_ = 0;
  CellStop stop_;
  std::optional<vm::Micros> at_;  // between two instants (goto-time, until): the moment shown
  std::function<bool()> interrupted_;
};

}  // namespace rs::debug
