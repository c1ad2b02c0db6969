#include "runtime/run/run_log.h"

#include <algorithm>

namespace rs::runtime {

namespace {

// The last element whose `step` is <= step, by binary search; null if none.
template <typename T>
const T* lastUpTo(const std::vector<T>& items, std::size_t step) {
  auto it =
      std::upper_bound(items.begin(), items.end(), step, [](std::size_t s, const T& item) { return s < item.step; });
  return it == items.begin() ? nullptr : &*(it - 1);
}

}  // namespace

RunLog::Mark RunLog::mark() const {
  Mark m;
  m.steps = steps.size(), m.outputs = outputs.size(), m.cameras = cameras.size(), m.inputs = inputs.size();
  m.grasps = grasps.size(), m.variables = variables.size(), m.inputChanges = inputChanges.size(), m.end = end;
  m.devices = devices.size(), m.motions = motions.size();
  for (const auto& list : moves) m.moves.push_back(list.size());
  return m;
}

void RunLog::cutTo(const Mark& m) {
  steps.resize(m.steps), outputs.resize(m.outputs), cameras.resize(m.cameras);
  inputs.resize(m.inputs), grasps.resize(m.grasps), variables.resize(m.variables);
  inputChanges.resize(m.inputChanges);
  devices.resize(m.devices), motions.resize(m.motions);
  for (std::size_t i = 0; i < moves.size() && i < m.moves.size(); ++i) moves[i].resize(m.moves[i]);
  end = m.end;
}

vm::Micros LineThinning::slotAt(vm::Micros end, vm::Micros current) const {
  if (slot > 0 && end / slot <= kMaxFixedSlots) return std::max(current, slot);
  vm::Micros power = 1;
  while (power <= end / kSlotsPerRun / 10) power *= 10;
  return std::max(current, power);
}

namespace {

// Can `next` (a lock-step move of the same motor) join `last`: the same
// step, the motor where the last left it (it may have stood still for
// knots in between), and together within one slot?
bool joins(const MotorMove& last, const MotorMove& next, vm::Micros slot) {
  return slot > 1 && last.lockStep && next.lockStep && last.step == next.step && last.end <= next.start &&
         last.to == next.from && last.start / slot == (next.end - 1) / slot;
}

void join(MotorMove& last, const MotorMove& next) {
  last.to = next.to;
  last.end = next.end;
  last.lead = false;  // merged: a constant rate from start to end, rounded toward the start
}

}  // namespace

void thinLineMoves(std::vector<MotorMove>& moves, vm::Micros slot) {
  if (moves.empty() || slot <= 1) return;
  std::size_t kept = 0;
  for (std::size_t i = 1; i < moves.size(); ++i) {
    if (joins(moves[kept], moves[i], slot)) join(moves[kept], moves[i]);
    else moves[++kept] = moves[i];
  }
  moves.resize(kept + 1);
}

void RunLogger::addLineMove(std::size_t m, const MotorMove& move) {
  std::vector<MotorMove>& list = log_.moves[m];
  if (lines_.on) {
    if (const vm::Micros slot = lines_.slotAt(move.end, log_.lineSlot); slot != log_.lineSlot) {
      log_.lineSlot = slot;
      for (std::vector<MotorMove>& l : log_.moves) thinLineMoves(l, slot);
    }
    if (!list.empty() && joins(list.back(), move, log_.lineSlot)) {
      join(list.back(), move);
      return;
    }
  }
  list.push_back(move);
}

RunLogger::RunLogger(SimMachine& machine, const World* world, LineThinning lines, std::size_t hand)
    : machine_(machine), world_(world), lines_(lines), hand_(hand) {
  log_.motors = machine.motors();
  log_.moves.resize(log_.motors.size());
  log_.inputs.push_back({machine.now(), machine.inputs()});
  takeStateOf(machine);
  // Inputs change at stimulus times, which may fall inside a DELAY or a
  // move: the machine says when, as it applies them. Several changes at one
  // time leave one level, the last.
  machine.onInputChange([this](vm::Micros at, vm::IoMask mask) { inputChanged(at, mask); });
  // A straight line is many small moves within one step: each is kept as
  // the machine makes it, under the step in progress.
  machine.onMove([this] { recordMoves(static_cast<std::uint32_t>(log_.steps.size())); });
}

void RunLogger::inputChanged(vm::Micros at, vm::IoMask mask) {
  std::vector<InputLevel>& levels = log_.inputs;
  if (levels.back().at == at) {
    levels.back().inputs = mask;
    if (levels.size() > 1 && levels[levels.size() - 2].inputs == mask) levels.pop_back();
  } else {
    levels.push_back({at, mask});
  }
}

void RunLogger::takeStateOf(const SimMachine& machine) {
  lastSegment_.resize(machine.motors().size());
  for (std::size_t m = 0; m < lastSegment_.size(); ++m) lastSegment_[m] = machine.segment(m);
  lastPosition_.assign(machine.positions().begin(), machine.positions().end());
  lastOutputs_ = machine.outputs();
  lastView_ = machine.viewRotation();
  lastWindow_ = machine.windowShift();
  lastNow_ = machine.now();
  graspsSeen_ = world_ ? world_->eventCount() : 0;
}

// A motor whose segment changed moved, jumped (RESET) or was asked to stay
// where it was; only the first two are kept.
void RunLogger::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
  if (const vm::Instr& in = vm.image().code[index]; vm::has(in.op, vm::kWritesVariable))
    log_.variables.push_back(
        {static_cast<std::uint32_t>(log_.steps.size()), static_cast<std::uint32_t>(in.b), vm.variables()[in.b]});
  record(index);
}

