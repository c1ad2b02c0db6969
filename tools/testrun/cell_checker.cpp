#include "tools/testrun/cell_checker.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "launch/robot_choice.h"
#include "tools/testrun/evaluate.h"
#include "tools/testrun/run_watch.h"

namespace rs::testrun {

namespace {

// What a robot's own run answers (the rest is the cell's): a prefix names
// the robot, and without one they are the program under test's robot's.
bool robotsOwn(ExpectKind kind) {
  switch (kind) {
    case ExpectKind::Motors:
    case ExpectKind::MotorBound:
    case ExpectKind::Output:
    case ExpectKind::Input:
    case ExpectKind::Pulses:
    case ExpectKind::Order:
    case ExpectKind::Variable:
    case ExpectKind::Tcp: return true;
    default: return false;
  }
}

// The robots that run a program here, for a hint: "`feeder`, `packer`".
std::string runningLabels(const runtime::CellRun& cell) {
  std::string out;
  for (std::size_t p = 0; p < cell.size(); ++p)
    out += fmt::format("{}`{}`", out.empty() ? "" : ", ", base::safeText(cell.label(p)));
  return out;
}

// How robot `p` ended: its own outcome, or, stopped with the cell, the
// cell's reason at the instruction it was at.
RunEnd robotEnd(const runtime::CellRun& cell, std::size_t p, const vm::RunOutcome& cellOutcome) {
  const runtime::Run& run = cell.robot(p);
  RunEnd end;
  end.robot = cell.label(p);
  end.at = cell.endTime(p);
  if (cell.end(p) == runtime::RobotEnd::Stopped || !run.outcome()) {
    end.outcome.reason = cellOutcome.reason;
    end.outcome.message = cellOutcome.message;
    end.outcome.index = run.view().instruction;
    end.stopped = cell.failed().has_value();
    end.line = run.view().line;
    return end;
  }
  end.outcome = *run.outcome();
  end.line = run.spec().image->lines[end.outcome.index];
  return end;
}

}  // namespace

// Checks the expectations against the finished cell run.
class CellChecker::Impl {
  // An order between two robots' lines: the expectation, each robot and
  // the place of its event in its watch.
  struct CrossOrder {
    std::size_t expectation, first, firstAt, second, secondAt;
  };

 public:
  Impl(const runtime::CellRun& cell, const vm::RunOutcome& outcome, const std::vector<Expectation>& all,
       std::optional<std::size_t> under, const std::string& file)
      : cell_(cell), outcome_(outcome), all_(all), under_(under), file_(file), own_(cell.size()), events_(cell.size()) {
    for (std::size_t i = 0; i < all.size(); ++i) route(i);
  }

  // Watches each robot's run for its own expectations (before the run).
  void watch(runtime::CellRun& cell) {
    watches_.resize(cell.size());
    eventWatches_.resize(cell.size());
    for (std::size_t p = 0; p < cell.size(); ++p) {
      if (RunWatch::needed(own_[p])) {
        watches_[p] = std::make_unique<RunWatch>(cell.robot(p), own_[p]);
        cell.observe(p, *watches_[p]);
      }
      if (!events_[p].empty()) {
        eventWatches_[p] = std::make_unique<RunWatch>(cell.robot(p), events_[p]);
        cell.observe(p, *eventWatches_[p]);
      }
    }
  }

  // After the run: every expectation, in the order written.
  std::vector<diag::Diagnostic> check(bool impliedFinished) {
    cellEnd_.outcome = outcome_;
    cellEnd_.at = cell_.clock();
    std::vector<diag::Diagnostic> out = problems_;
    for (std::size_t p = 0; p < cell_.size(); ++p) {
      const RunEnd end = robotEnd(cell_, p, outcome_);
      if (watches_.size() > p && watches_[p]) watches_[p]->finish(end.outcome);
      if (eventWatches_.size() > p && eventWatches_[p]) eventWatches_[p]->finish(end.outcome);
      const std::vector<diag::Diagnostic> said =
          evaluate(cell_.robot(p), end, own_[p], file_, false, watches_.size() > p ? watches_[p].get() : nullptr);
      out.insert(out.end(), said.begin(), said.end());
    }
    for (const Expectation& e : cellOwn_) cellExpectation(e, out);
    for (const CrossOrder& c : crosses_) crossOrder(c, out);
    std::stable_sort(out.begin(), out.end(),
                     [](const diag::Diagnostic& a, const diag::Diagnostic& b) {
                       return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.col < b.pos.col;
                     });
    if (impliedFinished && !outcome_.ok()) out.insert(out.begin(), impliedEnd());
    return out;
  }

