#include "runtime/run/run.h"

#include "base/ascii.h"

#include <algorithm>

namespace rs::runtime {

namespace {

// A long call runs in slices of this many instructions, or of this many
// knots of straight lines (a line is one instruction and may be thousands
// of them), so that a pause asked for from another thread is seen within a
// few milliseconds.
constexpr std::uint64_t kSlice = std::uint64_t{1} << 20;
constexpr std::uint64_t kSliceKnots = std::uint64_t{1} << 14;

}  // namespace

// The one observer the interpreter calls: the rig first (what the step
// took or let go), then the log, then every observer added, then the
// pause condition of the current call; last, the rig hears which
// instruction runs next (what its moves hit is that one's). It sees the
// run only as anyone does.
class Run::Observers final : public vm::StepObserver {
 public:
  Observers(const Run& run, Rig& rig, RunLogger* logger) : run_(run), rig_(rig), logger_(logger) {}
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override {
    rig_.afterStep(index);
    if (logger_) {
      // The step's record is the next one the log keeps.
      const auto step = static_cast<std::uint32_t>(logger_->log().steps.size());
      for (const Rig::InputChangeRecord& c : rig_.inputsOfLastStep()) logger_->inputCause(step, c.at, c.cause);
      for (const DeviceEvent& e : rig_.devicesOfLastStep()) logger_->deviceEvent(step, e);
      for (const PartMotion& m : rig_.motionsOfLastStep()) logger_->partMotion(step, m);
      logger_->afterStep(vm, index);
    }
    bool pause = false;
    for (vm::StepObserver* o : added) pause |= o->afterStep(vm, index);
    if (when && (*when)(run_)) conditionMet = true, pause = true;
    rig_.beforeStep(vm.pc());
    return pause;
  }
  // Without a world, a log, an observer or a condition, a step needs no call.
  bool any() const { return rig_.world() || logger_ || !added.empty() || when; }

  std::vector<vm::StepObserver*> added;
  const std::function<bool(const Run&)>* when = nullptr;
  bool conditionMet = false;

