#include "tools/debug/timeline.h"

#include <algorithm>

#include "vm/io_lines.h"

namespace rs::debug {

namespace {

// A node of a std::set: the element plus three pointers and a colour.
constexpr std::size_t kSetNodeOverhead = 4 * sizeof(void*);

template <typename T>
std::size_t heapBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

}  // namespace

std::size_t snapshotBytes(const runtime::RunSnapshot& s) {
  std::size_t b = sizeof s;
  b += heapBytes(s.vm.variables) + heapBytes(s.vm.callStack) + heapBytes(s.vm.softHome) + s.vm.outcome.message.capacity();
  b += heapBytes(s.rig.machine.positions) + heapBytes(s.rig.machine.segments) + heapBytes(s.rig.machine.path);
  b += s.rig.machine.schedule.reactive.size() * (sizeof(runtime::InputSchedule::State::Pending) + kSetNodeOverhead);
  if (s.rig.cell.world) b += heapBytes(s.rig.cell.world->grasp.resting) + heapBytes(s.rig.cell.world->grasp.letGo);
  b += s.rig.cell.clock.queue.size() * (sizeof(runtime::CellEvent) + kSetNodeOverhead);
  if (s.log) b += heapBytes(s.log->moves);
  b += heapBytes(s.rig.collisions);
  for (const runtime::CollisionEvent& e : s.rig.collisions) b += heapBytes(e.encoders);
  return b;
}

Timeline::Timeline(runtime::Run& run, std::uint64_t interval, std::size_t budget, std::uint64_t knotInterval)
    : run_(run), interval_(std::max<std::uint64_t>(interval, 1)), budget_(budget),
      knotInterval_(std::max<std::uint64_t>(knotInterval, 1)) {
  keep();
}

void Timeline::keep() {
  const std::uint64_t steps = run_.interpreter().steps();
  if (snapshots_.count(steps)) return;
  Stored s{run_.snapshot(), editsApplied_, run_.rig().clock(), run_.knots(), 0};
  s.bytes = snapshotBytes(s.snapshot);
  bytes_ += s.bytes;
  snapshots_.emplace(steps, std::move(s));
  thin();
}

// Over budget: twice the intervals, and every other snapshot dropped (the
// start always stays): the stretches between those left are at most twice
// as long, in instructions and in knots.
void Timeline::thin() {
  while (bytes_ > budget_ && snapshots_.size() > 2) {
    interval_ *= 2;
    knotInterval_ *= 2;
    bool drop = true;
    for (auto it = std::next(snapshots_.begin()); it != snapshots_.end(); drop = !drop) {
      if (!drop) {
        ++it;
        continue;
      }
      bytes_ -= it->second.bytes;
      it = snapshots_.erase(it);
    }
  }
}

// From the latest snapshot at or before the present: K instructions or W
// knots on, or the next snapshot kept already (a replay passes by it), or
// the next edit, whichever comes first.
Timeline::Boundary Timeline::nextBoundary() const {
  const std::uint64_t steps = run_.interpreter().steps();
  auto after = snapshots_.upper_bound(steps);
  const Stored& last = std::prev(after)->second;  // the start is always kept
  const std::uint64_t lastSteps = std::prev(after)->first;
  Boundary b{lastSteps + interval_, lastSteps + interval_, last.knots + knotInterval_};
  if (after != snapshots_.end()) b.steps = std::min(b.steps, after->first);
  if (editsApplied_ < edits_.size()) b.steps = std::min(b.steps, edits_[editsApplied_].steps);
  return b;
}

void Timeline::applyDueEdits() {
  const std::uint64_t steps = run_.interpreter().steps();
  while (editsApplied_ < edits_.size() && edits_[editsApplied_].steps <= steps && !run_.finished()) {
    const Edit& e = edits_[editsApplied_++];
    if (e.kind == Edit::Kind::Input) run_.rig().setInput(e.input, e.on);
    else run_.setVariable(e.slot, e.value);
  }
}

vm::RunOutcome Timeline::forward(const runtime::RunUntil& until, const std::function<bool()>& interrupted) {
  interrupted_ = false;
  runtime::RunUntil slice;
  slice.time = until.time;
  slice.instructions = until.instructions;
  slice.lines = until.lines;
  if (until.when) slice.when = [&until](const runtime::Run& r) { return until.when(r); };
  const vm::Image& image = *run_.spec().image;
  const std::uint64_t stepEnd = until.stepEnd(run_.interpreter().steps());
  for (;;) {
    applyDueEdits();
    const Boundary boundary = nextBoundary();
    const std::uint64_t cap = std::min(stepEnd, boundary.steps);
    slice.steps = cap;
    slice.knots = std::max(boundary.knots, run_.knots() + 1);
    const vm::RunOutcome outcome = run_.runUntil(slice);
    if (!outcome.paused()) return outcome;
    const std::uint64_t steps = run_.interpreter().steps();
    const bool knotBoundary = run_.knots() >= slice.knots;
    if (steps >= boundary.snapshot || knotBoundary) keep();
    // The moment after `steps` instructions is the one with its edits made:
    // wherever the run stops, they are in (the snapshot just kept is the
    // moment before them, and says so).
    applyDueEdits();
    // A slice ends at our own boundary; the run's other reasons to pause
    // (or the caller's) stop here. At the boundary the run names the step
    // count first, so the caller's time, instructions and lines are
    // looked at again.
    const bool ownBoundary =
        run_.pauseCause() == vm::StopReason::Step && ((steps == cap && cap < stepEnd) || (knotBoundary && steps < stepEnd));
    if (!ownBoundary) return outcome;
    const std::uint32_t pc = run_.interpreter().pc();
    if (run_.rig().clock() > until.time) return outcome;
    if (std::find(until.instructions.begin(), until.instructions.end(), pc) != until.instructions.end()) return outcome;
    if (pc < image.code.size() && (pc == 0 || image.lines[pc - 1] != image.lines[pc]) &&
        std::find(until.lines.begin(), until.lines.end(), image.lines[pc]) != until.lines.end())
      return outcome;
    if (interrupted && interrupted()) {
      interrupted_ = true;
      return outcome;
    }
  }
}

void Timeline::restoreAtOrBefore(std::uint64_t steps) {
  auto it = snapshots_.upper_bound(steps);
  --it;  // the start is always kept
  const std::uint64_t now = run_.interpreter().steps();
  if (now <= steps && now >= it->first && !run_.finished()) return;  // going on from here is no longer
  run_.restore(it->second.snapshot);
  editsApplied_ = it->second.editsApplied;
}

void Timeline::goToStep(std::uint64_t steps) {
  if (run_.finished() && steps >= run_.interpreter().steps()) return;
  restoreAtOrBefore(steps);
  runtime::RunUntil until;
  until.steps = steps;
  forward(until);
}

void Timeline::goToTime(vm::Micros t) {
  // The latest snapshot whose clock has not passed t (clocks never go back).
  auto it = snapshots_.end();
  do --it;
  while (it != snapshots_.begin() && it->second.clock > t);
  const bool fromHere = !run_.finished() && run_.rig().clock() <= t && run_.interpreter().steps() >= it->first;
  if (!fromHere) {
    if (run_.finished() && run_.rig().clock() <= t) return;  // the run ended before t
    run_.restore(it->second.snapshot);
    editsApplied_ = it->second.editsApplied;
  }
  runtime::RunUntil until;
  until.time = t;
  forward(until);
}

std::optional<std::uint64_t> Timeline::lastMatch(const std::function<void(const runtime::Run&)>& reset,
                                                 const std::function<bool(const runtime::Run&)>& matches) {
  const std::uint64_t present = run_.interpreter().steps();
  if (present == 0) return std::nullopt;
  std::optional<std::uint64_t> found;
  std::uint64_t last = present - 1;  // the latest moment the next stretch covers
  while (last > 0) {  // the start itself never matches
    auto it = snapshots_.lower_bound(last);
    --it;  // the latest snapshot before `last`: the start at worst
    const std::uint64_t first = it->first;
    run_.restore(it->second.snapshot);
    editsApplied_ = it->second.editsApplied;
    reset(run_);
    runtime::RunUntil until;
    until.steps = last;
    until.when = [&](const runtime::Run& r) {
      if (matches(r)) found = r.interpreter().steps();
      return false;
    };
    forward(until);
    if (found) break;
    last = first;
  }
  goToStep(found ? *found : present);
  return found;
}

bool Timeline::setInput(int input, bool on) {
  if (!vm::isIoLine(input)) return false;
  Edit e;
  e.kind = Edit::Kind::Input;
  e.input = input;
  e.on = on;
  return record(e);
}

bool Timeline::setVariable(std::uint32_t slot, std::int32_t value) {
  if (slot >= run_.spec().image->variables.size()) return false;
  Edit e;
  e.kind = Edit::Kind::Variable;
  e.slot = slot;
  e.value = value;
  return record(e);
}

bool Timeline::record(const Edit& edit) {
  if (run_.finished()) return false;
  const std::uint64_t steps = run_.interpreter().steps();
  applyDueEdits();
  // That future is gone: later edits and snapshots with it.
  edits_.resize(editsApplied_);
  for (auto it = snapshots_.upper_bound(steps); it != snapshots_.end();) {
    bytes_ -= it->second.bytes;
    it = snapshots_.erase(it);
  }
  const bool made = edit.kind == Edit::Kind::Input ? run_.rig().setInput(edit.input, edit.on)
                                                   : run_.setVariable(edit.slot, edit.value);
  if (!made) return false;
  edits_.push_back(edit);
  edits_.back().steps = steps;
  editsApplied_ = edits_.size();
  return true;
}

}  // namespace rs::debug
