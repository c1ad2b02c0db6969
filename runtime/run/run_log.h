// A run as data: every executed instruction with the clock before and after
// it, each motor's moves (SimMachine's segments), the output and camera
// changes, the inputs over time, and what the gripper took and let go. What
// the HTML animation replays and a test runner checks, and enough to answer
// "where was everything at time t" exactly as SimMachine would
// (positionAt's integer rounding included). A run keeps one when asked to
// (RunSpec::log); only a run on the simulated machine can.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/sim/sim_machine.h"
#include "runtime/sim/world.h"
#include "vm/interpreter.h"

namespace rs::runtime {

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
  bool lockStep = false;  ///< one small move of a straight line (MotorSegment::lockStep)
  bool lead = false;      ///< MotorSegment::lead
};

/// The output mask after step `step`, when that step changed it.
struct OutputChange {
  std::uint32_t step = 0;
  vm::IoMask outputs = 0;
};

/// The accumulated VIEW and WINDOW after step `step`, when it changed them.
struct CameraChange {
  std::uint32_t step = 0;
  CameraTriple view, window;
};

/// The input mask from time `at` on (after every change due at `at`).
struct InputLevel {
  vm::Micros at = 0;
  vm::IoMask inputs = 0;
};

/// Step `step` wrote `value` into variable slot `slot` (SET, ADD).
struct VariableWrite {
  std::uint32_t step = 0;
  std::uint32_t slot = 0;
  std::int32_t value = 0;
  bool operator==(const VariableWrite&) const = default;
};

/// A take or a let-go (runtime/sim/world.h) during step `step`.
struct GraspRecord {
  std::uint32_t step = 0;
  GraspEvent event;
};

struct RunLog {
  std::vector<vm::MotorSpec> motors;
  std::vector<StepRecord> steps;
  std::vector<std::vector<MotorMove>> moves;  ///< per motor, in step order
  std::vector<OutputChange> outputs;
  std::vector<CameraChange> cameras;
  std::vector<InputLevel> inputs;   ///< starts at time 0
  std::vector<GraspRecord> grasps;  ///< in step order; empty without a gripper
  std::vector<VariableWrite> variables;  ///< in step order
  vm::Micros end = 0;               ///< the clock when the run stopped (or paused)

  /// How long each list was at some moment, to cut the log back to it.
  struct Mark {
    std::size_t steps = 0, outputs = 0, cameras = 0, inputs = 0, grasps = 0, variables = 0;
    std::vector<std::size_t> moves;
    vm::Micros end = 0;
    bool operator==(const Mark&) const = default;
  };
  Mark mark() const;
  void cutTo(const Mark& mark);
};

/// Keeps a RunLog of a run on `machine` (and `world`, may be null), both of
/// which must outlive it: the run calls afterStep after every step and
/// finish when it stops.
class RunLogger {
 public:
  RunLogger(SimMachine& machine, const World* world);
  void afterStep(const vm::Interpreter& vm, std::uint32_t index);
  /// The instruction that stopped a run early (a runtime error, a
  /// deadlock, the time limit) counts as a step.
  void finish(const vm::RunOutcome& outcome);
  /// The log as it stands (the run paused or finished).
  const RunLog& log() const { return log_; }
  /// Back to an earlier moment of the same run (a snapshot being restored).
  void restore(const RunLog::Mark& mark, const SimMachine& machine);
  /// The machine's inputs became `mask` at `at` (the logger listens to the
  /// machine itself; a Run that also hands changes on calls this).
  void inputChanged(vm::Micros at, vm::IoMask mask);

 private:
  void record(std::uint32_t index);
  void recordMoves(std::uint32_t step);
  void takeStateOf(const SimMachine& machine);

  const SimMachine& machine_;
  const World* world_;
  RunLog log_;
  std::vector<MotorSegment> lastSegment_;
  std::vector<std::int32_t> lastPosition_;
  vm::IoMask lastOutputs_ = 0;
  CameraTriple lastView_, lastWindow_;
  vm::Micros lastNow_ = 0;
  std::uint64_t graspsSeen_ = 0;
};

/// Everything at one moment of a logged run.
struct RunState {
  std::optional<std::size_t> step;     ///< the step in progress, if any started yet
  std::vector<std::int32_t> encoders;  ///< every motor
  vm::IoMask outputs = 0, inputs = 0;
  CameraTriple view, window;
};

/// The state at time t: the step is the last one that started at or before
/// t (so a move in progress, or the last of the instructions that took no
/// time at t); motors as SimMachine::positionAt would answer.
RunState stateAt(const RunLog& log, vm::Micros t);
/// The state after step `step`'s effects, seen at time t (its start..end).
RunState stateAtStep(const RunLog& log, std::size_t step, vm::Micros t);

/// Variable slot `slot`'s value at time t (after every write due at t).
std::int32_t variableAt(const RunLog& log, std::uint32_t slot, vm::Micros t);

/// positionAt (runtime/sim/motion.h, what SimMachine answers) for one logged move.
std::int32_t positionAt(const MotorMove& move, const vm::MotorSpec& motor, vm::Micros t);

}  // namespace rs::runtime
