#include "runtime/run/run.h"

#include "base/ascii.h"

#include <algorithm>

namespace rs::runtime {

namespace {

// A long call runs in slices of this many instructions, so that a pause
// asked for from another thread is seen within a millisecond or so.
constexpr std::uint64_t kSlice = std::uint64_t{1} << 20;

}  // namespace

// The one observer the interpreter calls: the log first, then every
// observer added, then the pause condition of the current call.
class Run::Observers final : public vm::StepObserver {
 public:
  explicit Observers(Run& run) : run_(run) {}
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override {
    if (run_.world_) {
      run_.lastStepGrasped_ = run_.world_->eventCount() != run_.graspEventsSeen_;
      run_.graspEventsSeen_ = run_.world_->eventCount();
      run_.lastStepClosedEmpty_ = run_.world_->emptyCloseCount() != run_.emptyClosesSeen_;
      run_.emptyClosesSeen_ = run_.world_->emptyCloseCount();
      if (run_.lastStepClosedEmpty_ && !run_.firstEmptyClose_)
        run_.firstEmptyClose_.emplace(index, run_.world_->lastEmptyClose());
    }
    run_.noteCollisions(index);
    if (run_.logger_) run_.logger_->afterStep(vm, index);
    bool pause = false;
    for (vm::StepObserver* o : added) pause |= o->afterStep(vm, index);
    if (when && (*when)(run_)) conditionMet = true, pause = true;
    return pause;
  }
  bool any() const { return run_.world_ || run_.logger_ || !added.empty() || when; }

  std::vector<vm::StepObserver*> added;
  const std::function<bool(const Run&)>* when = nullptr;
  bool conditionMet = false;

