// The rig: what a program runs on, and what a teach pendant drives with no
// program at all. The workcell (or none), the machine that moves the
// motors (simulated, or a real controller), the world that reacts to it
// (what the gripper holds, where each object is), the collision watch,
// and on the simulated machine a snapshot of all of these.
//
//   Rig rig(cell, motors, stimuli, CollisionMode::Error);
//   rig.machine().moveTo(targets);
//   std::optional<std::array<double, 3>> at = rig.tcp();
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "compiler/stimuli/stimuli.h"
#include "model/workcell/model.h"
#include "runtime/cell/cell.h"
#include "runtime/cell/devices.h"
#include "runtime/cell/input_cause.h"
#include "runtime/run/followed_machine.h"
#include "runtime/run/robot_obstacles.h"
#include "runtime/sim/cell_machine.h"
#include "runtime/sim/collision_watch.h"
#include "runtime/sim/sim_machine.h"
#include "vm/machine.h"

namespace rs::runtime {

/// An object of the workcell at the rig's moment.
struct ObjectView {
  std::string_view name;  ///< its description's (`block`, `conveyor`)
  /// The name its OBJECT line gives it with `AS` (`infeed`), else `name`.
  std::string_view as;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< F_world_design
  Eigen::Vector3d at = Eigen::Vector3d::Zero();            ///< its AT corner in the world
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();        ///< the centre of its box (its lines' bounds) in the world
  bool held = false;                                       ///< by the gripper of the robot that runs the program
  bool moved = false;                                      ///< away from where the cell placed it
  bool present = true;      ///< in the cell (a feeder's empty slot, a part a sink took: not)
  std::uint32_t number = 0;  ///< "object 5": never given to another
};

/// A change of an input: when, and what made it (the trace's words).
struct InputChangeRecord {
  vm::Micros at = 0;
  InputCause cause;
  bool operator==(const InputChangeRecord&) const = default;
};

/// Everything that changes in a rig on the simulated machine.
struct RigSnapshot {
  SimMachine::State machine;
  /// The cell's clock and queue, and its world (on a workcell).
  Cell::State cell;
  /// Every collision found so far (in error mode one at most): restoring
  /// puts them back, whether the rig is behind or ahead of the snapshot.
  /// What else the swept check keeps is a cache (runtime/sim/sweep_memo.h).
  std::vector<CollisionEvent> collisions;
  /// The devices' state (a cell with devices).
  std::optional<CellDevices::State> devices;
  /// What they did that no step has reported yet (a snapshot before the
  /// first step: the cell's first instant, its first parts fed).
  std::vector<DeviceEvent> pendingDevices;
  /// Whether the devices had seen the world as it was (its revision, which
  /// is no state: it grows on every restore). `devices->revision` is kept
  /// as 0, so that a restored run's snapshot equals a fresh run's.
  bool devicesSawWorld = false;
  /// Each input's last change (Rig::lastInputChange).
  std::array<std::optional<InputChangeRecord>, vm::kIoCount> lastInputs;
  bool operator==(const RigSnapshot&) const = default;
};

class Rig {
 public:
  /// On the simulated machine, with these motors and input stimuli. On a
  /// workcell (may be null; Workcell::drivenRobot is driven) the world reacts,
  /// and collisions are checked unless `collisions` is Off.
  Rig(std::shared_ptr<const workcell::Workcell> cell, std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli,
      CollisionMode collisions);
  /// On another machine (a real controller): no snapshots, no collision check.
  Rig(std::shared_ptr<const workcell::Workcell> cell, std::unique_ptr<vm::Machine> machine);
  /// The same on a machine the caller keeps (it must outlive the rig).
  Rig(std::shared_ptr<const workcell::Workcell> cell, vm::Machine& machine);
  /// Robot `robot` of a cell of several (runtime/run/cell_run.h), on the
  /// simulated machine: it runs on `shared`'s clock and world (`cell` is
  /// withFeederSlots' copy, the one `shared` was made of; it must outlive
  /// the rig), and the cell's devices are attached later (attachDevices).
  /// No snapshots yet: a cell's snapshot is the cell run's. A `follower`
  /// (a real controller; it must outlive the rig) is given every motion
  /// and output of the simulated machine (followed_machine.h).
  Rig(std::shared_ptr<const workcell::Workcell> cell, Cell& shared, std::size_t robot,
      std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli, CollisionMode collisions,
      vm::Machine* follower = nullptr);
  Rig(const Rig&) = delete;
  Rig& operator=(const Rig&) = delete;
  ~Rig();

  const workcell::Workcell* cell() const { return cell_.get(); }
  /// The machine to drive (with the world's reactions, on a cell).
  const vm::Machine& machine() const { return *front_; }
  vm::Machine& machine() { return *front_; }
  /// The simulated machine, or null on a real one.
  const SimMachine* sim() const { return sim_; }
  SimMachine* sim() { return sim_; }
  /// The world, or null without a workcell.
  const World* world() const { return world_; }
  /// The running cell: its one clock (the simulated machine runs on it)
  /// and its world.
  const Cell& running() const { return *running_; }
  Cell& running() { return *running_; }

