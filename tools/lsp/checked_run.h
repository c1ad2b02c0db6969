// The run the editor makes of one version of a program: the run `robotsim
// check` makes (launch::prepareRun: at most 100,000,000 instructions and
// 3600 simulated seconds, a collision stops it), on the program's cell,
// with the stimuli file beside the program when there is one (NAME.stim
// for NAME.rsp, as the editors' Check command passes it with --stimuli),
// off the request thread (run_worker.h). What it reports are check's own
// diagnostics (launch/run_diagnostics.h); when each instruction ran feeds
// hovers and inlay hints, and how long each subroutine's calls took the
// code lenses. Before it, the compile-time check of the
// straight lines (compiler/program/line_check.h), which the editor's
// compile leaves out (CellContext's target): a plan of each MOVES, APPRO
// and DEPART, from the cell's cache of plans, so that an edit re-plans
// only the lines it changed; a line the arm cannot follow is the compile
// error `check` gives, and the program is then not run.
//
// The editor bounds it further: at most kRunBudget of the worker thread's
// CPU time (a run that needs more ends with a note saying so, never with a
// guess; CPU time, so that a loaded machine does not cut runs short), and
// a newer edit abandons it (RunControl::abandon: the run pauses after its
// current step, through the run's own pause mechanism).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/sim/collision_watch.h"
#include "vm/interpreter.h"

namespace rs::runtime {
class Run;
}

namespace rs::lsp {

class ProgramAnalysis;

/// The editor's own bound on a run, beyond check's limits: CPU time of the
/// thread that makes it.
inline constexpr std::chrono::milliseconds kRunBudget{5000};

struct InstructionTimes {
  vm::Micros start = 0;  ///< of its first execution
  vm::Micros end = 0;
  std::uint64_t runs = 0;  ///< 0: never ran (to its end)
  vm::Micros total = 0;    ///< every execution's time, added up
};

/// The calls of a subroutine that returned, from the GOSUB to its RETURN
/// (the calls it makes included).
struct CallTimes {
  std::uint64_t calls = 0;
  vm::Micros total = 0;
  vm::Micros shortest = 0;
  vm::Micros longest = 0;
};

/// What the run is given besides the program: check's options as the
/// editor sets them.
struct RunOptions {
  runtime::CollisionMode collisions = runtime::CollisionMode::Error;  ///< robotsim.collisions
  /// The stimuli file beside the program: its name, and its text as the
  /// editor holds it, or else its path on disk; neither when there is none.
  std::string stimuliFile;
  std::optional<std::string> stimuliText;
  std::string stimuliPath;
};

struct CheckedRun {
  /// NotRun: a straight line cannot be followed (its compile error is among
  /// the diagnostics), or the stimuli file beside the program has errors (a
  /// note says so).
  enum class End : std::uint8_t { Finished, OutOfBudget, Abandoned, NotRun };
  End end = End::Finished;
  std::vector<InstructionTimes> times;  ///< per instruction (0-based)
  std::vector<CallTimes> calls;         ///< per instruction: the calls of the subroutine it is the entry of
  std::optional<vm::RunOutcome> outcome;  ///< when finished
  vm::Micros clock = 0;                   ///< where the run stopped
  std::uint64_t steps = 0;
  /// Finished: what check reports (its stop, its warnings); out of
  /// budget: a note at the instruction the run stopped before.
  std::vector<diag::Diagnostic> diagnostics;
  /// How it ended, for hovers: "finished at 3.5 s", "stopped by a
  /// collision at 1.2 s (line 7)".
  std::string summary;
  /// The instruction the run stopped at when it did not end well (0-based).
  std::optional<std::uint32_t> stoppedAt() const;
};

/// Lets another thread abandon a run in progress.
class RunControl {
 public:
  /// From any thread: the run pauses after its current step and its result
  /// is not published.
  void abandon();
  bool abandoned() const { return abandoned_.load(std::memory_order_relaxed); }
  /// The runs being made (the worker's: one, or every robot's of a cell
  /// run), so that abandon() can pause them.
  void attach(std::vector<runtime::Run*> runs);

 private:
  std::atomic<bool> abandoned_ = false;
  std::mutex mutex_;
  std::vector<runtime::Run*> runs_;
};

/// The run of `analysis` (which compiled) as check makes it with these
/// options. Stops early when `control` is abandoned or the budget runs out.
CheckedRun checkRun(const ProgramAnalysis& analysis, const RunOptions& options, RunControl& control,
                    std::chrono::milliseconds budget = kRunBudget);

}  // namespace rs::lsp
