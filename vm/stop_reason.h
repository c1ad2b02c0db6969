// Why a run stopped or paused: the one type for it, from the interpreter's
// end of a run through the run layer's pause causes to the debugger's
// stops, and the one table of the words each is said with.
#pragma once

#include <cstdint>
#include <string_view>

namespace rs::vm {

enum class StopReason : std::uint8_t {
  // The run is over (the interpreter says these).
  End,           ///< END, or ran past the last instruction
  RuntimeError,  ///< bad value, call stack overflow, machine fault
  Deadlock,      ///< WAITFOR that nothing will satisfy
  StepLimit,
  TimeLimit,
  InstantLimit,  ///< maxStepsPerInstant instructions without the clock moving
  KnotLimit,     ///< more than maxKnots small moves of straight lines
  // The run paused and can go on. The interpreter says only Paused; the run
  // says why (runtime::Run::pauseCause), the debugger's stops say more.
  Paused,        ///< a pause point was reached
  Step,          ///< a step count reached; a step, next, finish, reverse step or reverse next done
  Time,          ///< the clock passed a time (until, goto-time)
  Breakpoint,    ///< before an instruction or a source line asked for
  Condition,     ///< a condition said so after a step
  Pause,         ///< asked for from outside (another thread, Ctrl-C, the adapter's pause)
  Entry,         ///< a debugging session starts before the first instruction
  Watch,         ///< a watched value changed
  Start,         ///< going backwards reached the start of the run
};

/// The run is over: it ended, failed, deadlocked or hit a limit.
constexpr bool isOver(StopReason r) { return r < StopReason::Paused; }
constexpr bool isLimit(StopReason r) {
  return r == StopReason::StepLimit || r == StopReason::TimeLimit || r == StopReason::InstantLimit ||
         r == StopReason::KnotLimit;
}

/// How a run's stop is reported by `run`, `check`, `test` and the editor:
/// "finished", "runtime error", "deadlock", "step limit", ...
std::string_view stopReasonName(StopReason reason);
/// How the debugger says it ("end", "limit", "breakpoint", ...).
std::string_view debuggerName(StopReason reason);
/// The Debug Adapter Protocol's `stopped` event reason for a stop that
/// leaves the session paused ("breakpoint", "data breakpoint", "goto",
/// "exception" for a run that is over, ...).
std::string_view adapterReason(StopReason reason);

}  // namespace rs::vm
