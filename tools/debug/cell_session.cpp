#include "tools/debug/cell_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "base/seconds.h"
#include "base/text.h"

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

diag::Result<int> CellSession::breakAtLine(std::size_t robot, std::uint32_t line) {
  if (robot >= size()) return diag::refusal("no such robot");
  const std::uint32_t at = lineWithCode(robot, line);
  const vm::Image& image = *run_->robot(robot).spec().image;
  if (at == 0)
    return diag::refusal(fmt::format("no instruction on line {} of {} or after it", line, fileName(robot)));
  CellBreakpoint b;
  b.id = nextId_++;
  b.robot = robot;
  b.line = at;
  for (std::uint32_t i = 0; i < image.code.size(); ++i)
    if (image.lines[i] == at && (i == 0 || image.lines[i - 1] != at)) b.instructions.push_back(i);
  breakpoints_.push_back(std::move(b));
  return breakpoints_.back().id;
}

bool CellSession::remove(int id) {
  const auto b = std::find_if(breakpoints_.begin(), breakpoints_.end(), [id](const CellBreakpoint& x) { return x.id == id; });
  if (b == breakpoints_.end()) return false;
  breakpoints_.erase(b);
  return true;
}

std::vector<int> CellSession::hits(std::size_t robot) const {
  std::vector<int> ids;
  const std::uint32_t pc = run_->robot(robot).interpreter().pc();
  for (const CellBreakpoint& b : breakpoints_)
    if (b.robot == robot && std::find(b.instructions.begin(), b.instructions.end(), pc) != b.instructions.end())
      ids.push_back(b.id);
  return ids;
}

std::string CellSession::describe(const CellBreakpoint& b) const {
  return fmt::format("{} line {}", fileName(b.robot), b.line);
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
  std::vector<int> ids;
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
    ids = hits(p);
    for (CellBreakpoint& b : breakpoints_)
      if (std::find(ids.begin(), ids.end(), b.id) != ids.end()) ++b.hitCount;
    if (!ids.empty() || (done && done(p))) {
      reached = true, who = p;
      return true;
    }
    return false;
  };
  run_->runUntil(until);
  if (run_->finished()) return stopped(endStop());
  if (!ids.empty()) {
    CellStop s{StopReason::Breakpoint, {}, who, ids};
    for (int id : ids)
      for (const CellBreakpoint& b : breakpoints_)
        if (b.id == id) s.message += fmt::format("{}breakpoint {} ({})", s.message.empty() ? "" : ", ", id, describe(b));
    return stopped(std::move(s));
  }
  if (interrupted) return stopped({StopReason::Pause, "interrupted", who, {}});
  if (reached) return stopped({StopReason::Step, "step done", who, {}});
  at_ = limits.time;
  return stopped({StopReason::Time, fmt::format("at {} s", base::formatSeconds(limits.time)), current_, {}});
}

diag::Result<CellStop> CellSession::step(std::uint64_t n) {
  const std::size_t c = current_;
  if (!run_->finished() && run_->end(c) != runtime::RobotEnd::Running)
    return diag::refusal(fmt::format("robot {} has ended: choose another with thread LABEL, or continue",
                                     base::safeText(label(c))));
  const std::uint64_t now = run_->robot(c).interpreter().steps();
  const std::uint64_t target = now + std::min(n, UINT64_MAX - now);
  return forward({}, [this, c, target](std::size_t p) { return p == c && run_->robot(c).interpreter().steps() >= target; });
}

diag::Result<CellStop> CellSession::next() {
  const std::size_t c = current_;
  if (!run_->finished() && run_->end(c) != runtime::RobotEnd::Running)
    return diag::refusal(fmt::format("robot {} has ended: choose another with thread LABEL, or continue",
                                     base::safeText(label(c))));
  const std::size_t depth = run_->robot(c).interpreter().callDepth();
  return forward({}, [this, c, depth](std::size_t p) { return p == c && run_->robot(c).interpreter().callDepth() <= depth; });
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

CellStop CellSession::reverseStep(std::uint64_t n) {
  const std::size_t c = current_;
  if (run_->steps() == 0 && !at_) return stopped({StopReason::Start, "already at the start of the run", c, {}});
  const std::uint64_t k = run_->robot(c).interpreter().steps();
  // Inside an instruction under way, the way back begins with it.
  const std::uint64_t back = underWay(c) ? n - 1 : n;
  const std::uint64_t target = k - std::min(back, k);
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

CellStop CellSession::reverseContinue() {
  if (run_->steps() == 0 && !at_) return stopped({StopReason::Start, "already at the start of the run", current_, {}});
  // The present, to run the cell to again: a count of steps, or a time between two instants.
  const std::uint64_t present = run_->steps();
  const std::optional<vm::Micros> presentTime = at_;
  const bool pastLast = at_.has_value() || run_->finished();  // the present is after its last step
  struct Match {
    std::uint64_t steps = 0;
    std::size_t robot = 0;
    std::vector<int> ids;
  };
  std::optional<Match> last;
  restart();
  runtime::CellUntil until;
  if (presentTime) until.time = *presentTime;
  else until.steps = present;
  until.afterStep = [&](const runtime::CellRun& cell, std::size_t p) {
    const std::uint64_t g = cell.steps();
    if (g < present || (pastLast && g == present))
      if (std::vector<int> ids = hits(p); !ids.empty()) last = Match{g, p, std::move(ids)};
    return false;
  };
  run_->runUntil(until);
  restart();
  if (!last) return stopped({StopReason::Start, "at the start of the run: no breakpoint stops before", current_, {}});
  runtime::CellUntil to;
  to.steps = last->steps;
  run_->runUntil(to);
  CellStop s{StopReason::Breakpoint, {}, last->robot, last->ids};
  for (int id : last->ids)
    for (const CellBreakpoint& b : breakpoints_)
      if (b.id == id) s.message += fmt::format("{}breakpoint {} ({})", s.message.empty() ? "" : ", ", id, describe(b));
  return stopped(std::move(s));
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

}  // namespace rs::debug
