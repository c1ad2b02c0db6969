#include "tools/debug/debug_session.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "runtime/run/empty_close.h"
#include "tools/debug/input_causes.h"
#include "vm/io_lines.h"

namespace rs::debug {

// Where a forward run is going, besides the breakpoints.
struct DebugSession::Target {
  std::uint64_t steps = UINT64_MAX;
  vm::Micros time = INT64_MAX;
  std::function<bool(const runtime::Run&)> done;  // the command's own end (next, finish)
  bool breakpoints = true;
};

// The values at the moment before, for the stops that happen as something
// changes: the clock (time breakpoints), the collisions found and the
// closes on nothing so far, each `when` breakpoint's truth, each watched
// value.
class DebugSession::Probe {
 public:
  explicit Probe(const DebugSession& s) : s_(s) {}
  void capture(const runtime::Run& r) {
    clock = r.rig().clock();
    collisions = r.rig().collisions().size();
    emptyCloses = r.rig().world() ? r.rig().world()->emptyCloseCount() : 0;
    held.resize(s_.breakpoints_.size());
    for (std::size_t i = 0; i < held.size(); ++i)
      held[i] = s_.breakpoints_[i].kind == Breakpoint::Kind::When && s_.breakpoints_[i].when.holds(r);
    values.resize(s_.watches_.size());
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = valueOf(r, s_.watches_[i].what);
  }
  vm::Micros clock = 0;
  std::size_t collisions = 0;
  std::uint64_t emptyCloses = 0;
  std::vector<bool> held;
  std::vector<std::int64_t> values;