 private:
  // Which robot's run answers expectation i, or the cell.
  void route(std::size_t i) {
    const Expectation& e = all_[i];
    if (e.kind == ExpectKind::CompileError || e.kind == ExpectKind::Trace) return;  // not the run's alone
    std::optional<std::size_t> robot;
    if (!e.robot.empty()) {
      robot = robotOf(e, e.robot, e.robotCol);
      if (!robot) return;
    } else if (robotsOwn(e.kind)) {
      if (!under_) {
        problems_.push_back({file_, e.pos, diag::Severity::Error,
                             fmt::format("a cell of several robots runs here: say whose {} this is, as in "
                                         "'LABEL.{}'",
                                         e.kind == ExpectKind::Variable ? "variable" : "line or motor", e.text),
                             {}, fmt::format("the robots with a program: {}", runningLabels(cell_))});
        return;
      }
      robot = under_;
    }
    if (!robot) return cellOwn_.push_back(e);
    Expectation mine = e;
    mine.robot.clear();
    if (!e.secondRobot.empty()) {
      const std::optional<std::size_t> second = robotOf(e, e.secondRobot, e.secondRobotCol);
      if (!second) return;
      mine.secondRobot.clear();
      if (*second != *robot) {
        // Each robot's watch gives when its own event first happened.
        Expectation first = mine, then = mine;
        first.second = first.first;
        then.first = then.second;
        crosses_.push_back({i, *robot, events_[*robot].size(), *second, events_[*second].size()});
        events_[*robot].push_back(std::move(first));
        events_[*second].push_back(std::move(then));
        return;
      }
    }
    own_[*robot].push_back(std::move(mine));
  }

  // The program of robot `label`, or a problem at its column.
  std::optional<std::size_t> robotOf(const Expectation& e, const std::string& label, std::uint32_t col) {
    for (std::size_t p = 0; p < cell_.size(); ++p)
      if (base::sameName(cell_.label(p), label)) return p;
    unknownRobot(e, label, col);
    return std::nullopt;
  }

  void unknownRobot(const Expectation& e, const std::string& label, std::uint32_t col) {
    const runtime::CellRun& c = cell_;
    const bool inCell = c.cell().robotLabeled(label) != workcell::kNoIndex;
    diag::Diagnostic d{file_, {e.pos.line, col}, diag::Severity::Error,
                       inCell ? fmt::format("robot {} runs no program in this scenario: it has no run to check",
                                            base::safeText(label))
                              : fmt::format("workcell {} has no robot labelled `{}`", base::safeText(c.cell().name),
                                            base::safeText(label)),
                       "unknown-robot",
                       inCell ? fmt::format("the robots with a program: {}", runningLabels(c))
                              : fmt::format("the cell's robots are {}", launch::robotLabelsOf(c.cell()))};
    problems_.push_back(std::move(d));
  }

  // One of the cell's expectations: its end and time, objects, devices, collisions.
  void cellExpectation(const Expectation& e, std::vector<diag::Diagnostic>& out) {
    const std::vector<Expectation> one{e};
    const auto on = [&](std::size_t p) { return evaluate(cell_.robot(p), cellEnd_, one, file_, false, nullptr); };
    // Held by any robot's gripper, not held by any; no collision of any
    // robot; a collision with NAME of one of them.
    const bool any = (e.kind == ExpectKind::ObjectHeld && e.on) || e.kind == ExpectKind::CollidesWith;
    const bool every = (e.kind == ExpectKind::ObjectHeld && !e.on) || e.kind == ExpectKind::NoCollision;
    if (!any && !every) {
      const std::vector<diag::Diagnostic> said = on(0);  // the world, the devices and the clock are the cell's
      out.insert(out.end(), said.begin(), said.end());
      return;
    }
    std::vector<diag::Diagnostic> first;
    for (std::size_t p = 0; p < cell_.size(); ++p) {
      std::vector<diag::Diagnostic> said = on(p);
      if (said.empty() && any) return;
      // Of a collision expected: the robot whose run had one says best what happened.
      const bool better = e.kind == ExpectKind::CollidesWith && !cell_.robot(p).rig().collisions().empty() &&
                          (first.empty() || cell_.robot(0).rig().collisions().empty());
      if (!said.empty() && (first.empty() || better)) first = std::move(said);
      if (!first.empty() && every) break;
    }
    out.insert(out.end(), first.begin(), first.end());
  }

