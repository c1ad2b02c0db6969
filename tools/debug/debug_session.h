// A debugging session on one run, independent of its front ends (the
// terminal's `robotsim debug`, the debug adapter's `robotsim dap`): the
// breakpoints and watches, the ways to go forwards (step, next, finish,
// continue, until a time) and backwards (reverse step, reverse next,
// reverse continue, go to a time), `set input` and `set VAR`, and why the
// run stopped.
// Every stop leaves the session inspectable, also a deadlock, a runtime
// error or a limit: the run can still be looked at and stepped back.
//
//   DebugSession s(spec);
//   s.addBreakpoint(lineBreakpoint);
//   Stop stop = s.resume();
//   runtime::RunView v = s.view();
//   stop = s.reverseStep();
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "diag/result.h"
#include "runtime/run/run.h"
#include "tools/debug/breakpoint.h"
#include "tools/debug/timeline.h"

namespace rs::debug {

/// Why the session stopped: the one stop-reason type (vm/stop_reason.h).
/// A session says Entry, Breakpoint, Watch, Step, Time, Pause and Start,
/// and a finished run's reason (End, RuntimeError, Deadlock, a limit);
/// vm::debuggerName says each.
using vm::StopReason;

struct Stop {
  StopReason reason = StopReason::Entry;
  std::string message;          ///< what happened, one line (names already made safe to print)
  std::vector<int> breakpoints;  ///< the breakpoints and watches that stopped it
  /// What the instructions run on the way did that is worth saying even
  /// at a plain step: a gripper that closed on nothing ("" if nothing).
  std::string note = {};
  /// The run is over: it ended, deadlocked, failed or hit a limit.
  bool finished() const { return vm::isOver(reason); }
};

struct SessionOptions {
  std::uint64_t snapshotInterval = kDefaultSnapshotInterval;
  std::size_t snapshotBudget = kDefaultSnapshotBudget;
  std::uint64_t snapshotKnots = kDefaultSnapshotKnots;
};

class DebugSession {
 public:
  /// The run of `spec` on the simulated machine, standing before its first
  /// instruction.
  explicit DebugSession(runtime::RunSpec spec, SessionOptions options = {});
  ~DebugSession();

  const runtime::Run& run() const { return *run_; }
  /// The run at the session's moment. After goto-time into the middle of
  /// a move (or a DELAY), and at a collision, that moment lies inside the
  /// instruction under way: the clock, the motors, the tool centre point
  /// and the objects are theirs at that time, the instruction and line the
  /// one under way, and the steps those done before it. A run that a
  /// collision ended (--collisions=error, the default) stands at its first
  /// contact, not at the end of the move the arm never reached.
  runtime::RunView view() const;
  const Stop& lastStop() const { return stop_; }
  const Timeline& timeline() const { return *timeline_; }

  // --- breakpoints and watches --------------------------------------------
  /// Before line `line` (or the first line with code after it).
  diag::Result<int> breakAtLine(std::uint32_t line);
  diag::Result<int> breakAtLabel(std::string_view label);
  /// Before instruction `index` (0-based; messages number from 1, as disasm).
  diag::Result<int> breakAtInstruction(std::uint32_t index);
  diag::Result<int> breakAtTime(vm::Micros t);
  /// When `condition` becomes true (`when out 2 = 1`, `when N = 3`).
  int breakWhen(Condition condition);
  /// At every collision the run's check finds (a run with --collisions=warn
  /// goes on after it; with error, the default, it ends there, and the stop
  /// is both this breakpoint's and the run's end): the session stands at
  /// the moment of the first contact.
  int breakOnCollision();
  /// At every closing move that takes nothing (what the trace notes and
  /// the run's warning is about).
  int breakOnWarning();
  /// After every instruction during which a device did what `point` says
  /// (a sensor's edge, a part fed, a part taken; device_points.h): the
  /// stop's message says what happened and when.
  int breakOnDevice(DevicePoint point);
  /// Adds a condition and a hit count to breakpoint `id`; false if none.
  bool qualify(int id, std::optional<Condition> condition, std::optional<HitCondition> hits);
  int watch(Expression what);
  /// Deletes a breakpoint or watch; false when there is none with that id.
  bool remove(int id);
  void removeAll();
  const std::vector<Breakpoint>& breakpoints() const { return breakpoints_; }
  const std::vector<Watch>& watches() const { return watches_; }
  /// The line a line breakpoint asked at `line` stands on (0: none after it).
  std::uint32_t lineWithCode(std::uint32_t line) const;

