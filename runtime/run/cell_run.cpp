#include "runtime/run/cell_run.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/seconds.h"

namespace rs::runtime {

namespace {

// Whether `label` (a stimulus's, a wire's: empty for the cell's first robot) names robot `robot`.
bool labelNames(const workcell::Workcell& cell, const std::string& label, std::size_t robot) {
  return label.empty() ? robot == cell.drivenRobotIndex() : cell.robotLabeled(label) == robot;
}

}  // namespace

stimuli::Stimuli stimuliOfRobot(const stimuli::Stimuli& all, const workcell::Workcell& cell, std::size_t robot) {
  stimuli::Stimuli own;
  for (stimuli::InputChange c : all.changes)
    if (labelNames(cell, c.robot, robot)) c.robot.clear(), c.robotColumn = 0, own.changes.push_back(std::move(c));
  for (stimuli::ReactiveRule r : all.rules)
    if (labelNames(cell, r.outputRobot, robot) && labelNames(cell, r.inputRobot, robot)) {
      r.outputRobot.clear(), r.inputRobot.clear(), r.outputRobotColumn = r.inputRobotColumn = 0;
      own.rules.push_back(std::move(r));
    }
  return own;
}

std::string checkCellRunSpec(const CellRunSpec& spec) {
  if (!spec.cell) return "a cell run needs a workcell";
  std::vector<bool> taken(spec.cell->robots.size(), false);
  for (const CellProgram& p : spec.programs) {
    if (p.robot >= taken.size()) return fmt::format("the cell has no robot {}", p.robot + 1);
    if (!p.image) return "a program without an image";
    if (taken[p.robot]) return fmt::format("two programs for robot {}", spec.cell->robots[p.robot].labelOf());
    taken[p.robot] = true;
  }
  for (const stimuli::ReactiveRule& r : spec.stimuli.rules) {
    const std::size_t out = r.outputRobot.empty() ? 0 : spec.cell->robotLabeled(r.outputRobot);
    const std::size_t in = r.inputRobot.empty() ? 0 : spec.cell->robotLabeled(r.inputRobot);
    if (out != in)
      return fmt::format("line {}: a rule from one robot's output to another's input is not run yet: write a WIRE "
                         "{}.OUT {} TO {}.IN {} in the cell instead",
                         r.line, r.outputRobot.empty() ? spec.cell->robots[0].labelOf() : r.outputRobot, r.output,
                         r.inputRobot.empty() ? spec.cell->robots[0].labelOf() : r.inputRobot, r.input);
  }
  return {};
}

CellRun::CellRun(CellRunSpec spec)
    : cell_(withFeederSlots(spec.cell)), shared_(cell_.get()), limits_(spec.limits) {
  std::vector<RobotIo*> ios(cell_->robots.size(), nullptr);
  for (const CellProgram& p : spec.programs) {
    RunSpec one;
    one.image = p.image;
    one.cell = cell_;
    one.stimuli = stimuliOfRobot(spec.stimuli, *cell_, p.robot);
    one.limits = spec.limits;
    one.collisions = spec.collisions;
    one.log = spec.log;
    one.lines = spec.lines;
    runs_.push_back(std::make_unique<Run>(std::move(one), shared_, p.robot, p.follower));
    ios[p.robot] = &runs_.back()->rig().io();
  }
  // Every robot is an obstacle to every other, where its machine has it.
  for (auto& r : runs_) {
    r->rig().avoidOtherRobots();
    if (RobotObstacles* o = r->rig().obstacles())
      for (auto& other : runs_) o->machine(other->rig().robotIndex(), other->rig().sim());
  }
  ends_.assign(runs_.size(), RobotEnd::Running);
  endAt_.assign(runs_.size(), 0);
  wakeAt_.assign(runs_.size(), 0);
  if (shared_.world() && !cell_->devices.empty()) {
    devices_ = std::make_unique<CellDevices>(*cell_, *shared_.world(), std::move(ios), shared_.clock());
    for (auto& r : runs_) {
      r->rig().attachDevices(*devices_);
      if (spec.log) r->rig().recordMotions();  // attached after the run was built: its log asks now
    }
  }
}

CellRun::~CellRun() = default;

const std::string& CellRun::label(std::size_t p) const {
  return cell_->robots[runs_[p]->rig().robotIndex()].labelOf();
}

vm::Status CellRun::advanceCell(vm::Micros t) {
  if (devices_) devices_->sync();
  if (vm::Status s = shared_.clock().advanceTo(t); !s) return s;
  if (devices_)
    if (std::optional<std::string> fault = devices_->takeFault()) return vm::Status::fault(*fault);
  return vm::Status::ok();
}

// The robot that failed stops the cell: the others' waits end where they are.
vm::RunOutcome CellRun::stopAll(std::size_t failed, const vm::RunOutcome& outcome) {
  failed_ = failed;
  ends_[failed] = RobotEnd::Finished;
  endAt_[failed] = clock();
  cellStops(outcome.reason, {});
  vm::RunOutcome cell = outcome;
  cell.message = fmt::format("robot {}: {}", label(failed), outcome.message);
  return cell;
}

vm::RunOutcome CellRun::cellStops(vm::StopReason reason, std::string message) {
  for (std::size_t p = 0; p < runs_.size(); ++p)
    if (ends_[p] == RobotEnd::Running) ends_[p] = RobotEnd::Stopped, endAt_[p] = clock();
  vm::RunOutcome o;
  o.reason = reason;
  o.message = std::move(message);
  return o;
}

std::string CellRun::deadlockMessage() const {
  std::string out = "deadlock: ";
  bool first = true;
  for (std::size_t p = 0; p < runs_.size(); ++p) {
    if (ends_[p] != RobotEnd::Running) continue;
    const Run& run = *runs_[p];
    const SimMachine& sim = *run.rig().sim();
    const std::size_t robot = run.rig().robotIndex();
    const int input = sim.waitingInput();
    std::string source = "nothing drives it";
    for (const workcell::Wire& w : cell_->devices.wires)
      if (w.input == input && labelNames(*cell_, w.robot, robot)) source = "wired from " + signalText(w.source);
    const vm::Image& image = *run.spec().image;
    out += fmt::format("{}{} waits at {}:{} for input {} ({})", first ? "" : "; ", label(p), image.sourceName,
                       run.view().line, input, source);
    first = false;
  }
  return out;
}

std::uint64_t CellRun::steps() const {
  std::uint64_t n = 0;
  for (const auto& r : runs_) n += r->interpreter().steps();
  return n;
}

vm::RunOutcome CellRun::over(vm::RunOutcome outcome) {
  outcome_ = outcome;
  return outcome;
}

// One loop of instants, which a pause leaves where it is (phase_, turn_):
// the next call goes on from there as if it had not paused.
vm::RunOutcome CellRun::runUntil(const CellUntil& until) {
  if (outcome_) return *outcome_;
  vm::RunOutcome paused;
  paused.reason = vm::StopReason::Paused;
  while (true) {
    if (phase_ == Phase::Evaluate) {
      // Evaluate: every robot runs until it waits or ends.
      for (; turn_ < runs_.size(); ++turn_) {
        const std::size_t p = turn_;
        if (ends_[p] != RobotEnd::Running) continue;
        RunUntil one;
        if (until.steps != UINT64_MAX) {
          const std::uint64_t done = steps();
          if (done >= until.steps) return paused;
          one.moreSteps = until.steps - done;
        }
        if (until.afterStep) one.when = [&until, this, p](const Run&) { return until.afterStep(*this, p); };
        const vm::RunOutcome o = runs_[p]->runUntil(one);
        if (o.waiting) {
          wakeAt_[p] = o.wakeAt;
          continue;
        }
        if (o.paused()) return paused;  // its turn goes on at the next call
        ends_[p] = RobotEnd::Finished;
        endAt_[p] = clock();
        lastEnded_ = p;
        endedSteps_ += o.steps;
        if (!o.ok()) return over(stopAll(p, o));
      }
      turn_ = 0;
      if (std::none_of(ends_.begin(), ends_.end(), [](RobotEnd e) { return e == RobotEnd::Running; })) {
        // The last END right after a take, a let-go or a RESET: the cell
        // acts on it at this instant, before the summary (Run::runUntil).
        if (vm::Status s = advanceCell(clock()); !s) return over(cellStops(vm::StopReason::RuntimeError, s.message));
        runs_[lastEnded_]->takeRecordsAfterEnd();
        vm::RunOutcome last;
        last.reason = vm::StopReason::End;
        last.steps = endedSteps_;
        return over(last);
      }
      // The cell acts on what the robots did at now, then its clock runs on.
      std::vector<vm::IoMask> inputsBefore;
      for (const auto& r : runs_) inputsBefore.push_back(r->rig().machine().inputs());
      if (vm::Status s = advanceCell(clock()); !s) return over(cellStops(vm::StopReason::RuntimeError, s.message));
      // A wire without AFTER may have answered a robot at this very instant:
      // it runs again now, before the clock moves on to anything else due.
      bool changed = false;
      for (std::size_t p = 0; p < runs_.size(); ++p) changed |= runs_[p]->rig().machine().inputs() != inputsBefore[p];
      if (changed) continue;
      allForever_ = true;
      for (std::size_t p = 0; p < runs_.size(); ++p) {
        if (ends_[p] != RobotEnd::Running) continue;
        if (wakeAt_[p] != vm::Status::kNever) runs_[p]->rig().wakeRobotAt(wakeAt_[p]), allForever_ = false;
      }
      if (!shared_.clock().nextTime()) return over(cellStops(vm::StopReason::Deadlock, deadlockMessage()));
      phase_ = Phase::Due;
    }
    const vm::Micros next = *shared_.clock().nextTime();
    // Only the devices may end these waits, in a cell that goes on forever:
    // past the time limit the cell stops.
    if (next > limits_.maxTime && allForever_)
      return over(cellStops(vm::StopReason::TimeLimit, fmt::format("every robot still waits past the time limit of {} s",
                                                                   base::formatSeconds(limits_.maxTime))));
    if (next > until.time) return paused;
    if (vm::Status s = advanceCell(next); !s) return over(cellStops(vm::StopReason::RuntimeError, s.message));
    phase_ = Phase::Evaluate;
  }
}

}  // namespace rs::runtime