 private:
  Run& run_;
};

Run::Run(RunSpec spec) : spec_(std::move(spec)) {
  auto sim = std::make_unique<SimMachine>(spec_.image->motors, spec_.stimuli);
  sim_ = sim.get();
  motion_ = std::move(sim);
  build(*motion_);
}

Run::Run(RunSpec spec, std::unique_ptr<vm::Machine> machine) : spec_(std::move(spec)) {
  spec_.log = false;
  motion_ = std::move(machine);
  build(*motion_);
}

Run::Run(RunSpec spec, vm::Machine& machine) : spec_(std::move(spec)) {
  spec_.log = false;
  build(machine);
}

Run::~Run() = default;

// The order matters and is written once, here: the world reacts inside the
// machine call (the cell machine stands in front of the motion machine), so
// by the time any observer hears of a step, the hold has changed; the log
// then records the step, and the observers added (a trace) see both.
void Run::build(vm::Machine& motion) {
  front_ = &motion;
  if (spec_.cell) {
    world_.emplace(*spec_.cell);
    cellMachine_.emplace(motion, *world_);
    front_ = &*cellMachine_;
    if (sim_ && spec_.collisions != CollisionMode::Off) {
      watch_.emplace(*spec_.cell);
      cellMachine_->watchCollisions(*sim_, *watch_, spec_.collisions);
    }
  }
  if (spec_.log && sim_) logger_.emplace(*sim_, world());
  interpreter_ = std::make_unique<vm::Interpreter>(*spec_.image, *front_);
  observers_ = std::make_unique<Observers>(*this);
  breakpoints_.assign(spec_.image->code.size(), 0);
}

void Run::observe(vm::StepObserver& observer) { observers_->added.push_back(&observer); }

// The machine holds one listener: the first one added takes the log's
// place there and hands each change to the log, then to every listener.
bool Run::onInputChange(std::function<void(vm::Micros, std::uint8_t)> listener) {
  if (!sim_) return false;
  inputListeners_.push_back(std::move(listener));
  if (inputListeners_.size() == 1)
    sim_->onInputChange([this](vm::Micros at, std::uint8_t mask) {
      if (logger_) logger_->inputChanged(at, mask);
      for (const auto& l : inputListeners_) l(at, mask);
    });
  return true;
}

std::optional<vm::RunOutcome> Run::outcome() const {
  if (!interpreter_->finished()) return std::nullopt;
  return interpreter_->state().outcome;
}

vm::RunOutcome Run::step(std::uint64_t n) {
  RunUntil until;
  until.steps = interpreter_->steps() + std::min(n, UINT64_MAX - interpreter_->steps());
  return runUntil(until);
}

vm::RunOutcome Run::runUntilTime(vm::Micros t) {
  RunUntil until;
  until.time = t;
  return runUntil(until);
}

vm::RunOutcome Run::runUntilLine(std::uint32_t line) {
  RunUntil until;
  until.lines.push_back(line);
  return runUntil(until);
}

std::optional<std::uint32_t> Run::labelInstruction(std::string_view label) const {
  for (const vm::Label& l : spec_.image->labels)
    if (base::sameName(spec_.image->labelName(l), label)) return l.index;
  return std::nullopt;
}

std::optional<vm::RunOutcome> Run::runUntilLabel(std::string_view label) {
  const std::optional<std::uint32_t> at = labelInstruction(label);
  if (!at) return std::nullopt;
  RunUntil until;
  until.instructions.push_back(*at);
  return runUntil(until);
}

PauseCause Run::causeOf(const vm::RunOutcome& outcome, const RunUntil& until, std::uint64_t sliceEnd) const {
  if (!outcome.paused()) return PauseCause::None;
  if (observers_->conditionMet) return PauseCause::Condition;
  if (interpreter_->steps() >= until.steps) return PauseCause::Steps;
  if (clock() > until.time) return PauseCause::Time;
  if (outcome.index < breakpoints_.size() && breakpoints_[outcome.index]) return PauseCause::Instruction;
  if (interpreter_->steps() >= sliceEnd) return PauseCause::None;  // the end of a slice: go on
  return PauseCause::Requested;
}

vm::RunOutcome Run::runUntil(const RunUntil& until) {
  cause_ = PauseCause::None;
  if (finished()) return *outcome();
  pauseRequested_.store(false, std::memory_order_relaxed);
  const vm::Image& image = *spec_.image;
  std::fill(breakpoints_.begin(), breakpoints_.end(), 0);
  bool anyBreak = false;
  for (std::uint32_t i : until.instructions)
    if (i < breakpoints_.size()) breakpoints_[i] = 1, anyBreak = true;
  if (!until.lines.empty())
    for (std::uint32_t i = 0; i < image.code.size(); ++i)
      if (std::find(until.lines.begin(), until.lines.end(), image.lines[i]) != until.lines.end() &&
          (i == 0 || image.lines[i - 1] != image.lines[i]))
        breakpoints_[i] = 1, anyBreak = true;
  observers_->when = until.when ? &until.when : nullptr;
  observers_->conditionMet = false;
  vm::StepObserver* observer = observers_->any() ? observers_.get() : nullptr;

  vm::RunOutcome outcome;
  while (true) {
    const std::uint64_t sliceEnd = interpreter_->steps() + kSlice;
    vm::PausePoints pause;
    pause.atSteps = std::min(until.steps, sliceEnd);
    pause.afterTime = until.time;
    if (anyBreak) pause.before = breakpoints_;
    outcome = interpreter_->run(spec_.limits, observer, pause);
    cause_ = causeOf(outcome, until, sliceEnd);
    if (!outcome.paused() || cause_ != PauseCause::None) break;
    if (pauseRequested_.load(std::memory_order_relaxed)) {
      cause_ = PauseCause::Requested;
      break;
    }
  }
  observers_->when = nullptr;
  if (!outcome.paused() && !outcome.ok()) noteCollisions(outcome.index);
  if (logger_) logger_->finish(outcome);
  return outcome;
}

// The watch does not know which instruction moved: the run tells it after
// each step (and after the step that failed).
void Run::noteCollisions(std::uint32_t instruction) {
  if (!watch_) return;
  for (auto it = watch_->mutableEvents().rbegin(); it != watch_->mutableEvents().rend() && it->instruction == UINT32_MAX; ++it)
    it->instruction = instruction;
}

std::span<const CollisionEvent> Run::collisions() const {
  return watch_ ? watch_->events() : std::span<const CollisionEvent>();
}

std::vector<std::int32_t> Run::motorsAt(vm::Micros t) const {
  const auto now = motors();
  std::vector<std::int32_t> at(now.begin(), now.end());
  if (sim_ && t < sim_->now())
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = sim_->positionAt(i, t);
  return at;
}

std::optional<std::array<double, 3>> Run::tcp() const {
  if (!world_) return std::nullopt;
  return world_->tcp(motors());
}

std::vector<ObjectView> Run::objects(vm::Micros at) const {
  std::vector<ObjectView> out;
  if (!world_) return out;
  const std::vector<std::int32_t> encoders = motorsAt(at);
  for (std::size_t o = 0; o < spec_.cell->objects.size(); ++o) {
    const workcell::PlacedObject& placed = spec_.cell->objects[o];
    ObjectView v;
    v.name = placed.shape.name;
    v.pose = world_->objectPose(o, encoders, at);
    v.at = v.pose * workcell::atCorner(placed.shape);
    v.held = world_->held() == o && at >= world_->heldSince();
    v.moved = (v.pose.matrix() - placed.F_world_design.matrix()).cwiseAbs().maxCoeff() > 1e-9;
    out.push_back(v);
  }
  return out;
}

RunView Run::view() const {
  const vm::Image& image = *spec_.image;
  const vm::Interpreter& vm = *interpreter_;
  RunView v;
  v.clock = clock();
  v.steps = vm.steps();
  v.finished = vm.finished();
  v.outcome = outcome();
  const std::uint32_t last = static_cast<std::uint32_t>(image.code.size() - 1);
  v.instruction = v.finished ? std::min(v.outcome->index, last) : std::min(vm.pc(), last);
  v.line = image.lines[v.instruction];
  for (std::uint32_t ret : vm.callStack()) v.callStack.push_back({ret - 1, image.lines[ret - 1]});
  for (std::size_t s = 0; s < image.variables.size(); ++s) v.variables.emplace_back(image.variables[s], vm.variables()[s]);
  v.motors.assign(motors().begin(), motors().end());
  v.tcp = tcp();
  v.inputs = machine().inputs();
  v.outputs = machine().outputs();
  v.objects = objects();
  v.events = log();
  return v;
}

RunSnapshot Run::snapshot() const {
  RunSnapshot s;
  s.vm = interpreter_->state();
  if (sim_) s.machine = sim_->state();
  if (world_) s.world = world_->state();
  if (logger_) s.log = logger_->log().mark();
  if (watch_) s.collisions.assign(watch_->events().begin(), watch_->events().end());
  return s;
}

void Run::restore(const RunSnapshot& s) {
  interpreter_->restore(s.vm);
  if (sim_) sim_->restore(s.machine);
  if (world_ && s.world) world_->restore(*s.world);
  graspEventsSeen_ = world_ ? world_->eventCount() : 0;
  lastStepGrasped_ = false;
  emptyClosesSeen_ = world_ ? world_->emptyCloseCount() : 0;
  lastStepClosedEmpty_ = false;
  if (emptyClosesSeen_ == 0) firstEmptyClose_.reset();
  if (watch_) watch_->mutableEvents() = s.collisions;
  if (logger_ && s.log && sim_) logger_->restore(*s.log, *sim_);
  cause_ = PauseCause::None;
}

}  // namespace rs::runtime