  vm::Micros clock() const { return machine().now(); }
  std::span<const std::int32_t> motors() const { return machine().positions(); }
  /// Every motor at time `t`, between the start of the last move and now
  /// (SimMachine::positionAt: a move in progress at t); now's on another machine.
  std::vector<std::int32_t> motorsAt(vm::Micros t) const;
  std::optional<std::array<double, 3>> tcp() const;
  std::vector<ObjectView> objects(vm::Micros at = INT64_MAX) const;
  /// Input `input` turns `on` now (SimMachine::setInputNow). False on a
  /// real machine or for an input outside 1..vm::kIoCount.
  bool setInput(int input, bool on) { return sim_ && sim_->setInputNow(input, on); }

  /// Every collision found so far (in warn mode, every one; in error mode,
  /// the one that stopped the run), each with its instruction.
  std::span<const CollisionEvent> collisions() const;
  /// The collision checker, or null when the rig checks none (no
  /// workcell, not simulated, or CollisionMode::Off).
  const CollisionWatch* collisionWatch() const { return watch_ ? &*watch_ : nullptr; }

  /// The cell's devices, or null (no workcell, no devices, or not simulated).
  const CellDevices* devices() const { return devices_; }
  /// What the cell's devices read and write of this robot (the simulated machine only).
  RobotIo& io() { return io_; }
  /// The cell's devices (a cell run's, shared by its robots) hear this
  /// robot's outputs; the first robot's moves also show the sensors what
  /// it carries. `devices` must outlive the rig.
  void attachDevices(CellDevices& devices);
  /// The cell's other robots become obstacles of this robot's swept check
  /// (robot_obstacles.h), each where its machine (named later through
  /// obstacles()) has it. A cell run's robot, on the simulated machine; a
  /// simulated robot of a cell of several on its own (a run of one
  /// program, teach) has it done at construction: the others stand at home.
  void avoidOtherRobots();
  RobotObstacles* obstacles() { return obstacles_.get(); }
  /// The robot's index in the cell (its hand in the world).
  std::size_t robotIndex() const { return robotIndex_; }
  /// Object `o`'s number ("object 5"): o + 1 for the objects the cell
  /// places; a fed part's is given when it is fed.
  std::uint32_t objectNumber(std::size_t o) const { return devices_ ? devices_->number(o) : static_cast<std::uint32_t>(o + 1); }
  /// `e` with the numbers its object and support have now (GraspEvent::number).
  GraspEvent numbered(GraspEvent e) const {
    e.number = objectNumber(e.object), e.supportNumber = objectNumber(e.support);
    return e;
  }
  /// The cell's clock runs to `t`, the devices acting on the way (after
  /// they have looked at what the robot changed). Fault: a loop of
  /// zero-delay changes, a device's mistake (a feeder out of slots).
  vm::Status advanceCell(vm::Micros t);
  /// What the devices did during the step just run (and before it).
  std::span<const DeviceEvent> devicesOfLastStep() const { return lastStepDevices_; }
  /// Record how the parts move (CellDevices::recordMotions): a run that
  /// keeps a log asks, and motionsOfLastStep() then says what changed
  /// during the step just run (and before it).
  void recordMotions() {
    if (devices_) devices_->recordMotions(true);
  }
  std::span<const PartMotion> motionsOfLastStep() const { return lastStepMotions_; }
  /// Every part on a running belt to where it is now (a pendant showing
  /// the cell between its instants; a run never needs it).
  void settleDevices() {
    if (devices_) devices_->commit();
  }
  /// What the devices did since the last step ended, as the step's (a run
  /// that stopped inside a step: afterStep never came).
  void takeDeviceRecords() {
    takeStepRecords();
    afterLastStep_ = true;
  }
  /// The records of the last step are those taken after it (takeDeviceRecords):
  /// a trace shows them at its end.
  bool recordsAfterLastStep() const { return afterLastStep_; }

