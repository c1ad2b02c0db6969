#include "tools/testrun/run_watch.h"

#include "base/ascii.h"
#include "vm/io_lines.h"

namespace rs::testrun {

namespace {

// An event of an Order expectation, or an output turning ON for Pulses:
// ON when the line is ON, OFF when it goes OFF after having been ON.
bool turnsTo(const LineEvent& ev, vm::IoMask mask, bool& was) {
  const bool now = vm::lineIsOn(mask, ev.number);
  const bool happened = ev.on ? now : (was && !now);
  was = now;
  return happened;
}

}  // namespace

bool RunWatch::needed(const std::vector<Expectation>& expectations) {
  for (const Expectation& e : expectations) {
    switch (e.kind) {
      case ExpectKind::Output:
      case ExpectKind::Input:
      case ExpectKind::Variable:
        if (e.at || e.during) return true;
        break;
      case ExpectKind::Pulses:
      case ExpectKind::Order:
      case ExpectKind::MotorBound: return true;
      default: break;
    }
  }
  return false;
}

RunWatch::RunWatch(runtime::Run& run, const std::vector<Expectation>& expectations)
    : run_(run), expectations_(expectations), answers_(expectations.size()) {
  const vm::Image& image = *run.spec().image;
  const runtime::SimMachine& sim = *run.rig().sim();
  boundsOf_.resize(image.motors.size());
  bool anyVariable = false;
  const auto add = [&](std::size_t i) {
    Watcher w;
    w.expectation = i;
    w.window = expectations[i].during.has_value();
    watchers_.push_back(w);
    return static_cast<std::uint32_t>(watchers_.size() - 1);
  };
  for (std::size_t i = 0; i < expectations.size(); ++i) {
    const Expectation& e = expectations[i];
    const vm::Micros from = e.at ? *e.at : e.during ? e.during->first : 0;
    switch (e.kind) {
      case ExpectKind::Output:
      case ExpectKind::Input: {
        if (!e.at && !e.during) break;  // at the end: the machine answers
        const bool output = e.kind == ExpectKind::Output;
        const std::uint32_t id = add(i);
        if (e.during) (output ? onOutputs_ : onInputLevels_).push_back(id);
        queue(output ? stepProbes_ : inputProbes_, id, from, output ? ProbeKind::Output : ProbeKind::Input);
        break;
      }
      case ExpectKind::Variable: {
        if (!e.at && !e.during) break;
        std::size_t slot = 0;
        while (slot < image.variables.size() && !base::sameName(image.variables[slot], e.name)) ++slot;
        if (slot == image.variables.size()) break;  // evaluate says there is no such variable
        const std::uint32_t id = add(i);
        watchers_[id].slot = static_cast<std::uint32_t>(slot);
        if (e.during) onVariables_.push_back(id);
        queue(stepProbes_, id, from, ProbeKind::Variable);
        anyVariable = true;
        break;
      }
      case ExpectKind::Pulses: onOutputs_.push_back(add(i)); break;
      case ExpectKind::Order: {
        const std::uint32_t id = add(i);
        if (e.first.output || e.second.output) onOutputs_.push_back(id);
        if (!e.first.output || !e.second.output) onInputLevels_.push_back(id);
        break;
      }
      case ExpectKind::MotorBound: {
        std::size_t m = 0;
        while (m < image.motors.size() && image.motors[m].letter != e.motors.front().first) ++m;
        if (m < image.motors.size()) boundsOf_[m].push_back(add(i));
        break;
      }
      default: break;
    }
  }
  if (anyVariable) variables_.resize(image.variables.size());
  bool anyBound = false;
  for (const auto& b : boundsOf_) anyBound |= !b.empty();
  if (anyBound) {
    for (std::size_t m = 0; m < image.motors.size(); ++m) segments_.push_back(sim.segment(m));
    positions_.assign(sim.positions().begin(), sim.positions().end());
  }
  lastNow_ = sim.now();
  outputs_ = sim.outputs();
  inputs_ = pendingMask_ = sim.inputs();
  pendingAt_ = sim.now();
  if (!inputProbes_.empty() || !onInputLevels_.empty())
    run.onInputChange([this](vm::Micros at, vm::IoMask mask) { inputChanged(at, mask); });
}

void RunWatch::queue(ProbeQueue& q, std::uint32_t watcher, vm::Micros at, ProbeKind kind) {
  q.push({at, probesQueued_++, watcher, kind});
}

bool RunWatch::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
  step(index, &vm);
  return false;
}

