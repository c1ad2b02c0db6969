// A run as data: every executed instruction with the clock before and after
// it, each motor's moves (SimMachine's segments), the output and camera
// changes, and the inputs over time. What the HTML animation replays, and
// enough to answer "where was everything at time t" exactly as SimMachine
// would (positionAt's integer rounding included).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/sim_machine.h"
#include "runtime/stimuli.h"
#include "vm/interpreter.h"

namespace rs::render {

/// One executed instruction: it ran from `start` to `end` on the clock.
struct StepRecord {
  std::uint32_t index = 0;  ///< 0-based instruction
  vm::Micros start = 0, end = 0;
};

/// A motor's move, started by step `step` (SimMachine::MotorSegment). A
/// jump (RESET) has start == end.
struct MotorMove {
  std::uint32_t step = 0;
  std::int32_t from = 0, to = 0;
  vm::Micros start = 0, end = 0;
};

/// The output mask after step `step`, when that step changed it.
struct OutputChange {
  std::uint32_t step = 0;
  std::uint8_t outputs = 0;
};

/// The accumulated VIEW and WINDOW after step `step`, when it changed them.
struct CameraChange {
  std::uint32_t step = 0;
  runtime::CameraTriple view, window;
};

/// The input mask from time `at` on (after every instruction that ran at
/// `at`: when several run at one instant, they all show the last one's).
struct InputLevel {
  vm::Micros at = 0;
  std::uint8_t inputs = 0;
};

struct RunRecording {
  std::vector<vm::MotorSpec> motors;
  std::vector<StepRecord> steps;
  std::vector<std::vector<MotorMove>> moves;  ///< per motor, in step order
  std::vector<OutputChange> outputs;
  std::vector<CameraChange> cameras;
  std::vector<InputLevel> inputs;  ///< starts at time 0
  vm::Micros end = 0;              ///< the clock when the run stopped
};

/// Records a run on `machine` (which must outlive it): pass it to
/// Interpreter::run, then call finish.
class RunRecorder final : public vm::StepObserver {
 public:
  explicit RunRecorder(const runtime::SimMachine& machine);
  void afterStep(const vm::Interpreter& vm, std::uint32_t index) override;

  /// Completes the recording: the instruction that stopped a run early (a
  /// runtime error, a deadlock, the time limit) counts as a step, and the
  /// input levels are rebuilt from the stimuli and the recorded outputs.
  RunRecording finish(const vm::RunOutcome& outcome, const runtime::Stimuli& stimuli);

 private:
  void record(std::uint32_t index);

  const runtime::SimMachine& machine_;
  RunRecording rec_;
  std::vector<runtime::MotorSegment> lastSegment_;
  std::vector<std::int32_t> lastPosition_;
  struct OutputEvent {
    vm::Micros at;
    int output;
    bool on;
  };
  std::vector<OutputEvent> outputEvents_;
  std::vector<std::uint8_t> inputsAtEnd_;  // per step, to check the rebuilt levels
  std::uint8_t lastOutputs_ = 0;
  runtime::CameraTriple lastView_, lastWindow_;
  vm::Micros lastNow_ = 0;
};

/// Everything at one moment of a recorded run.
struct RunState {
  std::optional<std::size_t> step;     ///< the step in progress, if any started yet
  std::vector<std::int32_t> encoders;  ///< every motor
  std::uint8_t outputs = 0, inputs = 0;
  runtime::CameraTriple view, window;
};

/// The state at time t: the step is the last one that started at or before
/// t (so a move in progress, or the last of the instructions that took no
/// time at t); motors as SimMachine::positionAt would answer.
RunState stateAt(const RunRecording& rec, vm::Micros t);
/// The state after step `step`'s effects, seen at time t (its start..end).
RunState stateAtStep(const RunRecording& rec, std::size_t step, vm::Micros t);

/// SimMachine::positionAt for one recorded move.
std::int32_t positionAt(const MotorMove& move, std::int32_t speed, vm::Micros t);

}  // namespace rs::render