  /// A program's next step runs instruction `instruction`: the collisions
  /// its moves find are that instruction's.
  void beforeStep(std::uint32_t instruction) {
    if (watch_) watch_->atInstruction(instruction);
  }
  /// A program's step at instruction `instruction` is done: the rig keeps
  /// what the world recorded it did (a take or let-go, a close on nothing).
  void afterStep(std::uint32_t instruction);
  /// The take or let-go of the step just run, or null (what a trace shows
  /// beside the step; right after a restore, null).
  const GraspEvent* graspOfLastStep() const { return lastStepGrasped_ ? &world_->lastEvent() : nullptr; }
  /// A closing move of the step just run that took nothing, or null.
  const EmptyClose* emptyCloseOfLastStep() const { return lastStepClosedEmpty_ ? &world_->lastEmptyClose() : nullptr; }
  /// The inputs that changed since the step before the one just run, each
  /// with its time and cause, in the order they changed (right after a
  /// restore, none).
  using InputChangeRecord = runtime::InputChangeRecord;
  std::span<const InputChangeRecord> inputsOfLastStep() const { return lastStepInputs_; }
  /// The last change of input `input` (1..vm::kIoCount) up to now, a
  /// stimulus at the start included; null when nothing changed it (it is
  /// OFF as every input starts) or on another machine than the simulated one.
  /// What the debugger and robotsim test say set an input.
  const InputChangeRecord* lastInputChange(int input) const {
    if (!vm::isIoLine(input)) return nullptr;
    const auto& last = lastInputs_[static_cast<std::size_t>(input - 1)];
    return last ? &*last : nullptr;
  }
  static constexpr std::size_t kMaxInputsPerStep = 4096;
  /// The instruction of the first closing move that took nothing, and
  /// where it left the tool centre point.
  std::optional<std::pair<std::uint32_t, EmptyClose>> firstEmptyClose() const { return firstEmptyClose_; }
  /// The first kKeptPlacingNotes closes round a fixture and let-gos that
  /// dropped a part more than kLongDrop, each with its instruction (what
  /// runtime/run/placing.h warns of; the world counts them all).
  static constexpr std::size_t kKeptPlacingNotes = 20;
  std::span<const std::pair<std::uint32_t, EmptyClose>> fixtureCloses() const { return fixtureCloses_; }
  std::span<const std::pair<std::uint32_t, GraspEvent>> longDrops() const { return longDrops_; }

  /// The robot that runs the program, as a process of the cell's clock:
  /// its machine's wait under way ends at `at` (a move's or a DELAY's end,
  /// a stimulus a WAITFOR waits for), so the clock stops there. Scheduled
  /// once per time.
  void wakeRobotAt(vm::Micros at);


  bool canSnapshot() const { return sim_ != nullptr && ownCell_ != nullptr; }
  /// The whole state (the simulated machine only: check canSnapshot()).
  RigSnapshot snapshot() const;
  /// Back to a snapshot of this rig.
  void restore(const RigSnapshot& snapshot);

 private:
  void build(vm::Machine& motion, CollisionMode collisions);

  // The robot on the cell's clock: woken, it does nothing itself (the run
  // resumes its machine after every instant); its events stop the clock
  // where its wait ends.
  struct RobotProcess final : CellProcess {
    CellDevices* devices = nullptr;
    // Before the robot looks at the world, the belts' parts are where they are now.
    void wake(const CellEvent&, Scheduler&) override {
      if (devices) devices->commit();
    }
    std::string name() const override { return "the robot"; }
  };
  struct SimIo final : RobotIo {
    SimMachine* sim = nullptr;
    bool output(int output) const override { return vm::lineIsOn(sim->outputs(), output); }
    void setInput(int input, bool on, const InputCause& cause) override { sim->setInputBy(input, on, cause); }
    void motorsAt(vm::Micros t, std::span<std::int32_t> out) const override {
      for (std::size_t m = 0; m < out.size(); ++m) out[m] = sim->positionAt(m, t);
    }
    std::size_t motorCount() const override { return sim->motors().size(); }
    bool motionKey(vm::Micros origin, std::vector<std::uint64_t>& out) const override {
      return sim->motionKey(origin, out);
    }
  };
  SimIo io_;
  std::unique_ptr<CellDevices> ownDevices_;  // a cell of one robot: the rig's own
  CellDevices* devices_ = nullptr;
  std::size_t robotIndex_ = 0;
  std::vector<DeviceEvent> lastStepDevices_;
  std::vector<PartMotion> lastStepMotions_;
  RobotProcess robot_;
  std::uint32_t robotId_ = 0;

  std::shared_ptr<const workcell::Workcell> cell_;
  std::unique_ptr<Cell> ownCell_;        // before the machine, which runs on its clock
  Cell* running_ = nullptr;              // ownCell_, or a cell run's
  World* world_ = nullptr;               // running_'s, on a workcell
  std::unique_ptr<vm::Machine> motion_;  // moves the motors, when the rig owns them
  SimMachine* sim_ = nullptr;            // motion_, when simulated
  std::unique_ptr<FollowedMachine> followed_;  // in front of sim_, when a controller follows it
  std::optional<CellMachine> cellMachine_;
  std::optional<CollisionWatch> watch_;
  CollisionMode collisions_ = CollisionMode::Off;
  std::unique_ptr<RobotObstacles> obstacles_;  // before watch_ is rebuilt on its view
  vm::Machine* front_ = nullptr;  // what is driven
  /// The inputs' changes and the devices' records since the last take, as the last step's.
  void takeStepRecords();
  std::vector<InputChangeRecord> pendingInputs_, lastStepInputs_;
  std::array<std::optional<InputChangeRecord>, vm::kIoCount> lastInputs_;
  void noteInputsAtStart(const stimuli::Stimuli& stimuli);
  bool afterLastStep_ = false;  // takeDeviceRecords came after the last step
  bool lastStepGrasped_ = false;
  bool lastStepClosedEmpty_ = false;
  std::optional<std::pair<std::uint32_t, EmptyClose>> firstEmptyClose_;
  std::vector<std::pair<std::uint32_t, EmptyClose>> fixtureCloses_;
  std::vector<std::pair<std::uint32_t, GraspEvent>> longDrops_;
};

}  // namespace rs::runtime
