#include "runtime/world.h"

namespace rs::runtime {

World::World(const workcell::Workcell& cell) : cell_(cell), grasping_(cell) {
  if (!cell.robots.empty() && cell.robots.front().robot.chain) tool_.emplace(cell.robots.front());
}

void World::moved(std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
                  vm::Micros end) {
  const std::optional<workcell::GraspChange> change = grasping_.step(before, after);
  if (!change) return;
  const std::size_t o = change->object;
  state_.last = change->held ? GraspEvent{end, o, true, grasping_.heldOffset()}
                             : GraspEvent{start, o, false, grasping_.restingPose(o)};
  if (change->held) state_.heldSince = end;
  ++state_.events;
}

void World::reset(vm::Micros at) {
  const std::optional<std::size_t> held = grasping_.held();
  grasping_.reset();
  if (!held) return;
  state_.last = {at, *held, false, grasping_.restingPose(*held)};
  ++state_.events;
}

Eigen::Isometry3d World::objectPose(std::size_t o, std::span<const std::int32_t> encoders, vm::Micros at) const {
  if (grasping_.held() == o && at < state_.heldSince) return grasping_.restingPose(o);
  return grasping_.objectPose(o, encoders);
}

std::optional<std::array<double, 3>> World::tcp(std::span<const std::int32_t> encoders) const {
  if (!tool_) return std::nullopt;
  return tool_->tcp(encoders);
}

World::State World::state() const {
  State s = state_;
  s.grasp = grasping_.state();
  return s;
}

void World::restore(const State& s) {
  state_ = s;
  grasping_.restore(s.grasp);
}

}  // namespace rs::runtime
