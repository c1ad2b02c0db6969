// A run as data: every executed instruction with the clock before and after
// it, each motor's moves (SimMachine's segments), the output and camera
// changes, the inputs over time, and what the gripper took and let go. What the HTML animation replays, and
// enough to answer "where was everything at time t" exactly as SimMachine
// would (positionAt's integer rounding included).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/grasp_observer.h"
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

/// The first robot's gripper took (`held`) or let go of object `object`
/// (an index in Workcell::objects) during step `step` (model/workcell/
/// grasp.h). A take happens at the end of the closing move, `at` = the
/// step's end, and `pose` is F_E_object: the object's placement in the
/// end-effector frame, which it keeps until let go. A let-go happens as the
/// opening move (or RESET) begins, `at` = the step's start, and `pose` is
/// F_world_object, where the object rests from then on (its workcell
/// placement after RESET).
struct GraspEvent {
  std::uint32_t step = 0;
  vm::Micros at = 0;
  std::size_t object = 0;
  bool held = false;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

struct RunRecording {
  std::vector<vm::MotorSpec> motors;
  std::vector<StepRecord> steps;
  std::vector<std::vector<MotorMove>> moves;  ///< per motor, in step order
  std::vector<OutputChange> outputs;
  std::vector<CameraChange> cameras;
  std::vector<InputLevel> inputs;  ///< starts at time 0
  std::vector<GraspEvent> grasps;  ///< in step order; empty without a gripper
  vm::Micros end = 0;              ///< the clock when the run stopped
};

/// Records a run on `machine` (which must outlive it): pass it to
/// Interpreter::run, then call finish. To record grasps too, chain it after
/// a GraspObserver (the one passed here, as that observer's `next`): it
/// reads the observer's lastChange() after every step.
class RunRecorder final : public vm::StepObserver {
 public:
  explicit RunRecorder(const runtime::SimMachine& machine, const runtime::GraspObserver* grasp = nullptr);
  void afterStep(const vm::Interpreter& vm, std::uint32_t index) override;

  /// Completes the recording: the instruction that stopped a run early (a
  /// runtime error, a deadlock, the time limit) counts as a step, and the
  /// input levels are rebuilt from the stimuli and the recorded outputs.
  RunRecording finish(const vm::RunOutcome& outcome, const runtime::Stimuli& stimuli);

 private:
  void record(std::uint32_t index);

  const runtime::SimMachine& machine_;
  const runtime::GraspObserver* grasp_;
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

/// runtime::positionAt (what SimMachine answers) for one recorded move.
std::int32_t positionAt(const MotorMove& move, std::int32_t speed, vm::Micros t);

}  // namespace rs::render