void RunLogger::recordMoves(std::uint32_t step) {
  for (std::size_t m = 0; m < lastSegment_.size(); ++m) {
    const MotorSegment& s = machine_.segment(m);
    if (s == lastSegment_[m]) continue;
    lastSegment_[m] = s;
    if (s.from != s.to || s.to != lastPosition_[m]) {
      const MotorMove move{step, s.from, s.to, s.start, s.end, s.lockStep, s.lead};
      if (move.lockStep) addLineMove(m, move);
      else log_.moves[m].push_back(move);
    }
    lastPosition_[m] = s.to;
  }
}

void RunLogger::record(std::uint32_t index) {
  const auto step = static_cast<std::uint32_t>(log_.steps.size());
  const vm::Micros now = machine_.now();
  log_.steps.push_back({index, lastNow_, now});
  recordMoves(step);
  if (const vm::IoMask outputs = machine_.outputs(); outputs != lastOutputs_) {
    log_.outputs.push_back({step, outputs});
    lastOutputs_ = outputs;
  }
  if (!(machine_.viewRotation() == lastView_) || !(machine_.windowShift() == lastWindow_)) {
    lastView_ = machine_.viewRotation();
    lastWindow_ = machine_.windowShift();
    log_.cameras.push_back({step, lastView_, lastWindow_});
  }
  if (world_ && world_->eventCount() != graspsSeen_) {
    graspsSeen_ = world_->eventCount();
    // Another robot's take or let-go (a cell's shared world) is its log's.
    if (world_->lastEvent().hand == hand_) log_.grasps.push_back({step, world_->lastEvent()});
  }
  lastNow_ = now;
  log_.end = now;
}

void RunLogger::finish(const vm::RunOutcome& outcome) {
  if (!outcome.ok() && outcome.reason != vm::StopReason::StepLimit && outcome.reason != vm::StopReason::InstantLimit &&
      !outcome.paused())
    record(outcome.index);  // it did not complete: it wrote no variable
  log_.end = machine_.now();
}

void RunLogger::restore(const RunLog::Mark& mark, const SimMachine& machine) {
  log_.cutTo(mark);
  takeStateOf(machine);
}

std::int32_t positionAt(const MotorMove& move, const vm::MotorSpec& motor, vm::Micros t) {
  return positionAt(MotorSegment{move.from, move.to, move.start, move.end, move.lockStep, move.lead}, motor, t);
}

RunState stateAtStep(const RunLog& log, std::size_t step, vm::Micros t) {
  RunState s;
  s.step = step;
  s.encoders.assign(log.motors.size(), 0);
  for (std::size_t m = 0; m < log.motors.size(); ++m)
    if (const MotorMove* move = lastUpTo(log.moves[m], step)) {
      // A step of several moves (a straight line's knots): the one under way at t.
      if (move->start > t) {
        const std::vector<MotorMove>& list = log.moves[m];
        const auto first = std::lower_bound(list.begin(), list.end(), move->step,
                                            [](const MotorMove& x, std::uint32_t st) { return x.step < st; });
        const auto last = list.begin() + (move - list.data()) + 1;
        const auto at = std::upper_bound(first, last, t, [](vm::Micros v, const MotorMove& x) { return v < x.start; });
        move = &*(at == first ? first : at - 1);
      }
      s.encoders[m] = positionAt(*move, log.motors[m], t);
    }
  if (const OutputChange* o = lastUpTo(log.outputs, step)) s.outputs = o->outputs;
  if (const CameraChange* c = lastUpTo(log.cameras, step)) s.view = c->view, s.window = c->window;
  auto level = std::upper_bound(log.inputs.begin(), log.inputs.end(), t,
                                [](vm::Micros v, const InputLevel& l) { return v < l.at; });
  if (level != log.inputs.begin()) s.inputs = (level - 1)->inputs;
  return s;
}

std::int32_t variableAt(const RunLog& log, std::uint32_t slot, vm::Micros t) {
  std::int32_t value = 0;  // variables start at 0
  for (const VariableWrite& w : log.variables) {
    if (log.steps[w.step].end > t) break;
    if (w.slot == slot) value = w.value;
  }
  return value;
}

RunState stateAt(const RunLog& log, vm::Micros t) {
  auto it = std::upper_bound(log.steps.begin(), log.steps.end(), t,
                             [](vm::Micros v, const StepRecord& s) { return v < s.start; });
  if (it == log.steps.begin()) {
    RunState s = stateAtStep(log, 0, t);  // nothing ran yet: home, no outputs
    s.step.reset();
    s.encoders.assign(log.motors.size(), 0);
    s.outputs = 0;
    s.view = s.window = {};
    return s;
  }
  return stateAtStep(log, static_cast<std::size_t>(it - log.steps.begin() - 1), t);
}

}  // namespace rs::runtime