void RunWatch::finish(const vm::RunOutcome& outcome) {
  if (!outcome.ok() && outcome.reason != vm::StopReason::StepLimit && outcome.reason != vm::StopReason::InstantLimit &&
      !outcome.paused())
    step(outcome.index, nullptr);  // it did not complete: it wrote no variable
  settleInputs(INT64_MAX);
  if (pending_) finishLevel();
  settleSteps(INT64_MAX);
}

// The step that just ran went from the clock of the step before to now.
// First every moment before its start is settled (the clock has passed
// it), as of the steps before; then its effects count.
void RunWatch::step(std::uint32_t index, const vm::Interpreter* vm) {
  const runtime::SimMachine& sim = *run_.rig().sim();
  const vm::Micros start = lastNow_, end = sim.now();
  settleInputs(start);
  if (pending_ && pendingAt_ < start) finishLevel();
  settleSteps(start);
  const vm::Image& image = *run_.spec().image;
  const std::uint32_t line = image.lines[index];
  if (vm && !variables_.empty()) {
    const vm::Instr& in = image.code[index];
    if (vm::has(in.op, vm::kWritesVariable)) variableWritten(in.b, vm->variables()[in.b], line, end);
  }
  if (sim.outputs() != outputs_) outputChanged(sim.outputs(), line, end);
  for (std::size_t m = 0; m < segments_.size(); ++m)
    if (!(sim.segment(m) == segments_[m])) moved(m, sim.segment(m), line);
  lastLine_ = line;
  lastNow_ = end;
}

// Inputs change at stimulus times, inside a step. A level (the mask after
// every change at one time) is settled once the clock has passed its time;
// changes at one time that end where the level before them was leave no
// level, as in a RunLog.
void RunWatch::inputChanged(vm::Micros at, vm::IoMask mask) {
  settleInputs(at);
  if (pending_ && pendingAt_ == at) {
    pendingMask_ = mask;
    if (settledMask_ && *settledMask_ == mask) pending_ = false;
  } else {
    if (pending_) finishLevel();
    pending_ = true, pendingAt_ = at, pendingMask_ = mask;
  }
  inputs_ = mask;
}

void RunWatch::finishLevel() {
  pending_ = false;
  settledMask_ = pendingMask_;
  level(pendingAt_, pendingMask_);
}

void RunWatch::level(vm::Micros at, vm::IoMask mask) {
  for (const std::uint32_t id : onInputLevels_) {
    Watcher& w = watchers_[id];
    const Expectation& e = of(w);
    WatchAnswer& a = answers_[w.expectation];
    if (e.kind == ExpectKind::Order) {
      if (!e.first.output && !a.first && turnsTo(e.first, mask, w.was[0])) a.first = at;
      if (!e.second.output && !a.second && turnsTo(e.second, mask, w.was[1])) a.second = at;
      continue;
    }
    if (w.failed || at <= e.during->first || at >= e.during->second) continue;
    if (vm::lineIsOn(mask, e.number) != e.on) windowFailed(w, inputMoment(at, mask, e.number));
  }
}

// The machine tells the watch of a change before the rig hears its cause,
// so the rig's last change is the one in effect at any moment the watch
// settles (no later change has come yet).
WatchedMoment RunWatch::inputMoment(vm::Micros at, vm::IoMask mask, int input) const {
  WatchedMoment m{at, vm::lineIsOn(mask, input) ? 1 : 0, std::nullopt, std::nullopt};
  if (const runtime::InputChangeRecord* last = run_.rig().lastInputChange(input); last && last->cause.on == (m.value != 0))
    m.change = *last;
  return m;
}

void RunWatch::windowFailed(Watcher& w, WatchedMoment m) {
  w.failed = true;
  answers_[w.expectation].moment = m;
  if (of(w).kind == ExpectKind::Input)  // which line was running: once the clock has passed
    queue(stepProbes_, static_cast<std::uint32_t>(&w - watchers_.data()), m.at, ProbeKind::InputCause);
}

// An input's value at a moment the clock has passed (no change at or before
// it is still to come).
void RunWatch::settleInputs(vm::Micros before) {
  while (!inputProbes_.empty() && inputProbes_.top().at < before) {
    const Probe p = inputProbes_.top();
    inputProbes_.pop();
    settle(p);
  }
}

void RunWatch::settleSteps(vm::Micros before) {
  while (!stepProbes_.empty() && stepProbes_.top().at < before) {
    const Probe p = stepProbes_.top();
    stepProbes_.pop();
    settle(p);
  }
}