  // `left.output 1 on before right.input 1 on`: each robot's event when it first happened.
  void crossOrder(const CrossOrder& c, std::vector<diag::Diagnostic>& out) const {
    const Expectation& e = all_[c.expectation];
    const std::optional<vm::Micros> a = eventWatches_[c.first]->answer(c.firstAt).first;
    const std::optional<vm::Micros> b = eventWatches_[c.second]->answer(c.secondAt).first;
    const auto text = [&](std::size_t p, const LineEvent& ev) {
      return fmt::format("{}.{} {} {}", base::safeText(cell_.label(p)), ev.output ? "output" : "input", ev.number,
                         ev.on ? "ON" : "OFF");
    };
    const std::string first = text(c.first, e.first), second = text(c.second, e.second);
    const std::string want = fmt::format("expected {} before {}", first, second);
    if (!a)
      out.push_back({file_, e.pos, diag::Severity::Error,
                     fmt::format("{}; {} never happened (the run ended at {} s)", want, first,
                                 base::formatSeconds(cell_.clock()))});
    else if (b && *b <= *a)
      out.push_back({file_, e.pos, diag::Severity::Error,
                     fmt::format("{}; {} came {}, at {} s ({} at {} s)", want, second, *b == *a ? "at the same time" : "first",
                                 base::formatSeconds(*b), first, base::formatSeconds(*a))});
  }

  // A scenario that states no end must finish: else a failure at the line
  // of the robot that stopped the cell (or of the first still running).
  diag::Diagnostic impliedEnd() const {
    std::size_t p = 0;
    if (cell_.failed()) p = *cell_.failed();
    else
      while (p + 1 < cell_.size() && cell_.end(p) != runtime::RobotEnd::Stopped) ++p;
    const RunEnd end = robotEnd(cell_, p, outcome_);
    std::vector<diag::Diagnostic> said = evaluate(cell_.robot(p), end, {}, file_, true, nullptr);
    diag::Diagnostic d = said.empty() ? diag::Diagnostic{file_, {}, diag::Severity::Error, outcome_.message}
                                      : said.front();
    d.file = cell_.robot(p).spec().image->sourceName;
    return d;
  }

  const runtime::CellRun& cell_;
  const vm::RunOutcome& outcome_;
  const std::vector<Expectation>& all_;
  std::optional<std::size_t> under_;
  const std::string& file_;
  RunEnd cellEnd_;
  std::vector<std::vector<Expectation>> own_;  // per program: its robot's expectations, prefix taken off
  std::vector<Expectation> cellOwn_;
  std::vector<diag::Diagnostic> problems_;  // found before the run: a robot that is not there
  std::vector<std::unique_ptr<RunWatch>> watches_;
  std::vector<CrossOrder> crosses_;
  std::vector<std::vector<Expectation>> events_;  // per program: the events of crosses_ it watches
  std::vector<std::unique_ptr<RunWatch>> eventWatches_;
};

CellChecker::CellChecker(runtime::CellRun& cell, const vm::RunOutcome& outcome,
                         const std::vector<Expectation>& expectations, std::optional<std::size_t> under,
                         const std::string& file)
    : impl_(std::make_unique<Impl>(cell, outcome, expectations, under, file)) {
  impl_->watch(cell);
}

CellChecker::~CellChecker() = default;

std::vector<diag::Diagnostic> CellChecker::check(bool impliedFinished) { return impl_->check(impliedFinished); }

}  // namespace rs::testrun
