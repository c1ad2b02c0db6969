#include "tools/debug/cell_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "base/seconds.h"
#include "base/text.h"
#include "vm/io_lines.h"
#include "runtime/run/empty_close.h"
#include "tools/debug/device_points.h"
#include "tools/debug/input_causes.h"

namespace rs::debug {

CellSession::CellSession(runtime::CellRunSpec spec) : spec_(std::move(spec)) {
  restart();
  stop_ = {StopReason::Entry, "at the start of the run", 0, {}};
}

CellSession::~CellSession() = default;

void CellSession::restart() {
  run_ = std::make_unique<runtime::CellRun>(spec_);
  at_.reset();
}

std::optional<std::size_t> CellSession::robotNamed(std::string_view name) const {
  for (std::size_t p = 0; p < size(); ++p)
    if (label(p) == name) return p;
  for (std::size_t p = 0; p < size(); ++p) {
    const std::string& file = run_->robot(p).spec().image->sourceName;
    if (file == name || std::filesystem::path(file).filename().string() == name) return p;
  }
  return std::nullopt;
}

std::string CellSession::fileName(std::size_t robot) const {
  return base::safeText(std::filesystem::path(run_->robot(robot).spec().image->sourceName).filename().string());
}

bool CellSession::underWay(std::size_t robot) const {
  return run_->robot(robot).interpreter().state().waiting && !run_->finished();
}

runtime::RunView CellSession::view(std::size_t robot) const {
  const runtime::Run& run = run_->robot(robot);
  runtime::RunView v = run.view();
  v.clock = clock();
  // A move under way has set the machine's motors to its end: show them where they are now.
  if (const runtime::SimMachine* sim = run.rig().sim())
    for (std::size_t m = 0; m < v.motors.size(); ++m) v.motors[m] = sim->positionAt(m, v.clock);
  if (const runtime::World* world = run.rig().world()) v.tcp = world->tcp(v.motors, run.rig().robotIndex());
  // A robot the cell stopped (another one failed, the deadlock) is over too.
  if (run_->finished() && !v.finished) v.finished = true, v.outcome = run_->outcome();
  return v;
}

// --- breakpoints ---------------------------------------------------------------

std::uint32_t CellSession::lineWithCode(std::size_t robot, std::uint32_t line) const {
  std::uint32_t best = 0;
  for (std::uint32_t l : run_->robot(robot).spec().image->lines)
    if (l >= line && (best == 0 || l < best)) best = l;
  return best;
}

int CellSession::add(Breakpoint::Kind kind, CellBreakpoint b) {
  b.id = nextId_++;
  b.kind = kind;
  breakpoints_.push_back(std::move(b));
  return breakpoints_.back().id;
}

diag::Result<int> CellSession::breakAtLine(std::size_t robot, std::uint32_t line) {
  if (robot >= size()) return diag::refusal("no such robot");
  const std::uint32_t at = lineWithCode(robot, line);
  const vm::Image& image = *run_->robot(robot).spec().image;
  if (at == 0)
    return diag::refusal(fmt::format("no instruction on line {} of {} or after it", line, fileName(robot)));
  CellBreakpoint b;
  b.robot = robot;
  b.line = at;
  for (std::uint32_t i = 0; i < image.code.size(); ++i)
    if (image.lines[i] == at && (i == 0 || image.lines[i - 1] != at)) b.instructions.push_back(i);
  return add(Breakpoint::Kind::Line, std::move(b));
}

diag::Result<int> CellSession::breakAtLabel(std::size_t robot, std::string_view label) {
  if (robot >= size()) return diag::refusal("no such robot");
  return addOf(robot, labelBreakpoint(*run_->robot(robot).spec().image, label));
}

diag::Result<int> CellSession::breakAtInstruction(std::size_t robot, std::uint32_t index) {
  if (robot >= size()) return diag::refusal("no such robot");
  return addOf(robot, instructionBreakpoint(*run_->robot(robot).spec().image, index));
}

diag::Result<int> CellSession::addOf(std::size_t robot, diag::Result<Breakpoint> made) {
  if (!made) return made.failure();
  CellBreakpoint c;
  static_cast<Breakpoint&>(c) = std::move(*made);
  c.robot = robot;
  const Breakpoint::Kind kind = c.kind;
  return add(kind, std::move(c));
}

diag::Result<int> CellSession::breakAtTime(vm::Micros t) {
  if (t < 0) return diag::refusal("a time is not negative");
  CellBreakpoint b;
  b.robot = current_;
  b.time = t;
  return add(Breakpoint::Kind::Time, std::move(b));
}

int CellSession::breakWhen(std::size_t robot, Condition condition) {
  CellBreakpoint b;
  b.robot = robot;
  b.when = std::move(condition);
  return add(Breakpoint::Kind::When, std::move(b));
}

int CellSession::breakOnDevice(DevicePoint point) {
  CellBreakpoint b;
  b.robot = current_;
  b.device = std::move(point);
  return add(Breakpoint::Kind::Device, std::move(b));
}

int CellSession::breakOnCollision() {
  CellBreakpoint b;
  b.robot = current_;
  return add(Breakpoint::Kind::Collision, std::move(b));
}

int CellSession::breakOnWarning() {
  CellBreakpoint b;
  b.robot = current_;
  return add(Breakpoint::Kind::Warning, std::move(b));
}

bool CellSession::qualify(int id, std::optional<Condition> condition, std::optional<HitCondition> hits) {
  for (CellBreakpoint& b : breakpoints_)
    if (b.id == id) {
      b.condition = std::move(condition);
      b.hits = hits;
      return true;
    }
  return false;
}

int CellSession::watch(std::size_t robot, Expression what) {
  watches_.push_back({nextId_++, robot, std::move(what)});
  return watches_.back().id;
}

bool CellSession::remove(int id) { return eraseId(breakpoints_, id) || eraseId(watches_, id); }

std::string CellSession::describe(const CellBreakpoint& b) const {
  if (b.inProgram()) return fmt::format("{} {}", fileName(b.robot), b.describe());
  // A condition reads one robot's values: say whose.
  if (b.kind == Breakpoint::Kind::When || b.condition)
    return fmt::format("{} on {}", b.describe(), base::safeText(label(b.robot)));
  return b.describe();
}

// --- where the cell stops -------------------------------------------------------

// The values after the step before, for what stops as something changes:
// the clock (time breakpoints), each `when`'s truth, each watched value.
struct CellSession::Probe {
  vm::Micros clock = 0;
  std::size_t collisions = 0;     // of every robot
  std::uint64_t emptyCloses = 0;  // in the cell's one world
  std::vector<bool> held;
  std::vector<std::int64_t> values;
};

struct CellSession::Found {
  std::vector<int> ids;
  std::vector<std::string> notes;     // the watches': what changed
  std::vector<std::string> happened;  // the devices': what they did
};

CellSession::Probe CellSession::probe() const {
  Probe p;
  p.clock = run_->clock();
  p.collisions = probeCollisions();
  if (const runtime::World* world = run_->robot(0).rig().world()) p.emptyCloses = world->emptyCloseCount();
  for (const CellBreakpoint& b : breakpoints_)
    p.held.push_back(b.kind == Breakpoint::Kind::When && b.when.holds(run_->robot(b.robot)));
  for (const CellWatch& w : watches_) p.values.push_back(valueOf(run_->robot(w.robot), w.what));
  return p;
}

std::size_t CellSession::probeCollisions() const {
  std::size_t n = 0;
  for (std::size_t r = 0; r < size(); ++r) n += run_->robot(r).rig().collisions().size();
  return n;
}

// A collision's or a close on nothing's stop says it, as the run's report does, with its time.
std::string CellSession::whatHappened(Breakpoint::Kind kind, const runtime::Run& stepped) const {
  if (kind == Breakpoint::Kind::Collision) {
    const runtime::Rig* latest = nullptr;  // the robot whose collision came last
    for (std::size_t r = 0; r < size(); ++r) {
      const runtime::Rig& rig = run_->robot(r).rig();
      if (!rig.collisions().empty() && rig.collisionWatch() &&
          (!latest || rig.collisions().back().at > latest->collisions().back().at))
        latest = &rig;
    }
    if (latest) {
      const runtime::CollisionEvent& e = latest->collisions().back();
      return fmt::format("{} at {} s", latest->collisionWatch()->describe(e.contact), base::formatSeconds(e.at));
    }
  }
  if (kind == Breakpoint::Kind::Warning && stepped.rig().world() && stepped.rig().cell()) {
    const std::string nearest = runtime::emptyCloseText(stepped.rig().world()->lastEmptyClose(), *stepped.rig().cell());
    return "a gripper closed on nothing" + (nearest.empty() ? std::string() : ": " + nearest);
  }
  return {};
}

CellSession::Found CellSession::matches(std::size_t robot, const Probe& before, bool counting) {
  Found f;
  const runtime::Run& stepped = run_->robot(robot);
  const std::uint32_t pc = stepped.interpreter().pc();
  for (std::size_t i = 0; i < breakpoints_.size(); ++i) {
    CellBreakpoint& b = breakpoints_[i];
    const runtime::Run& own = run_->robot(b.robot);
    bool at = false;
    switch (b.kind) {
      case Breakpoint::Kind::Line:
      case Breakpoint::Kind::Label:
      case Breakpoint::Kind::Instruction:
        at = b.robot == robot && std::find(b.instructions.begin(), b.instructions.end(), pc) != b.instructions.end();
        break;
      case Breakpoint::Kind::Time: at = before.clock <= b.time && run_->clock() > b.time; break;
      case Breakpoint::Kind::When: at = b.when.holds(own) && !(i < before.held.size() && before.held[i]); break;
      case Breakpoint::Kind::Device: {
        const auto events = stepped.rig().devicesOfLastStep();
        at = std::any_of(events.begin(), events.end(), [&](const runtime::DeviceEvent& e) { return b.device.matches(e); });
        break;
      }
      case Breakpoint::Kind::Collision: at = probeCollisions() > before.collisions; break;
      case Breakpoint::Kind::Warning:
        at = stepped.rig().world() && stepped.rig().world()->emptyCloseCount() > before.emptyCloses;
        break;
    }
    if (!at || (b.condition && !b.condition->holds(own))) continue;
    if (counting && ++b.hitCount && b.hits && !b.hits->stopsAt(b.hitCount)) continue;
    f.ids.push_back(b.id);
    if (std::string h = whatHappened(b.kind, stepped); !h.empty() &&
        std::find(f.happened.begin(), f.happened.end(), h) == f.happened.end())
      f.happened.push_back(std::move(h));
    if (b.kind == Breakpoint::Kind::When)
      if (std::string h = conditionCause(own, b.when);
          !h.empty() && std::find(f.happened.begin(), f.happened.end(), h) == f.happened.end())
        f.happened.push_back(std::move(h));
    if (b.kind == Breakpoint::Kind::Device)
      for (std::string& h : deviceHits(stepped, b.device))
        if (std::find(f.happened.begin(), f.happened.end(), h) == f.happened.end()) f.happened.push_back(std::move(h));
  }
  for (std::size_t i = 0; i < watches_.size(); ++i) {
    const std::int64_t now = valueOf(run_->robot(watches_[i].robot), watches_[i].what);
    if (i < before.values.size() && now != before.values[i]) {
      f.ids.push_back(watches_[i].id);
      f.notes.push_back(fmt::format("{} of {} changed from {} to {}{}", base::safeText(watches_[i].what.name),
                                    base::safeText(label(watches_[i].robot)), before.values[i], now,
                                    causeAside(run_->robot(watches_[i].robot), watches_[i].what, now)));
    }
  }
  return f;
}

CellStop CellSession::foundStop(std::size_t robot, const Found& found) const {
  const bool onlyWatches = std::all_of(found.ids.begin(), found.ids.end(), [this](int id) {
    return std::none_of(breakpoints_.begin(), breakpoints_.end(), [id](const CellBreakpoint& b) { return b.id == id; });
  });
  CellStop s{onlyWatches ? StopReason::Watch : StopReason::Breakpoint, {}, robot, found.ids};
  s.message = stopText(found.ids, [this](int id) -> std::optional<std::string> {
    for (const CellBreakpoint& b : breakpoints_)
      if (b.id == id) return describe(b);
    return std::nullopt;
  }, found.notes, found.happened);
  return s;
}

// --- stops ---------------------------------------------------------------------

CellStop CellSession::endStop() const {
  const vm::RunOutcome& o = *run_->outcome();
  CellStop s;
  s.reason = o.reason;
  s.robot = run_->failed().value_or(current_);
  if (o.ok()) s.message = "every program ended";
  else if (o.reason == StopReason::Deadlock) s.message = base::safeText(o.message);  // it says "deadlock: " itself
  else s.message = fmt::format("{}: {}", vm::debuggerName(o.reason), base::safeText(o.message));
  return s;
}

CellStop CellSession::stopped(CellStop stop) {
  current_ = stop.robot;
  stop_ = std::move(stop);
  return stop_;
}

CellStop CellSession::forward(const runtime::CellUntil& limits, std::function<bool(std::size_t)> done) {
  if (run_->finished()) {
    CellStop s = endStop();
    s.message = fmt::format("the run is over ({}); go back with reverse-step or goto-time", s.message);
    return stopped(std::move(s));
  }
  at_.reset();
  Found found;
  Probe before = probe();
  std::size_t who = current_;
  bool reached = false, interrupted = false;
  std::uint64_t sinceAsked = 0;
  runtime::CellUntil until = limits;
  until.afterStep = [&](const runtime::CellRun&, std::size_t p) {
    // Ctrl-C, or the client's pause: asked every 4096 steps, which cost microseconds.
    if (interrupted_ && ++sinceAsked % 4096 == 0 && interrupted_()) {
      interrupted = true, who = p;
      return true;
    }
    found = matches(p, before, true);
    if (!watches_.empty() || !before.held.empty()) before = probe();
    before.clock = run_->clock();
    if (!found.ids.empty() || (done && done(p))) {
      reached = true, who = p;
      return true;
    }
    return false;
  };
  run_->runUntil(until);
  if (run_->finished()) return stopped(endStop());
  if (!found.ids.empty()) return stopped(foundStop(who, found));
  if (interrupted) return stopped({StopReason::Pause, "interrupted", who, {}});
  if (reached) return stopped({StopReason::Step, "step done", who, {}});
  at_ = limits.time;
  return stopped({StopReason::Time, fmt::format("at {} s", base::formatSeconds(limits.time)), current_, {}});
}

std::optional<std::string> CellSession::cannotStep() const {
  if (run_->finished() || run_->end(current_) == runtime::RobotEnd::Running) return std::nullopt;
  return fmt::format("robot {} has ended: choose another with thread LABEL, or continue", base::safeText(label(current_)));
}

diag::Result<CellStop> CellSession::step(std::uint64_t n) {
  if (auto why = cannotStep()) return diag::refusal(*why);
  const std::size_t c = current_;
  const std::uint64_t now = run_->robot(c).interpreter().steps();
  const std::uint64_t target = now + std::min(n, UINT64_MAX - now);
  return forward({}, [this, c, target](std::size_t p) { return p == c && run_->robot(c).interpreter().steps() >= target; });
}

diag::Result<CellStop> CellSession::next() {
  if (auto why = cannotStep()) return diag::refusal(*why);
  const std::size_t c = current_;
  const std::size_t depth = run_->robot(c).interpreter().callDepth();
  return forward({}, [this, c, depth](std::size_t p) { return p == c && run_->robot(c).interpreter().callDepth() <= depth; });
}

diag::Result<CellStop> CellSession::finish() {
  if (auto why = cannotStep()) return diag::refusal(*why);
  const std::size_t c = current_;
  const std::size_t depth = run_->robot(c).interpreter().callDepth();
  if (depth == 0 || run_->finished())
    return diag::refusal(fmt::format("not in a subroutine: the call stack of {} is empty", base::safeText(label(c))));
  return forward({}, [this, c, depth](std::size_t p) { return p == c && run_->robot(c).interpreter().callDepth() < depth; });
}

CellStop CellSession::resume() { return forward({}, nullptr); }

CellStop CellSession::until(vm::Micros t) {
  if (t < clock() && !run_->finished())
    return stopped({StopReason::Time, fmt::format("the clock is already past {} s", base::formatSeconds(t)), current_, {}});
  runtime::CellUntil limits;
  limits.time = t;
  return forward(limits, nullptr);
}

// --- backwards -----------------------------------------------------------------

CellStop CellSession::backTo(std::uint64_t target) {
  const std::size_t c = current_;
  restart();
  if (target > 0) {
    runtime::CellUntil until;
    until.afterStep = [this, c, target](const runtime::CellRun&, std::size_t p) {
      return p == c && run_->robot(c).interpreter().steps() == target;
    };
    run_->runUntil(until);
  }
  if (run_->steps() == 0) return stopped({StopReason::Start, "at the start of the run", c, {}});
  return stopped({StopReason::Step, "step back done", c, {}});
}

CellStop CellSession::reverseStep(std::uint64_t n) {
  const std::size_t c = current_;
  if (run_->steps() == 0 && !at_) return stopped({StopReason::Start, "already at the start of the run", c, {}});
  const std::uint64_t k = run_->robot(c).interpreter().steps();
  // Inside an instruction under way, the way back begins with it.
  const std::uint64_t back = underWay(c) ? n - 1 : n;
  return backTo(k - std::min(back, k));
}

CellStop CellSession::reverseNext() {
  const std::size_t c = current_;
  if (run_->steps() == 0 && !at_) return stopped({StopReason::Start, "already at the start of the run", c, {}});
  const std::uint64_t k = run_->robot(c).interpreter().steps();
  const std::size_t depth = run_->robot(c).interpreter().callDepth();
  // The moments before: after the robot's step j, j < k (from inside an instruction under way, j <= k).
  const std::uint64_t last = underWay(c) ? k : (k > 0 ? k - 1 : 0);
  std::uint64_t target = 0;
  restart();
  if (last > 0) {
    runtime::CellUntil until;
    until.afterStep = [&](const runtime::CellRun&, std::size_t p) {
      if (p != c) return false;
      const runtime::Run& r = run_->robot(c);
      if (r.interpreter().steps() > last) return true;
      if (r.interpreter().callDepth() <= depth) target = r.interpreter().steps();
      return r.interpreter().steps() == last;
    };
    run_->runUntil(until);
  }
  return backTo(target);
}

CellStop CellSession::reverseContinue() {
  if (run_->steps() == 0 && !at_) return stopped({StopReason::Start, "already at the start of the run", current_, {}});
  // The present, to run the cell to again: a count of steps, or a time between two instants.
  const std::uint64_t present = run_->steps();
  const std::optional<vm::Micros> presentTime = at_;
  const bool pastLast = at_.has_value() || run_->finished();  // the present is after its last step
  struct Match {
    std::uint64_t steps = 0;
    std::size_t robot = 0;
    Found found;
  };
  std::optional<Match> last;
  restart();
  Probe before = probe();
  runtime::CellUntil until;
  if (presentTime) until.time = *presentTime;
  else until.steps = present;
  until.afterStep = [&](const runtime::CellRun& cell, std::size_t p) {
    const std::uint64_t g = cell.steps();
    if (g < present || (pastLast && g == present))
      if (Found f = matches(p, before, false); !f.ids.empty()) last = Match{g, p, std::move(f)};
    before = probe();
    return false;
  };
  run_->runUntil(until);
  restart();
  if (!last)
    return stopped({StopReason::Start, "at the start of the run: no breakpoint or watch stops before", current_, {}});
  runtime::CellUntil to;
  to.steps = last->steps;
  run_->runUntil(to);
  return stopped(foundStop(last->robot, last->found));
}

CellStop CellSession::gotoTime(vm::Micros t) {
  restart();
  runtime::CellUntil until;
  until.time = t;
  run_->runUntil(until);
  if (run_->finished()) {
    CellStop s = endStop();
    s.message += fmt::format(" before {} s", base::formatSeconds(t));
    return stopped(std::move(s));
  }
  at_ = t;
  return stopped({StopReason::Time, fmt::format("at {} s", base::formatSeconds(t)), current_, {}});
}

std::optional<std::string> CellSession::setInput(std::size_t robot, int input, bool on) {
  if (run_->finished()) return std::string("the run is over: go back first (reverse-step, goto-time)");
  if (!vm::isIoLine(input)) return fmt::format("there is no input {}: inputs are 1..{}", input, vm::kIoCount);
  if (auto wired = wiredInputRefusal(run_->cell(), run_->robot(robot).rig().robotIndex(), input, label(robot)))
    return wired;
  stimuli::InputChange change;
  change.at = clock();
  change.input = input;
  change.on = on;
  change.robot = label(robot);
  change.bySession = true;
  spec_.stimuli.changes.push_back(std::move(change));
  // The same present again (the same steps done, the moment shown), with the change ahead of it.
  const std::optional<vm::Micros> moment = at_;
  const std::uint64_t present = run_->steps();
  restart();
  runtime::CellUntil until;
  until.steps = present;
  run_->runUntil(until);
  at_ = moment;
  return std::nullopt;
}

}  // namespace rs::debug
