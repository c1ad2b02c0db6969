#include "runtime/render/recording.h"

#include <algorithm>
#include <limits>
#include <set>

#include "runtime/input_schedule.h"

namespace rs::render {

namespace {

vm::Micros later(vm::Micros t, vm::Micros delay) {
  delay = std::max<vm::Micros>(delay, 0);
  return t > std::numeric_limits<vm::Micros>::max() - delay ? std::numeric_limits<vm::Micros>::max() : t + delay;
}

// The last element whose `step` is <= step, by binary search; null if none.
template <typename T>
const T* lastUpTo(const std::vector<T>& items, std::size_t step) {
  auto it =
      std::upper_bound(items.begin(), items.end(), step, [](std::size_t s, const T& item) { return s < item.step; });
  return it == items.begin() ? nullptr : &*(it - 1);
}

}  // namespace

RunRecorder::RunRecorder(const runtime::SimMachine& machine, const runtime::GraspObserver* grasp)
    : machine_(machine),
      grasp_(grasp),
      lastSegment_(machine.motors().size()),
      lastPosition_(machine.positions().begin(), machine.positions().end()),
      lastOutputs_(machine.outputs()),
      lastView_(machine.viewRotation()),
      lastWindow_(machine.windowShift()),
      lastNow_(machine.now()) {
  rec_.motors = machine.motors();
  rec_.moves.resize(rec_.motors.size());
  for (std::size_t m = 0; m < lastSegment_.size(); ++m) lastSegment_[m] = machine.segment(m);
}

// The grasp observer has already seen this step (the recorder is its
// `next`); the instruction that stops a run early (finish) never reaches
// it, so it is not asked there.
void RunRecorder::afterStep(const vm::Interpreter&, std::uint32_t index) {
  record(index);
  if (!grasp_ || !grasp_->lastChange()) return;
  const workcell::GraspChange& c = *grasp_->lastChange();
  const auto step = static_cast<std::uint32_t>(rec_.steps.size() - 1);
  const StepRecord& s = rec_.steps.back();
  const workcell::Grasping& g = grasp_->grasping();
  rec_.grasps.push_back(
      {step, c.held ? s.end : s.start, c.object, c.held, c.held ? g.heldOffset() : g.restingPose(c.object)});
}

// A motor whose segment changed moved, jumped (RESET) or was asked to stay
// where it was; only the first two are kept.
void RunRecorder::record(std::uint32_t index) {
  const auto step = static_cast<std::uint32_t>(rec_.steps.size());
  const vm::Micros now = machine_.now();
  rec_.steps.push_back({index, lastNow_, now});
  for (std::size_t m = 0; m < lastSegment_.size(); ++m) {
    const runtime::MotorSegment& s = machine_.segment(m);
    if (s == lastSegment_[m]) continue;
    lastSegment_[m] = s;
    if (s.from != s.to || s.to != lastPosition_[m]) rec_.moves[m].push_back({step, s.from, s.to, s.start, s.end});
    lastPosition_[m] = s.to;
  }
  if (const std::uint8_t outputs = machine_.outputs(); outputs != lastOutputs_) {
    for (int line = 1; line <= 8; ++line)
      if (const std::uint8_t bit = runtime::lineBit(line); (outputs ^ lastOutputs_) & bit)
        outputEvents_.push_back({now, line, (outputs & bit) != 0});
    rec_.outputs.push_back({step, outputs});
    lastOutputs_ = outputs;
  }
  if (!(machine_.viewRotation() == lastView_) || !(machine_.windowShift() == lastWindow_)) {
    lastView_ = machine_.viewRotation();
    lastWindow_ = machine_.windowShift();
    rec_.cameras.push_back({step, lastView_, lastWindow_});
  }
  inputsAtEnd_.push_back(machine_.inputs());
  lastNow_ = now;
}

// Inputs change at stimulus times, which may fall inside a DELAY or a move,
// so the levels are rebuilt the way SimMachine applies them: the timed
// changes, plus the rules each output change fires, through the same
// InputSchedule. Checked against the inputs seen at every step's end.
RunRecording RunRecorder::finish(const vm::RunOutcome& outcome, const runtime::Stimuli& stimuli) {
  if (!outcome.ok() && outcome.reason != vm::StopReason::StepLimit) record(outcome.index);
  rec_.end = machine_.now();

  runtime::InputSchedule schedule(stimuli.changes, 64);
  std::set<vm::Micros> due;
  for (const runtime::InputChange& c : stimuli.changes) due.insert(c.at);
  std::uint8_t mask = 0;
  schedule.applyUntil(0, mask);
  std::vector<InputLevel> levels{{0, mask}};
  const auto advanceTo = [&](vm::Micros t) {
    while (!due.empty() && *due.begin() <= t) {
      const vm::Micros at = *due.begin();
      due.erase(due.begin());
      schedule.applyUntil(at, mask);
      if (mask != levels.back().inputs) levels.push_back({at, mask});
    }
  };
  for (const OutputEvent& e : outputEvents_) {
    advanceTo(e.at);
    for (const runtime::ReactiveRule& rule : stimuli.rules)
      if (rule.output == e.output && rule.outputOn == e.on) {
        schedule.schedule({later(e.at, rule.delay), rule.input, rule.inputOn});
        due.insert(later(e.at, rule.delay));
      }
    advanceTo(e.at);
  }
  advanceTo(rec_.end);

  // Several instructions can run at one instant; the levels hold what the
  // last of them saw, so only that one is compared.
  bool consistent = true;
  for (std::size_t k = 0; k < inputsAtEnd_.size() && consistent; ++k) {
    const vm::Micros t = rec_.steps[k].end;
    if (k + 1 < inputsAtEnd_.size() && rec_.steps[k + 1].end == t) continue;
    auto it =
        std::upper_bound(levels.begin(), levels.end(), t, [](vm::Micros v, const InputLevel& l) { return v < l.at; });
    consistent = (it - 1)->inputs == inputsAtEnd_[k];
  }
  if (consistent) {
    rec_.inputs = std::move(levels);
  } else {  // never expected; fall back to what each step's end saw
    rec_.inputs = {{0, 0}};
    for (std::size_t k = 0; k < inputsAtEnd_.size(); ++k)
      if (inputsAtEnd_[k] != rec_.inputs.back().inputs) rec_.inputs.push_back({rec_.steps[k].end, inputsAtEnd_[k]});
  }
  return std::move(rec_);
}

std::int32_t positionAt(const MotorMove& move, std::int32_t speed, vm::Micros t) {
  return runtime::positionAt({move.from, move.to, move.start, move.end}, speed, t);
}

RunState stateAtStep(const RunRecording& rec, std::size_t step, vm::Micros t) {
  RunState s;
  s.step = step;
  s.encoders.assign(rec.motors.size(), 0);
  for (std::size_t m = 0; m < rec.motors.size(); ++m)
    if (const MotorMove* move = lastUpTo(rec.moves[m], step)) s.encoders[m] = positionAt(*move, rec.motors[m].speed, t);
  if (const OutputChange* o = lastUpTo(rec.outputs, step)) s.outputs = o->outputs;
  if (const CameraChange* c = lastUpTo(rec.cameras, step)) s.view = c->view, s.window = c->window;
  auto level = std::upper_bound(rec.inputs.begin(), rec.inputs.end(), t,
                                [](vm::Micros v, const InputLevel& l) { return v < l.at; });
  if (level != rec.inputs.begin()) s.inputs = (level - 1)->inputs;
  return s;
}

RunState stateAt(const RunRecording& rec, vm::Micros t) {
  auto it = std::upper_bound(rec.steps.begin(), rec.steps.end(), t,
                             [](vm::Micros v, const StepRecord& s) { return v < s.start; });
  if (it == rec.steps.begin()) {
    RunState s = stateAtStep(rec, 0, t);  // nothing ran yet: home, no outputs
    s.step.reset();
    s.encoders.assign(rec.motors.size(), 0);
    s.outputs = 0;
    s.view = s.window = {};
    return s;
  }
  return stateAtStep(rec, static_cast<std::size_t>(it - rec.steps.begin() - 1), t);
}

}  // namespace rs::render
