// The interpreter: runs a verified image against a Machine. Variables live
// in slots, the call stack is bounded, and every way a run can stop (END,
// a runtime error, a deadlock, a limit) is an outcome value. A run can be
// resumed: `run` goes on from where the last call paused, so a debugger,
// a test runner or a teach pendant can step, run to a breakpoint or to a
// simulated time, look, and go on. Its whole state is a value
// (`InterpreterState`) that can be saved and put back.
//
// Only the run layer (runtime/run.h) constructs an interpreter.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "vm/image.h"
#include "vm/machine.h"
#include "vm/stop_reason.h"

namespace rs::vm {

struct RunLimits {
  std::uint64_t maxSteps = 100'000'000;        // instructions executed
  Micros maxTime = Micros{3600} * 1'000'000;   // simulated time
  /// Instructions in a row while the clock stands still (a loop that never
  /// moves, waits or delays); 0 = no limit.
  std::uint64_t maxStepsPerInstant = 10'000'000;
  /// The small moves of straight lines (Machine::knots) a run may make:
  /// a line costs its knots, not one instruction (a 300-unit MOVES on an
  /// IRB 120 is 672 of them). The line that passes it is the last.
  std::uint64_t maxKnots = 100'000'000;
};

struct RunOutcome {
  StopReason reason = StopReason::End;
  std::string message;     // empty for End and Paused
  std::uint32_t index = 0; // 0-based instruction that stopped the run (Paused: the next one to run)
  std::uint64_t steps = 0; // instructions executed
  /// Paused because a machine call said NotYet (Status::NotYet): the
  /// instruction at `index` has begun and ends when the clock reaches
  /// `wakeAt` (Status::kNever: when an input changes); the next `run`
  /// resumes it (Machine::resume) before anything else.
  bool waiting = false;
  Micros wakeAt = 0;
  bool ok() const { return reason == StopReason::End; }
  bool paused() const { return reason == StopReason::Paused; }
  bool operator==(const RunOutcome&) const = default;
};

/// Where a resumed run pauses, besides finishing. Every condition is
/// checked at no cost when unset.
struct PausePoints {
  /// Pause once this many instructions have run in all (not per call).
  std::uint64_t atSteps = UINT64_MAX;
  /// Pause right after the instruction that takes the clock past this
  /// time; instructions that run at exactly this time still run.
  Micros afterTime = INT64_MAX;
  /// Pause right after the instruction that takes the machine's knots
  /// (Machine::knots) to this many or more: a slice of work, not of
  /// instructions, for a program of straight lines.
  std::uint64_t atKnots = UINT64_MAX;
  /// One byte per instruction, non-zero: pause before running it (but not
  /// before the first instruction of a call, so a run can leave a
  /// breakpoint it stands on). Empty: none.
  std::span<const std::uint8_t> before;
};

/// Everything that changes while a program runs, apart from the machine.
struct InterpreterState {
  std::uint32_t pc = 0;        ///< next instruction (0-based)
  std::uint64_t steps = 0;     ///< instructions executed so far
  std::uint64_t stillSince = 0;  ///< `steps` when the clock last moved
  Micros clockSeen = 0;        ///< the clock then
  std::vector<std::int32_t> variables;
  std::vector<std::uint32_t> callStack;  ///< return addresses, innermost last
  std::vector<std::int32_t> softHome;
  bool finished = false;
  bool waiting = false;        ///< the instruction at pc has begun and waits (RunOutcome::waiting)
  RunOutcome outcome;          ///< how it finished (when `finished`)
  bool operator==(const InterpreterState&) const = default;
};

class Interpreter;

/// Called after every executed instruction when set (tracing, recording,
/// a debugger's conditions). One check per instruction when unset.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// Return true to pause the run after this step.
  virtual bool afterStep(const Interpreter& vm, std::uint32_t index) = 0;
};

class Interpreter {
 public:
  /// `image` must have passed verify(); both must outlive the interpreter.
  Interpreter(const Image& image, Machine& machine);

  /// Runs from where the last call stopped until the program ends, fails,
  /// hits a limit, or reaches a pause point. After an outcome other than
  /// Paused the run is finished and further calls return at once.
  RunOutcome run(const RunLimits& limits, StepObserver* observer = nullptr, const PausePoints& pause = {});

  const Image& image() const { return image_; }
  Machine& machine() const { return machine_; }
  std::span<const std::int32_t> variables() const { return state_.variables; }
  std::span<const std::uint32_t> callStack() const { return state_.callStack; }
  std::size_t callDepth() const { return state_.callStack.size(); }
  std::uint32_t pc() const { return state_.pc; }
  std::uint64_t steps() const { return state_.steps; }
  bool finished() const { return state_.finished; }

  const InterpreterState& state() const { return state_; }
  /// Puts back a state saved from this interpreter (the machine's state is
  /// the caller's to put back).
  void restore(const InterpreterState& state) { state_ = state; }
  /// A run that ended (END) whose machine then failed at that instant (a
  /// cell's devices, looking once more): the outcome becomes that fault.
  RunOutcome failAfterEnd(std::string message) {
    state_.outcome.reason = StopReason::RuntimeError, state_.outcome.message = std::move(message);
    return state_.outcome;
  }

 private:
  /// Every instruction that moves the motors (kMovesMotors).
  Status move(const Instr& in);
  /// Every instruction that acts on the machine (kUsesMachine).
  Status machineCall(const Instr& in);
  Status moveTo(std::span<const std::int32_t> targets);
  RunOutcome finish(StopReason reason, std::string message, std::uint32_t index);
  /// What the loop does after an instruction that acts on the machine.
  enum class AfterCall : std::uint8_t { Next, Pause, Stopped, Waiting };
  /// Runs instruction `at` (which acts on the machine), or resumes it when
  /// it waits, and checks what the
  /// call did: a failure or the time limit finishes the run (Stopped,
  /// with `next` and `steps` saved), a moved clock renews `check`, a
  /// clock past the pause time asks for a pause. Out of the loop's way:
  /// its Status and messages are strings, which the loop never touches.
  AfterCall machineStep(const Instr& in, std::uint32_t at, std::uint32_t next, std::uint64_t steps,
                        const RunLimits& limits, const PausePoints& pause, std::uint64_t& check);
  /// The loop's ways out: a pause before `next`; a finished run (state
  /// saved, `index` the instruction it ended on); the step count checked.
  RunOutcome pauseAt(std::uint32_t next, std::uint64_t steps);
  RunOutcome stopAt(StopReason reason, std::string message, std::uint32_t index, std::uint32_t next,
                    std::uint64_t steps);
  RunOutcome checkpoint(const RunLimits& limits, std::uint32_t pc, std::uint64_t steps);
  /// The dispatch loop; `kWatched`: with an observer or breakpoints (the
  /// loop without them checks nothing per step beyond one step count).
  template <bool kWatched>
  RunOutcome loop(const RunLimits& limits, StepObserver* observer, const PausePoints& pause);

  const Image& image_;
  Machine& machine_;
  InterpreterState state_;
  std::vector<std::int32_t> target_;  // scratch, sized once
};

}  // namespace rs::vm