 private:
  const Run& run_;
  Rig& rig_;
  RunLogger* logger_;
};

Run::Run(RunSpec spec) : spec_(std::move(spec)) {
  build(std::make_unique<Rig>(spec_.cell, spec_.image->motors, spec_.stimuli, spec_.collisions));
}

Run::Run(RunSpec spec, std::unique_ptr<vm::Machine> machine) : spec_(std::move(spec)) {
  spec_.log = false;
  build(std::make_unique<Rig>(spec_.cell, std::move(machine)));
}

Run::Run(RunSpec spec, vm::Machine& machine) : spec_(std::move(spec)) {
  spec_.log = false;
  build(std::make_unique<Rig>(spec_.cell, machine));
}

Run::Run(RunSpec spec, Cell& shared, std::size_t robot, vm::Machine* follower)
    : spec_(std::move(spec)), inCellRun_(true) {
  build(std::make_unique<Rig>(spec_.cell, shared, robot, spec_.image->motors, spec_.stimuli, spec_.collisions,
                              follower));
}

Run::~Run() = default;

// The order matters and is written once, here: the rig's world reacts
// inside the machine call, so by the time any observer hears of a step,
// the hold has changed; the log then records the step, and the observers
// added (a trace) see both.
void Run::build(std::unique_ptr<Rig> rig) {
  rig_ = std::move(rig);
  // The simulated robot runs as a process of the cell: its waits say "not
  // yet" and the run moves the cell's clock (waitOnCell).
  if (rig_->sim()) rig_->sim()->waitOnScheduler(true);
  if (spec_.log && rig_->sim()) logger_.emplace(*rig_->sim(), rig_->world(), spec_.lines, rig_->robotIndex()), rig_->recordMotions();
  interpreter_ = std::make_unique<vm::Interpreter>(*spec_.image, rig_->machine());
  observers_ = std::make_unique<Observers>(*this, *rig_, logger_ ? &*logger_ : nullptr);
  breakpoints_.assign(spec_.image->code.size(), 0);
}

void Run::observe(vm::StepObserver& observer) { observers_->added.push_back(&observer); }

// The machine holds one listener: the first one added takes the log's
// place there and hands each change to the log, then to every listener.
bool Run::onInputChange(std::function<void(vm::Micros, vm::IoMask)> listener) {
  SimMachine* sim = rig_->sim();
  if (!sim) return false;
  inputListeners_.push_back(std::move(listener));
  if (inputListeners_.size() == 1)
    sim->onInputChange([this](vm::Micros at, vm::IoMask mask) {
      if (logger_) logger_->inputChanged(at, mask);
      for (const auto& l : inputListeners_) l(at, mask);
    });
  return true;
}

std::optional<vm::RunOutcome> Run::outcome() const {
  if (!interpreter_->finished()) return std::nullopt;
  return interpreter_->state().outcome;
}

std::optional<std::uint32_t> labelInstruction(const vm::Image& image, std::string_view label) {
  for (const vm::Label& l : image.labels)
    if (base::sameName(image.labelName(l), label)) return l.index;
  return std::nullopt;
}

std::uint64_t Run::knots() const { return rig_->machine().knots(); }

// Why the interpreter paused; nullopt at the end of a slice (go on).
std::optional<vm::StopReason> Run::causeOf(const vm::RunOutcome& outcome, const RunUntil& until,
                                           std::uint64_t stepEnd, std::uint64_t sliceEnd,
                                           std::uint64_t sliceKnots) const {
  using vm::StopReason;
  if (!outcome.paused()) return outcome.reason;
  if (observers_->conditionMet) return StopReason::Condition;
  if (interpreter_->steps() >= stepEnd || knots() >= until.knots) return StopReason::Step;
  if (rig_->clock() > until.time) return StopReason::Time;
  if (outcome.index < breakpoints_.size() && breakpoints_[outcome.index]) return StopReason::Breakpoint;
  if (interpreter_->steps() >= sliceEnd || knots() >= sliceKnots) return std::nullopt;
  return StopReason::Pause;
}

vm::RunOutcome Run::runUntil(const RunUntil& until) {
  if (finished()) {
    cause_ = outcome()->reason;
    return *outcome();
  }
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

  const std::uint64_t stepEnd = until.stepEnd(interpreter_->steps());
  rig_->beforeStep(interpreter_->pc());
  if (rig_->sim()) rig_->sim()->finishAlone(!inCellRun_);

  vm::RunOutcome outcome;
  while (true) {
    const std::uint64_t sliceEnd = interpreter_->steps() + kSlice;
    const std::uint64_t sliceKnots = knots() + kSliceKnots;
    vm::PausePoints pause;
    pause.atSteps = std::min(stepEnd, sliceEnd);
    pause.afterTime = until.time;
    pause.atKnots = std::min(until.knots, sliceKnots);
    if (anyBreak) pause.before = breakpoints_;
    outcome = interpreter_->run(spec_.limits, observer, pause);
    if (outcome.waiting && inCellRun_) {
      cause_ = vm::StopReason::Pause;
      break;
    }
    while (outcome.waiting && !pauseRequested_.load(std::memory_order_relaxed)) {
      waitOnCell(outcome);
      outcome = interpreter_->run(spec_.limits, observer, pause);
    }
    if (outcome.waiting) {
      cause_ = vm::StopReason::Pause;
      break;
    }
    const std::optional<vm::StopReason> cause = causeOf(outcome, until, stepEnd, sliceEnd, sliceKnots);
    if (cause) {
      cause_ = *cause;
      break;
    }
    if (pauseRequested_.load(std::memory_order_relaxed)) {
      cause_ = vm::StopReason::Pause;
      break;
    }
  }
  observers_->when = nullptr;
  // END right after a take, a let-go or a RESET: the devices' look at that
  // instant comes before the summary, which shows the cell as the instant ends.
  // A fault of theirs then (a feeder with no slot left) is the run's.
  if (finished() && outcome.ok() && !inCellRun_)
    if (vm::Status s = rig_->advanceCell(rig_->running().clock().now()); !s)
      outcome = interpreter_->failAfterEnd(std::move(s.message));
  // A step cut short (the time limit in a WAITFOR the devices end, a
  // fault), or the instant of the last: what the devices did since is the
  // log's last step's, and the trace's last lines (a cell run's robots
  // share the devices: theirs go to whoever steps next, the last instant's
  // to the robot that ended last, CellRun::runUntil).
  if (finished() && (logger_ || !inCellRun_)) takeRecordsAfterEnd();
  if (logger_) logger_->finish(outcome);
  return outcome;
}

void Run::takeRecordsAfterEnd() {
  rig_->takeDeviceRecords();
  if (!logger_) return;
  const auto step = static_cast<std::uint32_t>(logger_->log().steps.size());
  for (const DeviceEvent& e : rig_->devicesOfLastStep()) logger_->deviceEvent(step, e);
  for (const PartMotion& m : rig_->motionsOfLastStep()) logger_->partMotion(step, m);
}

void Run::waitOnCell(const vm::RunOutcome& waiting) {
  SimMachine& sim = *rig_->sim();
  Scheduler& clock = rig_->running().clock();
  // What the robot changed since (an output, a take) acts first, at now.
  const vm::IoMask inputsBefore = sim.inputs();
  if (vm::Status s = rig_->advanceCell(clock.now()); !s) return sim.endWait(s);
  if (waiting.wakeAt != vm::Status::kNever) rig_->wakeRobotAt(waiting.wakeAt);
  const std::optional<vm::Micros> next = clock.nextTime();
  if (!next) {
    // A wire without AFTER may have answered the robot at this very
    // instant (OUTSIG 1 ON, then WAITFOR on the input OUT 1 drives): the
    // machine looks at its inputs again before anything is called a deadlock.
    if (sim.inputs() != inputsBefore) return;
    sim.endWait(sim.waitDeadlock());  // only a WAITFOR waits for nothing scheduled
    return;
  }
  // A WAITFOR that only the devices may end, in a cell that goes on
  // forever: past the time limit the wait ends, and the run with it.
  if (*next > spec_.limits.maxTime && waiting.wakeAt == vm::Status::kNever) {
    if (vm::Status s = rig_->advanceCell(*next); !s) return sim.endWait(s);
    return sim.endWait(vm::Status::ok());
  }
  if (vm::Status s = rig_->advanceCell(*next); !s) sim.endWait(s);
}

RunView Run::view() const {
  const vm::Image& image = *spec_.image;
  const vm::Interpreter& vm = *interpreter_;
  RunView v;
  const Rig& rig = *rig_;
  v.clock = rig.clock();
  v.steps = vm.steps();
  v.finished = vm.finished();
  v.outcome = outcome();
  const std::uint32_t last = static_cast<std::uint32_t>(image.code.size() - 1);
  v.instruction = v.finished ? std::min(v.outcome->index, last) : std::min(vm.pc(), last);
  v.line = image.lines[v.instruction];
  for (std::uint32_t ret : vm.callStack()) v.callStack.push_back({ret - 1, image.lines[ret - 1]});
  for (std::size_t s = 0; s < image.variables.size(); ++s) v.variables.emplace_back(image.variables[s], vm.variables()[s]);
  v.motors.assign(rig.motors().begin(), rig.motors().end());
  v.tcp = rig.tcp();
  v.inputs = rig.machine().inputs();
  v.outputs = rig.machine().outputs();
  v.objects = rig.objects();
  v.events = log();
  return v;
}

RunSnapshot Run::snapshot() const {
  RunSnapshot s;
  s.vm = interpreter_->state();
  s.rig = rig_->snapshot();
  if (logger_) s.log = logger_->log().mark();
  return s;
}

void Run::restore(const RunSnapshot& s) {
  interpreter_->restore(s.vm);
  rig_->restore(s.rig);
  if (logger_ && s.log && rig_->sim()) logger_->restore(*s.log, *rig_->sim());
  cause_ = vm::StopReason::Paused;
}

bool Run::setVariable(std::uint32_t slot, std::int32_t value) {
  if (finished() || slot >= interpreter_->variables().size()) return false;
  vm::InterpreterState state = interpreter_->state();  // the interpreter's one way in: its state
  state.variables[slot] = value;
  interpreter_->restore(state);
  return true;
}

}  // namespace rs::runtime
