#include "runtime/run/rig.h"

#include <algorithm>

#include "runtime/sim/input_schedule.h"

namespace rs::runtime {

Rig::Rig(std::shared_ptr<const workcell::Workcell> cell, std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli,
         CollisionMode collisions)
    : cell_(withFeederSlots(std::move(cell))), ownCell_(std::make_unique<Cell>(cell_.get())), running_(ownCell_.get()) {
  noteInputsAtStart(stimuli);
  auto sim = std::make_unique<SimMachine>(std::move(motors), std::move(stimuli), running_->clock());
  sim_ = sim.get();
  motion_ = std::move(sim);
  build(*motion_, collisions);
  io_.sim = sim_;
  // The cell's other robots stand at home, and are obstacles there.
  if (cell_ && cell_->robots.size() > 1) avoidOtherRobots();
  if (world_ && !cell_->devices.empty()) {
    ownDevices_ = std::make_unique<CellDevices>(*cell_, *world_, io_, running_->clock());
    attachDevices(*ownDevices_);
    // The cell's first instant: the first parts fed, the sensors as the cell begins.
    (void)advanceCell(running_->clock().now());
  }
}

Rig::Rig(std::shared_ptr<const workcell::Workcell> cell, Cell& shared, std::size_t robot,
         std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli, CollisionMode collisions,
         vm::Machine* follower)
    : robotIndex_(robot), cell_(std::move(cell)), running_(&shared) {
  noteInputsAtStart(stimuli);
  auto sim = std::make_unique<SimMachine>(std::move(motors), std::move(stimuli), running_->clock());
  sim_ = sim.get();
  motion_ = std::move(sim);
  if (follower) followed_ = std::make_unique<FollowedMachine>(*sim_, *follower);
  build(followed_ ? *followed_ : *motion_, collisions);
  io_.sim = sim_;
  if (world_) world_->handMotors(robot, sim_);
}

void Rig::avoidOtherRobots() {
  if (!sim_ || !cell_ || !watch_) return;
  obstacles_ = std::make_unique<RobotObstacles>(*cell_, robotIndex_);
  if (!obstacles_->any()) return;
  watch_.emplace(obstacles_->view(), robotIndex_);
  watch_->alsoAvoid(obstacles_->firstPart(), *obstacles_, cell_->robots[robotIndex_].labelOf());
  cellMachine_->watchCollisions(*sim_, *watch_, collisions_);
}

void Rig::attachDevices(CellDevices& devices) {
  if (!sim_) return;
  devices_ = &devices;
  robot_.devices = devices_;
  sim_->onOutputChange([this](int output, bool) { return devices_->outputChanged(output, robotIndex_); });
  // The devices watch what every robot shows the sensors on the way.
  sim_->onMoveBegun([this](vm::Micros until) { devices_->robotMoves(until, robotIndex_); });
  // A wait that finishes alone does what the run's wait on the cell and the
  // robot's wake do for the devices: look again first, commit at its end.
  sim_->onFinishAlone([this] { devices_->sync(); }, [this] { devices_->commit(); });
}

vm::Status Rig::advanceCell(vm::Micros t) {
  if (devices_) devices_->sync();
  if (vm::Status s = running_->clock().advanceTo(t); !s) return s;
  if (devices_)
    if (std::optional<std::string> fault = devices_->takeFault()) return vm::Status::fault(*fault);
  return vm::Status::ok();
}

Rig::Rig(std::shared_ptr<const workcell::Workcell> cell, std::unique_ptr<vm::Machine> machine)
    : cell_(std::move(cell)), ownCell_(std::make_unique<Cell>(cell_.get())), running_(ownCell_.get()),
      motion_(std::move(machine)) {
  build(*motion_, CollisionMode::Off);
}

Rig::Rig(std::shared_ptr<const workcell::Workcell> cell, vm::Machine& machine)
    : cell_(std::move(cell)), ownCell_(std::make_unique<Cell>(cell_.get())), running_(ownCell_.get()) {
  build(machine, CollisionMode::Off);
}

Rig::~Rig() = default;

// The world reacts inside the machine call: the cell machine stands in
// front of the motion machine, so by the time anyone hears of a move, the
// hold has changed. Only the simulated machine's moves can be swept.
void Rig::build(vm::Machine& motion, CollisionMode collisions) {
  front_ = &motion;
  robotId_ = running_->clock().add(robot_);
  // Kept until the step's end (afterStep). A run that nobody observes never
  // ends a step for the rig, so the list is bounded: a step keeps its first
  // kMaxInputsPerStep changes.
  if (sim_)
    sim_->onInputCause([this](vm::Micros at, const InputCause& c) {
      if (pendingInputs_.size() < kMaxInputsPerStep) pendingInputs_.push_back({at, c});
      lastInputs_[static_cast<std::size_t>(c.input - 1)] = InputChangeRecord{at, c};
    });
  if (!cell_) return;
  world_ = running_->world();
  cellMachine_.emplace(motion, *world_, robotIndex_);
  front_ = &*cellMachine_;
  collisions_ = collisions;
  if (sim_ && collisions != CollisionMode::Off) {
    watch_.emplace(*cell_, robotIndex_);
    cellMachine_->watchCollisions(*sim_, *watch_, collisions);
  }
}

// The machine applies the stimuli due at the start as it is made, before
// anyone listens (the trace shows none of them): their causes are found
// here, the same changes in the same order.
void Rig::noteInputsAtStart(const stimuli::Stimuli& stimuli) {
  InputSchedule start(stimuli.changes);
  vm::IoMask inputs = 0;
  start.applyUntil(running_->clock().now(), inputs, [this](vm::Micros at, vm::IoMask, const InputCause& c) {
    lastInputs_[static_cast<std::size_t>(c.input - 1)] = InputChangeRecord{at, c};
  });
}

void Rig::wakeRobotAt(vm::Micros at) {
  // An event for `at` still waits when one was scheduled there: a wait
  // always ends after now, so a second one would only repeat it.
  const auto& queue = running_->clock().state().queue;
  for (auto it = queue.lower_bound({at, 0, 0, 0}); it != queue.end() && it->at == at; ++it)
    if (it->process == robotId_) return;
  running_->clock().schedule(at, robotId_);
}

void Rig::takeStepRecords() {
  lastStepInputs_.swap(pendingInputs_);
  pendingInputs_.clear();
  if (devices_) lastStepDevices_ = devices_->takeEvents(), lastStepMotions_ = devices_->takeMotions();
}

void Rig::afterStep(std::uint32_t instruction) {
  afterLastStep_ = false;
  takeStepRecords();
  if (!world_) return;
  const World::StepEffects step = world_->takeStepEffects(robotIndex_);
  lastStepGrasped_ = step.grasped;
  lastStepClosedEmpty_ = step.closedEmpty;
  if (step.closedEmpty && !firstEmptyClose_) firstEmptyClose_.emplace(instruction, world_->lastEmptyClose());
  if (step.closedEmpty && world_->lastEmptyClose().fixture && fixtureCloses_.size() < kKeptPlacingNotes)
    fixtureCloses_.emplace_back(instruction, world_->lastEmptyClose());
  if (step.grasped && world_->lastEvent().settled() && world_->lastEvent().drop > kLongDrop &&
      longDrops_.size() < kKeptPlacingNotes)
    longDrops_.emplace_back(instruction, numbered(world_->lastEvent()));
}

std::span<const CollisionEvent> Rig::collisions() const {
  return watch_ ? watch_->events() : std::span<const CollisionEvent>();
}

std::vector<std::int32_t> Rig::motorsAt(vm::Micros t) const {
  const auto now = motors();
  std::vector<std::int32_t> at(now.begin(), now.end());
  if (sim_ && t < sim_->now())
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = sim_->positionAt(i, t);
  return at;
}

std::optional<std::array<double, 3>> Rig::tcp() const {
  if (!world_) return std::nullopt;
  return world_->tcp(motors(), robotIndex_);
}

std::vector<ObjectView> Rig::objects(vm::Micros at) const {
  std::vector<ObjectView> out;
  if (!world_) return out;
  const std::vector<std::int32_t> encoders = motorsAt(at);
  for (std::size_t o = 0; o < cell_->objects.size(); ++o) {
    const workcell::PlacedObject& placed = cell_->objects[o];
    ObjectView v;
    v.name = placed.shape.name;
    v.as = placed.name.empty() ? v.name : std::string_view(placed.name);
    v.pose = world_->objectPose(o, encoders, at, robotIndex_);
    v.at = v.pose * workcell::atCorner(placed.shape);
    const Eigen::AlignedBox3d bounds = workcell::boundsOf(placed.shape);
    v.centre = bounds.isEmpty() ? v.at : Eigen::Vector3d(v.pose * bounds.center());
    v.held = world_->held(robotIndex_) == o && at >= world_->heldSince(robotIndex_);
    v.moved = (v.pose.matrix() - placed.F_world_design.matrix()).cwiseAbs().maxCoeff() > 1e-9;
    v.number = objectNumber(o);
    v.present = v.number != 0 && world_->inCell(o);  // a RESET empties a slot before the devices next look
    out.push_back(v);
  }
  return out;
}

RigSnapshot Rig::snapshot() const {
  RigSnapshot s;
  if (sim_) s.machine = sim_->state();
  s.cell = running_->state();
  s.lastInputs = lastInputs_;
  if (watch_) s.collisions.assign(watch_->events().begin(), watch_->events().end());
  if (devices_) {
    s.devices = devices_->state(), s.pendingDevices = devices_->pendingEvents();
    s.devicesSawWorld = s.devices->revision == world_->revision();
    s.devices->revision = 0;
  }
  return s;
}

void Rig::restore(const RigSnapshot& s) {
  running_->restore(s.cell);
  if (sim_) sim_->restore(s.machine);
  if (devices_ && s.devices) {
    // After the world's restore, which gave it a new revision: the devices
    // see it as they saw the world then (in step, or with a change to look at).
    CellDevices::State devices = *s.devices;
    devices.revision = s.devicesSawWorld ? world_->revision() : world_->revision() - 1;
    devices_->restore(devices);
    devices_->putBack(s.pendingDevices);
  }
  lastStepDevices_.clear();
  lastStepMotions_.clear();
  lastStepGrasped_ = false;
  lastStepClosedEmpty_ = false;
  pendingInputs_.clear(), lastStepInputs_.clear();
  lastInputs_ = s.lastInputs;
  if (!world_ || world_->emptyCloseCount() == 0) firstEmptyClose_.reset();
  // Back to as many as the world had counted by then (kept in run order).
  fixtureCloses_.resize(std::min<std::size_t>(fixtureCloses_.size(), world_ ? world_->fixtureCloseCount() : 0));
  longDrops_.resize(std::min<std::size_t>(longDrops_.size(), world_ ? world_->longDropCount() : 0));
  if (watch_) watch_->restoreEvents(s.collisions);
}

}  // namespace rs::runtime