  // --- forwards -----------------------------------------------------------
  /// `n` instructions (fewer at a breakpoint or the end).
  Stop step(std::uint64_t n = 1);
  /// One instruction, over a GOSUB (until it returns).
  Stop next();
  /// Until the current subroutine returns; an error when none is running.
  diag::Result<Stop> finish();
  /// Until a breakpoint, a watch, or the end.
  Stop resume();
  /// Until the clock passes `t` (or a breakpoint, or the end).
  Stop until(vm::Micros t);

  // --- backwards ----------------------------------------------------------
  Stop reverseStep(std::uint64_t n = 1);
  /// Back over a GOSUB: to the moment before the previous instruction run
  /// at this call depth or an outer one.
  Stop reverseNext();
  /// Back to the last moment a breakpoint or watch would have stopped the
  /// run going forwards (hit counts aside), else to the start.
  Stop reverseContinue();
  /// To the moment `t` exactly, forwards or back (breakpoints are not
  /// looked at): after the instructions done by then; when one is under
  /// way at t (a move, a DELAY), view() shows it at t.
  Stop gotoTime(vm::Micros t);

  /// Input `input` turns `on` from now on (inside an instruction under way,
  /// from its end, where the session then stands); reverse execution
  /// replays it.
  /// An error message when the run is over or the input is not 1..vm::kIoCount.
  std::optional<std::string> setInput(int input, bool on);
  /// Variable `name` (any case) holds `value` from now on, as setInput
  /// (reverse execution replays it). An error message when the run is
  /// over, the program has no such variable, or the value does not fit
  /// one (32 bits, as SET's).
  std::optional<std::string> setVariable(std::string_view name, std::int64_t value);

  /// Called after every command that moves the run, with the stop, and
  /// after setInput, with the last stop again (a live view of the
  /// workcell follows the debugger through this).
  using StopObserver = std::function<void(const DebugSession&, const Stop&)>;
  void onStop(StopObserver observer) { observers_.push_back(std::move(observer)); }
  /// Asked between slices of a long forward run; yes pauses it (Pause).
  void setInterrupt(std::function<bool()> interrupted) { interrupted_ = std::move(interrupted); }

 private:
  struct Target;
  class Probe;
  Stop forward(const Target& target);
  /// `happened`: what the devices did that device breakpoints stop at.
  bool stopsHere(const runtime::Run& r, const Probe& before, bool counting, std::vector<int>& ids,
                 std::vector<std::string>& notes, std::vector<std::string>& happened);
  Stop finishedStop(bool already) const;
  Stop stopped(Stop stop);
  /// When a collision breakpoint is among `ids`: the session stands at the
  /// moment of the last collision's first contact (true).
  bool standAtCollision(const std::vector<int>& ids);
  /// The collision that ended the run, if one did (CollisionMode::Error
  /// stops a run at its first collision, the machine having made the whole
  /// move): the session shows its contact, never the pose after it.
  const runtime::CollisionEvent* endingCollision() const;
  /// A run that a collision ended: the stop at its contact, with the
  /// collision breakpoints (unconditional, or whose condition holds) that
  /// stop there.
  Stop collisionEnd(Stop stop);
  /// Runs back one instruction to see which one is under way at `t`.
  void standWithin(vm::Micros t);
  /// A close on nothing among the instructions since `emptyClosesBefore`.
  std::string emptyCloseNote(std::uint64_t emptyClosesBefore) const;
  std::uint64_t emptyCloses() const;
  /// The last collision, said as the run's report says it, with its time.
  std::string collisionText() const;
  int nextId() { return nextId_++; }
  /// Breakpoint `b` of kind `kind` added with the next id: that id.
  int add(Breakpoint::Kind kind, Breakpoint b);
  Breakpoint* find(int id);
  /// A breakpoint's description by id (stopText's); nullopt for a watch.
  std::function<std::optional<std::string>(int)> describer();

  std::unique_ptr<runtime::Run> run_;
  std::unique_ptr<Timeline> timeline_;
  std::vector<Breakpoint> breakpoints_;
  std::vector<Watch> watches_;
  int nextId_ = 1;
  Stop stop_;
  // The moment inside the instruction under way that view() shows (the run
  // stands after that instruction).
  struct Moment {
    vm::Micros time = 0;
    std::uint32_t instruction = 0;
  };
  std::optional<Moment> moment_;
  std::vector<StopObserver> observers_;
  std::function<bool()> interrupted_;
};

}  // namespace rs::debug
