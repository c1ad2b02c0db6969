#include "runtime/sim/cell_machine.h"

#include <algorithm>
#include <fmt/format.h>

#include "base/seconds.h"
#include "vm/interpreter.h"

namespace rs::runtime {

template <typename Move>
vm::Status CellMachine::moveAndReact(Move&& move) {
  const auto positions = motion_.positions();
  std::copy(positions.begin(), positions.end(), before_.begin());
  start_ = motion_.now();
  vm::Status status = move();
  if (status.notYet()) pendingMove_ = true;
  if (!status) return status;
  return react();
}

vm::Status CellMachine::react() {
  if (watch_ && mode_ != CollisionMode::Off) {
    const CollisionEvent* hit =
        inLine_ ? watch_->sweep(*timeline_, world_, before_, motion_.positions(), start_, motion_.now(), lineFrom_, lineTo_)
                : watch_->sweep(*timeline_, world_, before_, motion_.positions(), start_, motion_.now());
    if (hit && mode_ == CollisionMode::Error)
      return vm::Status::fault(
          fmt::format("collision at {} s: {}", base::formatSeconds(hit->at), watch_->describe(*hit)));
  }
  world_.moved(before_, motion_.positions(), start_, motion_.now(), robot_);
  return vm::Status::ok();
}

vm::Status CellMachine::resume() {
  vm::Status status = motion_.resume();
  if (!status || !pendingMove_) return status;
  pendingMove_ = false;
  status = react();
  if (!status) inLine_ = false;
  if (!status || !inLine_) return status;
  return runKnots(lineKnot_ + 1);
}

vm::Status CellMachine::moveTo(std::span<const std::int32_t> targets) {
  return moveAndReact([&] { return motion_.moveTo(targets); });
}

vm::Status CellMachine::moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) {
  return moveAndReact([&] { return motion_.moveLockStep(targets, lead); });
}

bool CellMachine::planner() {
  if (planner_) return true;
  const auto& robots = world_.cell().robots;
  const workcell::PlacedRobot* driven = robot_ < robots.size() ? &robots[robot_] : nullptr;
  if (!driven || !driven->robot.chain) return false;
  plans_ = std::make_unique<workcell::LinePlanCache>();
  planner_ = std::make_unique<workcell::LinePlanner>(*driven, plans_.get());
  path_ = std::make_unique<workcell::LinePath>(*planner_);
  return true;
}

// Every knot in turn: the world reacts to each (a grasp, a collision), as
// it would to a program of small moves.
vm::Status CellMachine::runPath(const std::optional<workcell::LineProblem>& problem) {
  if (problem) return vm::Status::fault(problem->message);
  if (path_->size() == 0) return vm::Status::ok();
  const auto from = motion_.positions();
  const auto to = path_->knot(path_->size() - 1);
  lineFrom_.assign(from.begin(), from.end());
  lineTo_.assign(to.begin(), to.end());
  inLine_ = true;
  if (watch_) watch_->beginLine();
  motion_.beginPath();
  return runKnots(0);
}

vm::Status CellMachine::runKnots(std::size_t from) {
  vm::Status status = vm::Status::ok();
  for (std::size_t k = from; k < path_->size() && status; ++k) {
    status = moveLockStep(path_->knot(k), path_->lead(k));
    if (status.notYet()) {
      lineKnot_ = k;
      return status;  // still in the line: resume goes on from the next knot
    }
  }
  inLine_ = false;
  return status;
}

vm::Status CellMachine::moveLine(std::span<const std::int32_t> targets) {
  if (!planner()) return vm::Machine::moveLine(targets);
  if (targets.size() != planner_->motorCount())
    return vm::Status::fault(fmt::format("move has {} targets for {} motors", targets.size(), planner_->motorCount()));
  return runPath(planner_->planTo(motion_.positions(), targets, *path_));
}

vm::Status CellMachine::moveAlongTool(std::int32_t distance) {
  if (!planner()) return vm::Machine::moveAlongTool(distance);
  return runPath(planner_->planAlongTool(motion_.positions(), distance, *path_, distance > 0 ? "APPRO" : "DEPART"));
}

vm::Status CellMachine::hardHome() {
  return moveAndReact([&] { return motion_.hardHome(); });
}

vm::Status CellMachine::reset() {
  vm::Status status = motion_.reset();
  if (status) world_.reset(motion_.now(), robot_);
  return status;
}

}  // namespace rs::runtime
