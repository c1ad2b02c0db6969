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
#include "runtime/cell/devices.h"
#include "runtime/cell/world.h"
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

/// Input `cause.input` changed at `at`, for `cause` (a stimulus, a rule, a
/// wire, the debugger), during step `step` (or before it, between steps).
struct InputRecord {
  std::uint32_t step = 0;
  vm::Micros at = 0;
  InputCause cause;
};

/// Step `step` wrote `value` into variable slot `slot` (SET, ADD).
struct VariableWrite {
  std::uint32_t step = 0;
  std::uint32_t slot = 0;
  std::int32_t value = 0;
  bool operator==(const VariableWrite&) const = default;
};

/// A take or a let-go (runtime/cell/world.h) during step `step`.
struct GraspRecord {
  std::uint32_t step = 0;
  GraspEvent event;
};

/// What a device did (runtime/cell/devices.h) during step `step` (or before it).
struct DeviceRecord {
  std::uint32_t step = 0;
  DeviceEvent event;
};

/// How a part moved from then on (runtime/cell/devices.h) during step `step` (or before it).
struct MotionRecord {
  std::uint32_t step = 0;
  PartMotion motion;
};

struct RunLog {
  std::vector<vm::MotorSpec> motors;
  std::vector<StepRecord> steps;
  std::vector<std::vector<MotorMove>> moves;  ///< per motor, in step order
  std::vector<OutputChange> outputs;
  std::vector<CameraChange> cameras;
  std::vector<InputLevel> inputs;   ///< starts at time 0
  std::vector<InputRecord> inputChanges;  ///< every change of an input, with its cause
  std::vector<GraspRecord> grasps;  ///< in step order; empty without a gripper
  std::vector<VariableWrite> variables;  ///< in step order
  std::vector<DeviceRecord> devices;     ///< a sensor's edge, a part fed (or waiting), a part a sink took
  std::vector<MotionRecord> motions;     ///< a part's motion changed: a belt started or stopped it, fed, took it
  vm::Micros end = 0;               ///< the clock when the run stopped (or paused)
  /// The slot its straight lines' knots are merged within (LineThinning;
  /// 1: every knot is kept).
  vm::Micros lineSlot = 1;

  /// How long each list was at some moment, to cut the log back to it.
  struct Mark {
    std::size_t steps = 0, outputs = 0, cameras = 0, inputs = 0, grasps = 0, variables = 0, inputChanges = 0,
                devices = 0, motions = 0;
    std::vector<std::size_t> moves;
    vm::Micros end = 0;
    bool operator==(const Mark&) const = default;
  };
  Mark mark() const;
  void cutTo(const Mark& mark);
};

/// How a log keeps the knots of straight lines (RunSpec::lines). Every
/// knot by default: a 300-unit MOVES of an IRB 120 is 672 of them, seven
/// motor moves each, so a loop of lines logged whole grows with its knots
/// (1.65 GB for 2,000 instructions). Thinned, the knots a motor makes in
/// one step (and the knots it stands still in between) are merged while
/// together they stay within one slot of `slot` microseconds: the log is
/// then exact (stateAt answers what the machine would) at every multiple
/// of the slot, at each line's start and end, and all through a knot
/// longer than a slot; in between, a merged move runs at a constant rate.
/// Its line moves are at most about three a slot and motor, plus two a
/// line.
struct LineThinning {
  bool on = false;
  /// The slot, while the run's time is at most kMaxFixedSlots of them
  /// (0: none). Beyond that, and without one, the slot is the largest
  /// power of ten microseconds at most 1/kSlotsPerRun of the run's time so
  /// far: it grows as the run goes, tenfold at a time, and the log is
  /// thinned again each time (a power of ten divides every interval of 1,
  /// 2 or 5 times a larger power of ten, such as a chart's samples).
  vm::Micros slot = 0;
  static constexpr vm::Micros kSlotsPerRun = 5000;
  static constexpr vm::Micros kMaxFixedSlots = 1'000'000;
  /// The slot for a run whose time so far is `end`, given the slot used so far.
  vm::Micros slotAt(vm::Micros end, vm::Micros current) const;
};

/// Merges the lock-step moves of `moves` (one motor's, in step order) as
/// LineThinning says for slots of `slot` microseconds.
void thinLineMoves(std::vector<MotorMove>& moves, vm::Micros slot);

/// Keeps a RunLog of a run on `machine` (and `world`, may be null), both of
/// which must outlive it: the run calls afterStep after every step and
/// finish when it stops. A thinned log (`lines`) cannot be cut back to a
/// mark (restore): its merged moves are not those it had then. `hand` is
/// the robot whose takes and let-gos the log keeps (GraspEvent::hand): in
/// a cell of several robots the world is shared, and each robot's log
/// keeps only its own gripper's.
class RunLogger {
 public:
  RunLogger(SimMachine& machine, const World* world, LineThinning lines = {}, std::size_t hand = 0);
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
  /// Input `cause.input` changed at `at` for `cause`, in step `step`.
  void inputCause(std::uint32_t step, vm::Micros at, const InputCause& cause) {
    log_.inputChanges.push_back({step, at, cause});
  }
  void deviceEvent(std::uint32_t step, const DeviceEvent& event) { log_.devices.push_back({step, event}); }
  void partMotion(std::uint32_t step, const PartMotion& motion) { log_.motions.push_back({step, motion}); }

 private:
  void record(std::uint32_t index);
  void recordMoves(std::uint32_t step);
  void takeStateOf(const SimMachine& machine);
  /// A lock-step move of motor m: merged into the last one when it may be.
  void addLineMove(std::size_t m, const MotorMove& move);

  const SimMachine& machine_;
  const World* world_;
  RunLog log_;
  std::vector<MotorSegment> lastSegment_;
  std::vector<std::int32_t> lastPosition_;
  vm::IoMask lastOutputs_ = 0;
  CameraTriple lastView_, lastWindow_;
  vm::Micros lastNow_ = 0;
  std::uint64_t graspsSeen_ = 0;
  LineThinning lines_;
  std::size_t hand_ = 0;
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
