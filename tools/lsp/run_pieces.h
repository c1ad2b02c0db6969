// The pieces of the editor's checked run that a run of one program
// (checked_run.cpp) and a run of the whole cell (cell_checked_run.cpp)
// share: the timer that notes each instruction's times and keeps the
// budget, the summary for hovers, the note of a run out of budget, the
// check of the straight lines, and the stimuli file beside the program.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compiler/stimuli/stimuli.h"
#include "diag/diagnostic.h"
#include "tools/lsp/checked_run.h"
#include "vm/interpreter.h"

namespace rs::workcell {
struct Workcell;
}

namespace rs::lsp {

/// The CPU time of the calling thread: the run's budget is the work the
/// worker's thread does, whatever else the machine is doing meanwhile (a
/// wall-clock budget ran out on a loaded machine before the work did).
std::chrono::nanoseconds threadTime();

/// Notes when each instruction first starts and ends, how often it runs and
/// for how long, and how long each call of a subroutine takes (a stack of
/// the calls under way, as the interpreter's); pauses the run when it is
/// abandoned or out of time (the thread's clock read every kClockEvery
/// steps: a step costs nanoseconds, a read hundreds; and every
/// kClockEveryKnots knots, since one straight line is a step of thousands
/// of moves).
class RunTimer final : public vm::StepObserver {
 public:
  static constexpr std::uint64_t kClockEvery = 1024;
  static constexpr std::uint64_t kClockEveryKnots = 4096;

  RunTimer(std::vector<InstructionTimes>& times, std::vector<CallTimes>& calls, const RunControl& control,
           std::chrono::nanoseconds deadline)
      : times_(times), calls_(calls), control_(control), deadline_(deadline) {}
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override;
  bool outOfTime() const { return outOfTime_; }

 private:
  struct Call {
    std::uint32_t entry = 0;  // the subroutine's first instruction
    vm::Micros start = 0;
  };
  std::vector<InstructionTimes>& times_;
  std::vector<CallTimes>& calls_;
  std::vector<Call> underWay_;
  const RunControl& control_;
  std::chrono::nanoseconds deadline_;
  vm::Micros before_ = 0;
  std::uint64_t steps_ = 0;
  std::uint64_t knotsRead_ = 0;
  bool outOfTime_ = false;
};

/// How a run ended, for hovers: "finished at 3.5 s", "stopped by an error
/// at 1.2 s (line 7: ...)".
std::string summaryOf(const runtime::Run& run, const vm::RunOutcome& outcome);

/// The run stopped by the editor's budget: a note where it stopped, so
/// that no line is left looking checked when it was not.
diag::Diagnostic budgetNote(const runtime::Run& run, const std::string& file, std::chrono::milliseconds budget);

/// The compile-time check of the straight lines the editor's compile
/// leaves out (cell_context.h): its errors, none when every line can be
/// followed (or the program's robot has no arm to plan for).
std::vector<diag::Diagnostic> lineErrors(const ProgramAnalysis& analysis);

/// The stimuli file beside `analysis`'s program, from `options` (the
/// editor's text, else the saved file), placed on `cell`'s robots (those
/// `running` marks, for a cell run): nothing when there is none. A file
/// with errors, or naming an unknown robot, is a note on the program's
/// first line (`run-not-made`) and a summary, returned as a run not made.
std::optional<CheckedRun> stimuliBeside(const ProgramAnalysis& analysis, const RunOptions& options,
                                        const workcell::Workcell* cell, stimuli::Stimuli& into,
                                        const std::vector<bool>* running = nullptr);

}  // namespace rs::lsp