 private:
  const DebugSession& s_;
};

DebugSession::DebugSession(runtime::RunSpec spec, SessionOptions options) {
  spec.log = false;
  run_ = std::make_unique<runtime::Run>(std::move(spec));
  timeline_ = std::make_unique<Timeline>(*run_, options.snapshotInterval, options.snapshotBudget,
                                         options.snapshotKnots);
  stop_ = {StopReason::Entry, "at the start of the run", {}};
}

DebugSession::~DebugSession() = default;

// --- breakpoints -------------------------------------------------------------

std::uint32_t DebugSession::lineWithCode(std::uint32_t line) const {
  std::uint32_t best = 0;
  for (std::uint32_t l : run_->spec().image->lines)
    if (l >= line && (best == 0 || l < best)) best = l;
  return best;
}

namespace {

// The first instruction of each run of instructions on `line`.
std::vector<std::uint32_t> lineStarts(const vm::Image& image, std::uint32_t line) {
  std::vector<std::uint32_t> at;
  for (std::uint32_t i = 0; i < image.code.size(); ++i)
    if (image.lines[i] == line && (i == 0 || image.lines[i - 1] != line)) at.push_back(i);
  return at;
}

}  // namespace

diag::Result<int> DebugSession::breakAtLine(std::uint32_t line) {
  const std::uint32_t at = lineWithCode(line);
  if (at == 0) return diag::refusal(fmt::format("no instruction on line {} or after it", line));
  Breakpoint b;
  b.line = at;
  b.instructions = lineStarts(*run_->spec().image, at);
  return add(Breakpoint::Kind::Line, std::move(b));
}

diag::Result<int> DebugSession::breakAtLabel(std::string_view label) {
  auto b = labelBreakpoint(*run_->spec().image, label);
  if (!b) return b.failure();
  return add(Breakpoint::Kind::Label, std::move(*b));
}

diag::Result<int> DebugSession::breakAtInstruction(std::uint32_t index) {
  auto b = instructionBreakpoint(*run_->spec().image, index);
  if (!b) return b.failure();
  return add(Breakpoint::Kind::Instruction, std::move(*b));
}

diag::Result<int> DebugSession::breakAtTime(vm::Micros t) {
  if (t < 0) return diag::refusal("a time is not negative");
  Breakpoint b;
  b.time = t;
  return add(Breakpoint::Kind::Time, std::move(b));
}

int DebugSession::breakOnCollision() {
  return add(Breakpoint::Kind::Collision, {});
}

int DebugSession::breakOnWarning() {
  return add(Breakpoint::Kind::Warning, {});
}

int DebugSession::breakOnDevice(DevicePoint point) {
  Breakpoint b;
  b.device = std::move(point);
  return add(Breakpoint::Kind::Device, std::move(b));
}

int DebugSession::breakWhen(Condition condition) {
  Breakpoint b;
  b.when = std::move(condition);
  return add(Breakpoint::Kind::When, std::move(b));
}

int DebugSession::add(Breakpoint::Kind kind, Breakpoint b) {
  b.id = nextId();
  b.kind = kind;
  breakpoints_.push_back(std::move(b));
  return breakpoints_.back().id;
}

Breakpoint* DebugSession::find(int id) {
  for (Breakpoint& b : breakpoints_)
    if (b.id == id) return &b;
  return nullptr;
}

bool DebugSession::qualify(int id, std::optional<Condition> condition, std::optional<HitCondition> hits) {
  Breakpoint* b = find(id);
  if (!b) return false;
  b->condition = std::move(condition);
  b->hits = hits;
  return true;
}

int DebugSession::watch(Expression what) {
  watches_.push_back({nextId(), std::move(what)});
  return watches_.back().id;
}

bool DebugSession::remove(int id) { return eraseId(breakpoints_, id) || eraseId(watches_, id); }

void DebugSession::removeAll() {
  breakpoints_.clear();
  watches_.clear();
}

// --- where the run stops ------------------------------------------------------

std::function<std::optional<std::string>(int)> DebugSession::describer() {
  return [this](int id) -> std::optional<std::string> {
    if (const Breakpoint* b = find(id)) return b->describe();
    return std::nullopt;
  };
}

// Does a breakpoint or watch stop the run at this moment (`before` holds
// the moment before)? `counting`: going forwards, so hits count and hit
// conditions apply. The ids that stop it, and for watches what changed.
bool DebugSession::stopsHere(const runtime::Run& r, const Probe& before, bool counting, std::vector<int>& ids,
                             std::vector<std::string>& notes, std::vector<std::string>& happened) {
  const std::uint32_t pc = r.interpreter().pc();
  for (std::size_t i = 0; i < breakpoints_.size(); ++i) {
    Breakpoint& b = breakpoints_[i];
    bool at = false;
    switch (b.kind) {
      case Breakpoint::Kind::Line:
      case Breakpoint::Kind::Label:
      case Breakpoint::Kind::Instruction:
        at = std::find(b.instructions.begin(), b.instructions.end(), pc) != b.instructions.end();
        break;
      case Breakpoint::Kind::Time:
        at = before.clock <= b.time && r.rig().clock() > b.time;
        break;
      case Breakpoint::Kind::When:
        at = b.when.holds(r) && !(i < before.held.size() && before.held[i]);
        break;
      case Breakpoint::Kind::Collision:
        at = r.rig().collisions().size() > before.collisions;
        break;
      case Breakpoint::Kind::Warning:
        at = r.rig().world() && r.rig().world()->emptyCloseCount() > before.emptyCloses;
        break;
      case Breakpoint::Kind::Device: {
        const auto events = r.rig().devicesOfLastStep();
        at = std::any_of(events.begin(), events.end(), [&](const runtime::DeviceEvent& e) { return b.device.matches(e); });
        break;
      }
    }
    if (!at || (b.condition && !b.condition->holds(r))) continue;
    if (counting && ++b.hitCount && b.hits && !b.hits->stopsAt(b.hitCount)) continue;
    ids.push_back(b.id);
    if (b.kind == Breakpoint::Kind::When)
      if (std::string h = conditionCause(r, b.when);
          !h.empty() && std::find(happened.begin(), happened.end(), h) == happened.end())
        happened.push_back(std::move(h));
    if (b.kind == Breakpoint::Kind::Device)
      for (std::string& h : deviceHits(r, b.device))
        if (std::find(happened.begin(), happened.end(), h) == happened.end()) happened.push_back(std::move(h));
  }
  for (std::size_t i = 0; i < watches_.size(); ++i) {
    const std::int64_t now = valueOf(r, watches_[i].what);
    if (i < before.values.size() && now != before.values[i]) {
      ids.push_back(watches_[i].id);
      notes.push_back(fmt::format("{} changed from {} to {}{}", base::safeText(watches_[i].what.name), before.values[i],
                                  now, causeAside(r, watches_[i].what, now)));
    }
  }
  return !ids.empty();
}

runtime::RunView DebugSession::view() const {
  runtime::RunView v = run_->view();
  if (!moment_) return v;  // set in a finished run only at the collision that ended it
  const runtime::Rig& rig = run_->rig();
  v.clock = moment_->time;
  v.motors = rig.motorsAt(moment_->time);
  if (const runtime::World* world = rig.world()) v.tcp = world->tcp(v.motors);
  v.objects = rig.objects(moment_->time);
  v.instruction = moment_->instruction;
  v.line = run_->spec().image->lines[moment_->instruction];
  v.steps = v.steps > 0 ? v.steps - 1 : 0;  // the instruction under way is not done
  // Inside the move a collision ends, before its contact: not over yet.
  if (const runtime::CollisionEvent* hit = endingCollision(); hit && moment_->time < hit->at) {
    v.finished = false;
    v.outcome.reset();
  }
  return v;
}

std::uint64_t DebugSession::emptyCloses() const {
  const runtime::World* world = run_->rig().world();
  return world ? world->emptyCloseCount() : 0;
}

std::string DebugSession::emptyCloseNote(std::uint64_t emptyClosesBefore) const {
  const std::uint64_t now = emptyCloses();
  if (now <= emptyClosesBefore || !run_->rig().cell()) return {};
  const std::string nearest = runtime::emptyCloseText(run_->rig().world()->lastEmptyClose(), *run_->rig().cell());
  const std::string times = now - emptyClosesBefore == 1 ? std::string() : fmt::format(" ({} times)", now - emptyClosesBefore);
  return fmt::format("the gripper closed on nothing{}{}", times, nearest.empty() ? "" : ": " + nearest);
}

bool DebugSession::standAtCollision(const std::vector<int>& ids) {
  const bool collisionStop = std::any_of(ids.begin(), ids.end(), [this](int id) {
    const Breakpoint* b = find(id);
    return b && b->kind == Breakpoint::Kind::Collision;
  });
  const auto events = run_->rig().collisions();
  if (!collisionStop || events.empty()) return false;
  const runtime::CollisionEvent& e = events.back();
  if (e.at < run_->rig().clock() && e.instruction < run_->spec().image->code.size()) moment_ = Moment{e.at, e.instruction};
  return true;
}

void DebugSession::standWithin(vm::Micros t) {
  const std::uint64_t steps = run_->interpreter().steps();
  // A run a collision ended (before t: gotoTime) stood in its last move at t.
  if (steps == 0 || (run_->finished() && !endingCollision()) || run_->rig().clock() <= t) return;
  timeline_->goToStep(steps - 1);
  if (run_->rig().clock() == t) return;  // t falls between two instructions: stand there
  const std::uint32_t underWay = run_->interpreter().pc();
  timeline_->goToStep(steps);
  moment_ = Moment{t, underWay};
}

const runtime::CollisionEvent* DebugSession::endingCollision() const {
  if (!run_->finished() || run_->spec().collisions != runtime::CollisionMode::Error) return nullptr;
  const vm::RunOutcome outcome = *run_->outcome();
  const auto events = run_->rig().collisions();
  if (outcome.reason != StopReason::RuntimeError || events.empty()) return nullptr;
  const runtime::CollisionEvent& e = events.back();
  return e.instruction == outcome.index ? &e : nullptr;
}

Stop DebugSession::collisionEnd(Stop stop) {
  const runtime::CollisionEvent* e = endingCollision();
  if (!e) return stop;
  if (e->instruction < run_->spec().image->code.size()) moment_ = Moment{e->at, e->instruction};
  std::string breakpoints;
  for (Breakpoint& b : breakpoints_) {
    if (b.kind != Breakpoint::Kind::Collision || (b.condition && !b.condition->holds(*run_))) continue;
    stop.breakpoints.push_back(b.id);
    breakpoints += fmt::format("breakpoint {} ({}): ", b.id, b.describe());
  }
  stop.message = breakpoints + stop.message;
  return stop;
}

std::string DebugSession::collisionText() const {
  const auto events = run_->rig().collisions();
  const runtime::CollisionWatch* watch = run_->rig().collisionWatch();
  if (events.empty() || !watch) return {};
  const runtime::CollisionEvent& e = events.back();
  return fmt::format("{} at {} s", watch->describe(e.contact), base::formatSeconds(e.at));
}

Stop DebugSession::finishedStop(bool already) const {
  const vm::RunOutcome outcome = *run_->outcome();
  Stop s;
  s.reason = outcome.reason;
  std::string what = outcome.ok() ? std::string("the program ended")
                                  : fmt::format("{}: {}", vm::debuggerName(s.reason), base::safeText(outcome.message));
  // What `robotsim run` warns about at the end, said where the run ends.
  if (const auto w = runtime::gripperWarning(*run_, run_->spec().image->sourceName))
    what += fmt::format("; warning at line {}: {}", w->pos.line, base::safeText(w->message));
  s.message = already ? fmt::format("the run is over ({}); go back with reverse-step or goto-time", what) : what;
  return s;
}

Stop DebugSession::stopped(Stop stop) {
  stop_ = stop;
  for (const StopObserver& o : observers_) o(*this, stop_);
  return stop_;
}

Stop DebugSession::forward(const Target& target) {
  // At the end there is no forwards: the session stays where it stands (a
  // collision's contact), or from a moment of the move before the contact
  // goes on to it.
  if (run_->finished()) {
    const runtime::CollisionEvent* hit = endingCollision();
    if (hit && moment_ && moment_->time < hit->at) return stopped(collisionEnd(finishedStop(false)));
    return stopped(finishedStop(true));
  }
  const bool within = moment_.has_value();
  moment_.reset();
  const std::uint64_t closesBefore = emptyCloses();
  Probe probe(*this);
  probe.capture(*run_);
  std::vector<int> ids;
  std::vector<std::string> notes, happened;
  bool done = false;
  // From inside an instruction under way, the run already stands after it:
  // that moment (the instruction finished) is the first one forwards.
  bool already = false;
  if (within) {
    if (target.breakpoints) already = stopsHere(*run_, probe, true, ids, notes, happened);
    if (run_->interpreter().steps() >= target.steps || (target.done && target.done(*run_))) done = already = true;
  }
  runtime::RunUntil until;
  until.steps = target.steps;
  until.time = target.time;
  until.when = [&](const runtime::Run& r) {
    ids.clear();
    notes.clear();
    happened.clear();
    bool stop = false;
    if (target.breakpoints) stop = stopsHere(r, probe, true, ids, notes, happened);
    if (target.done && target.done(r)) done = stop = true;
    probe.capture(r);
    return stop;
  };
  // Nothing to look at after each step: the interpreter runs unwatched.
  const bool watched = target.breakpoints && (!breakpoints_.empty() || !watches_.empty());
  if (!watched && !target.done) until.when = nullptr;
  if (!already) timeline_->forward(until, interrupted_);
  if (run_->finished()) {
    Stop s = collisionEnd(finishedStop(false));
    s.note = emptyCloseNote(closesBefore);
    return stopped(std::move(s));
  }
  Stop s;
  if (!already && timeline_->wasInterrupted()) {
    s = {StopReason::Pause, "interrupted", {}};
  } else if (!ids.empty()) {
    const bool onlyWatches = std::none_of(ids.begin(), ids.end(), [this](int id) { return find(id) != nullptr; });
    s.reason = onlyWatches ? StopReason::Watch : StopReason::Breakpoint;
    s.breakpoints = ids;
    s.message = stopText(ids, describer(), notes, happened);
    if (standAtCollision(ids)) s.message += ": " + collisionText();
  } else if (done || run_->interpreter().steps() >= target.steps) {
    s = {StopReason::Step, "step done", {}};
  } else if (run_->rig().clock() > target.time) {
    s = {StopReason::Time, fmt::format("the clock passed {} s", base::formatSeconds(target.time)), {}};
  } else {
    s = {StopReason::Pause, "paused", {}};
  }
  s.note = emptyCloseNote(closesBefore);
  return stopped(std::move(s));
}

Stop DebugSession::step(std::uint64_t n) {
  Target t;
  // Inside an instruction under way, it is not done yet: it is the first.
  const std::uint64_t now = run_->interpreter().steps() - (moment_ ? 1 : 0);
  t.steps = now + std::min(n, UINT64_MAX - now);
  return forward(t);
}

Stop DebugSession::next() {
  Target t;
  const std::size_t depth = run_->interpreter().callDepth();
  t.done = [depth](const runtime::Run& r) { return r.interpreter().callDepth() <= depth; };
  return forward(t);
}

diag::Result<Stop> DebugSession::finish() {
  const std::size_t depth = run_->interpreter().callDepth();
  if (depth == 0 || run_->finished()) return diag::refusal("not in a subroutine: the call stack is empty");
  Target t;
  t.done = [depth](const runtime::Run& r) { return r.interpreter().callDepth() < depth; };
  return forward(t);
}

Stop DebugSession::resume() { return forward({}); }

Stop DebugSession::until(vm::Micros time) {
  // Inside an instruction under way that ends after `time`: that moment.
  if (moment_ && time >= moment_->time && time < run_->rig().clock()) return gotoTime(time);
  Target t;
  t.time = time;
  if (run_->rig().clock() > time && !run_->finished())
    return stopped({StopReason::Time, fmt::format("the clock is already past {} s", base::formatSeconds(time)), {}});
  return forward(t);
}

// --- backwards ------------------------------------------------------------------

Stop DebugSession::reverseStep(std::uint64_t n) {
  moment_.reset();
  const std::uint64_t now = run_->interpreter().steps();
  if (now == 0) return stopped({StopReason::Start, "already at the start of the run", {}});
  timeline_->goToStep(now - std::min(n, now));
  if (run_->interpreter().steps() == 0) return stopped({StopReason::Start, "at the start of the run", {}});
  return stopped({StopReason::Step, "step back done", {}});
}

Stop DebugSession::reverseNext() {
  moment_.reset();
  if (run_->interpreter().steps() == 0) return stopped({StopReason::Start, "already at the start of the run", {}});
  const std::size_t depth = run_->interpreter().callDepth();
  const auto found = timeline_->lastMatch([](const runtime::Run&) {},
                                          [depth](const runtime::Run& r) { return r.interpreter().callDepth() <= depth; });
  if (!found) {
    timeline_->goToStep(0);
    return stopped({StopReason::Start, "at the start of the run", {}});
  }
  return stopped({StopReason::Step, "step back done", {}});
}

Stop DebugSession::reverseContinue() {
  moment_.reset();
  if (run_->interpreter().steps() == 0) return stopped({StopReason::Start, "already at the start of the run", {}});
  Probe probe(*this);
  std::vector<int> ids, foundIds;
  std::vector<std::string> notes, foundNotes, happened, foundHappened;
  const auto found = timeline_->lastMatch([&](const runtime::Run& r) { probe.capture(r); },
                                          [&](const runtime::Run& r) {
                                            ids.clear(), notes.clear(), happened.clear();
                                            const bool match = stopsHere(r, probe, false, ids, notes, happened);
                                            if (match) foundIds = ids, foundNotes = notes, foundHappened = happened;
                                            probe.capture(r);
                                            return match;
                                          });
  if (!found) {
    timeline_->goToStep(0);
    return stopped({StopReason::Start, "at the start of the run: no breakpoint or watch stops before", {}});
  }
  Stop s;
  const bool onlyWatches = std::none_of(foundIds.begin(), foundIds.end(), [this](int id) { return find(id) != nullptr; });
  s.reason = onlyWatches ? StopReason::Watch : StopReason::Breakpoint;
  s.breakpoints = foundIds;
  s.message = stopText(foundIds, describer(), foundNotes, foundHappened);
  if (standAtCollision(foundIds)) s.message += ": " + collisionText();
  return stopped(std::move(s));
}

Stop DebugSession::gotoTime(vm::Micros t) {
  moment_.reset();
  timeline_->goToTime(t);
  // A collision ended the run at its contact: later moments of its move
  // never came. (Its moment copied: standWithin restores snapshots, which
  // replace the run's list of collisions.)
  std::optional<Moment> contact;
  if (const runtime::CollisionEvent* hit = endingCollision()) contact = Moment{hit->at, hit->instruction};
  if (run_->finished() && (run_->rig().clock() <= t || (contact && contact->time <= t))) {
    Stop s = finishedStop(false);
    s.message += fmt::format(" before {} s", base::formatSeconds(t));
    moment_ = contact;
    return stopped(std::move(s));
  }
  standWithin(t);
  if (!moment_) return stopped({StopReason::Time, fmt::format("at {} s", base::formatSeconds(t)), {}});
  const std::string_view what = vm::has(run_->spec().image->code[moment_->instruction].op, vm::kMovesMotors)
                                    ? "the move" : "the instruction";
  const std::string end = contact
                              ? fmt::format("a collision ends the run in it at {} s", base::formatSeconds(contact->time))
                              : fmt::format("it ends at {} s", base::formatSeconds(run_->rig().clock()));
  return stopped({StopReason::Time,
                  fmt::format("at {} s, in the middle of {} of line {} ({})", base::formatSeconds(t), what,
                              run_->spec().image->lines[moment_->instruction], end),
                  {}});
}

std::optional<std::string> DebugSession::setInput(int input, bool on) {
  if (run_->finished()) return std::string("the run is over: go back first (reverse-step, goto-time)");
  if (!vm::isIoLine(input)) return fmt::format("there is no input {}: inputs are 1..{}", input, vm::kIoCount);
  if (auto wired = wiredInputRefusal(*run_, input, {})) return wired;
  if (!timeline_->setInput(input, on)) return std::string("too many input changes are waiting");
  // A change applies between instructions: inside one under way, from its end.
  moment_.reset();
  for (const StopObserver& o : observers_) o(*this, stop_);  // the same moment, another input
  return std::nullopt;
}

std::optional<std::string> DebugSession::setVariable(std::string_view name, std::int64_t value) {
  if (run_->finished()) return std::string("the run is over: go back first (reverse-step, goto-time)");
  const std::vector<std::string>& names = run_->spec().image->variables;
  const auto slot = std::find_if(names.begin(), names.end(), [&](const std::string& n) { return base::sameName(n, name); });
  if (slot == names.end())
    return fmt::format("'{}' is not a variable of the program", base::safeText(name.substr(0, 60)));
  if (value < INT32_MIN || value > INT32_MAX)
    return fmt::format("{} does not fit a variable: values are {}..{}", value, INT32_MIN, INT32_MAX);
  if (!timeline_->setVariable(static_cast<std::uint32_t>(slot - names.begin()), static_cast<std::int32_t>(value)))
    return std::string("the variable could not be set");
  moment_.reset();  // as setInput: a change applies between instructions
  for (const StopObserver& o : observers_) o(*this, stop_);
  return std::nullopt;
}

}  // namespace rs::debug