// The write (or output change) in effect at t: the last one whose step
// ended at or before t. Only the last step seen can have ended after t
// (it started at or before t), so the one before it is then the answer.
std::optional<RunWatch::Setter> RunWatch::setterAt(const SlotHistory& h, vm::Micros t) {
  if (h.last && h.last->end <= t) return h.last;
  return h.before;
}

void RunWatch::settle(const Probe& p) {
  Watcher& w = watchers_[p.watcher];
  const Expectation& e = of(w);
  WatchAnswer& a = answers_[w.expectation];
  switch (p.kind) {
    case ProbeKind::Output: {
      const std::optional<Setter> by = setterAt(outputChanges_, p.at);
      const WatchedMoment m{p.at, vm::lineIsOn(outputs_, e.number) ? 1 : 0,
                            by ? std::optional<std::uint32_t>(by->line) : std::nullopt};
      if (!w.window)
        a.moment = m;
      else if (!w.failed && (m.value != 0) != e.on)
        windowFailed(w, m);
      break;
    }
    case ProbeKind::Input: {
      const WatchedMoment m = inputMoment(p.at, inputs_, e.number);
      if (!w.window) {
        a.moment = m;
        queue(stepProbes_, p.watcher, p.at, ProbeKind::InputCause);
      } else if (!w.failed && (m.value != 0) != e.on) {
        windowFailed(w, m);
      }
      break;
    }
    case ProbeKind::InputCause: a.moment->line = lastLine_; break;
    case ProbeKind::Variable: {
      const std::optional<Setter> by = setterAt(variables_[w.slot], p.at);
      const WatchedMoment m{p.at, by ? by->value : 0, by ? std::optional<std::uint32_t>(by->line) : std::nullopt};
      if (!w.window)
        a.moment = m;
      else if (!w.failed && m.value != e.value)
        windowFailed(w, m);
      break;
    }
  }
}

void RunWatch::outputChanged(vm::IoMask outputs, std::uint32_t line, vm::Micros end) {
  outputs_ = outputs;
  outputChanges_.before = outputChanges_.last;
  outputChanges_.last = Setter{outputs, line, end};
  for (const std::uint32_t id : onOutputs_) {
    Watcher& w = watchers_[id];
    const Expectation& e = of(w);
    WatchAnswer& a = answers_[w.expectation];
    if (e.kind == ExpectKind::Pulses) {
      const bool on = vm::lineIsOn(outputs, e.number);
      if (on && !w.was[0]) ++a.pulses;
      w.was[0] = on;
    } else if (e.kind == ExpectKind::Order) {
      if (e.first.output && !a.first && turnsTo(e.first, outputs, w.was[0])) a.first = end;
      if (e.second.output && !a.second && turnsTo(e.second, outputs, w.was[1])) a.second = end;
    } else if (!w.failed && end > e.during->first && end < e.during->second && end != w.queued) {
      w.queued = end;  // checked once the clock has passed it
      queue(stepProbes_, id, end, ProbeKind::Output);
    }
  }
}

void RunWatch::variableWritten(std::uint32_t slot, std::int32_t value, std::uint32_t line, vm::Micros end) {
  SlotHistory& h = variables_[slot];
  h.before = h.last;
  h.last = Setter{value, line, end};
  for (const std::uint32_t id : onVariables_) {
    Watcher& w = watchers_[id];
    const Expectation& e = of(w);
    if (w.slot != slot || w.failed || end <= e.during->first || end >= e.during->second || end == w.queued) continue;
    w.queued = end;
    queue(stepProbes_, id, end, ProbeKind::Variable);
  }
}

// A motor's segment changed: a move, a jump (RESET), or a move to where it
// already was, which is no move.
void RunWatch::moved(std::size_t motor, const runtime::MotorSegment& s, std::uint32_t line) {
  segments_[motor] = s;
  const bool moves = s.from != s.to || s.to != positions_[motor];
  positions_[motor] = s.to;
  if (!moves) return;
  for (const std::uint32_t id : boundsOf_[motor]) {
    const Expectation& e = of(watchers_[id]);
    WatchAnswer& a = answers_[watchers_[id].expectation];
    if (a.beyond) continue;
    const std::int32_t bound = e.motors.front().second;
    const std::int32_t reached = e.on ? std::max(s.from, s.to) : std::min(s.from, s.to);
    if (e.on ? reached > bound : reached < bound) a.beyond = WatchedMove{s.to, line, s.start, s.end};
  }
}

}  // namespace rs::testrun
