// A debugging session on a cell of several robots (runtime::CellRun), each
// robot a thread of the session: breakpoints per program (file), a stop
// stops the whole cell, `step` runs the current robot to its next
// instruction while the others go on in time, and reverse-step,
// reverse-continue and goto-time put the whole cell back.
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

/// A breakpoint before a line of one robot's program.
struct CellBreakpoint {
  int id = 0;
  std::size_t robot = 0;  ///< the program index
  std::uint32_t line = 0;  ///< where it stands (the first line with code at or after the one asked)
  std::vector<std::uint32_t> instructions;  ///< the first of each run of instructions on the line
  std::uint64_t hitCount = 0;               ///< times reached running forwards
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

  // --- breakpoints ----------------------------------------------------------
  /// Before line `line` of robot `robot`'s program (or the first line with code after it).
  diag::Result<int> breakAtLine(std::size_t robot, std::uint32_t line);
  std::uint32_t lineWithCode(std::size_t robot, std::uint32_t line) const;
  bool remove(int id);
  void removeAll() { breakpoints_.clear(); }
  const std::vector<CellBreakpoint>& breakpoints() const { return breakpoints_; }

  // --- forwards -------------------------------------------------------------
  /// The current robot runs `n` instructions, the others on in time with
  /// it (fewer at a breakpoint of any robot, or the cell's end). An error
  /// when the current robot's program is over.
  diag::Result<CellStop> step(std::uint64_t n = 1);
  /// The current robot's next instruction, over a GOSUB (until it returns); an error as step's.
  diag::Result<CellStop> next();
  /// Until a breakpoint or the end.
  CellStop resume();
  /// Until the clock passes `t` (or a breakpoint, or the end): the cell stands at `t`.
  CellStop until(vm::Micros t);

  /// Asked every few thousand steps of a forward run; yes pauses it (Pause).
  void setInterrupt(std::function<bool()> interrupted) { interrupted_ = std::move(interrupted); }

  // --- backwards ------------------------------------------------------------
  /// The whole cell back to where the current robot had run `n` fewer
  /// instructions (from inside one under way: that one is the first).
  CellStop reverseStep(std::uint64_t n = 1);
  /// Back to the last moment a breakpoint would have stopped the cell going forwards, else the start.
  CellStop reverseContinue();
  /// The whole cell to the moment `t`, forwards or back (breakpoints are not looked at).
  CellStop gotoTime(vm::Micros t);

 private:
  /// A fresh run of the spec, standing at its start.
  void restart();
  /// The breakpoints that stop robot `robot` where it stands now.
  std::vector<int> hits(std::size_t robot) const;
  CellStop forward(const runtime::CellUntil& limits, std::function<bool(std::size_t)> done);
  CellStop endStop() const;
  CellStop stopped(CellStop stop);
  std::string describe(const CellBreakpoint& b) const;

  runtime::CellRunSpec spec_;
  std::unique_ptr<runtime::CellRun> run_;
  std::vector<CellBreakpoint> breakpoints_;
  int nextId_ = 1;
  std::size_t current_ = 0;
  CellStop stop_;
  std::optional<vm::Micros> at_;  // between two instants (goto-time, until): the moment shown
  std::function<bool()> interrupted_;
};

}  // namespace rs::debug
