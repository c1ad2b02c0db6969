#include "runtime/cell/world.h"

namespace rs::runtime {

World::World(const workcell::Workcell& cell) : cell_(cell), grasping_(cell) {
  state_.rests.assign(cell.objects.size(), std::nullopt);
  if (const workcell::PlacedRobot* driven = cell.drivenRobot(); driven && driven->robot.chain) tool_.emplace(*driven);
}

void World::moved(std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
                  vm::Micros end) {
  const bool closing = grasping_.closes(before, after);
  const bool heldBefore = grasping_.held().has_value();
  const std::optional<workcell::GraspChange> change = grasping_.step(before, after);
  if (closing) ++state_.closes;
  if (closing && !heldBefore && !change && !cell_.objects.empty()) {
    EmptyClose& e = state_.lastEmptyClose;
    e.at = end;
    e.tcp = grasping_.toolFrame(after).translation();
    e.fixture = grasping_.objectAt(e.tcp);  // no part holds it: a fixture, if anything
    if (e.fixture) ++state_.fixtureCloses;
    const auto nearest = grasping_.nearestObject(e.tcp);
    e.nearest = nearest ? std::optional<std::size_t>(nearest->first) : std::nullopt;
    e.distance = nearest ? nearest->second : 0.0;
    e.centre = nearest ? grasping_.boxCentre(nearest->first) : Eigen::Vector3d::Zero();
    ++state_.emptyCloses;
    step_.closedEmpty = true;
  }
  if (!change) return;
  ++revision_;
  if (change->held) ++state_.takes;
  const std::size_t o = change->object;
  const workcell::Settled& s = change->settled;
  state_.last = change->held ? GraspEvent{end, o, true, grasping_.heldOffset()}
                             : GraspEvent{start, o, false, grasping_.restingPose(o), s.on, s.support, s.drop};
  if (change->held) state_.heldSince = end;
  state_.rests[o] = change->held ? std::nullopt : std::optional<GraspEvent>(state_.last);
  if (!change->held && s.drop > kLongDrop) ++state_.longDrops;
  ++state_.events;
  step_.grasped = true;
}

void World::reset(vm::Micros at) {
  const std::optional<std::size_t> held = grasping_.held();
  grasping_.reset();
  ++revision_;
  state_.rests.assign(cell_.objects.size(), std::nullopt);
  if (!held) return;
  state_.last = {at, *held, false, grasping_.restingPose(*held)};
  ++state_.events;
  step_.grasped = true;
}

Eigen::Isometry3d World::objectPose(std::size_t o, std::span<const std::int32_t> encoders, vm::Micros at) const {
  if (grasping_.held() == o && at < state_.heldSince) return grasping_.restingPose(o);
  return grasping_.objectPose(o, encoders);
}

std::optional<std::array<double, 3>> World::tcp(std::span<const std::int32_t> encoders) const {
  if (!tool_) return std::nullopt;
  return tool_->tcp(encoders);
}

workcell::CollisionQuery World::collisionQuery(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                              std::vector<Eigen::Isometry3d>& poses) const {
  workcell::CollisionQuery q;
  for (std::size_t o = 0; o < poses.size(); ++o) poses[o] = grasping_.restingPose(o);
  q.held = grasping_.held();
  q.heldOffset = grasping_.heldOffset();
  q.objectPoses = poses;
  if (!grasping_.hasGripper()) return q;
  if (q.held && grasping_.opens(before, after)) {
    // Let go as the move starts and settled at once: the fingers open round it.
    poses[*q.held] = grasping_.settleHeld(before).pose;
    q.exempt = q.held;
    q.held.reset();
  } else if (!q.held && grasping_.closes(before, after)) {
    // The fingers close round the part they take at the end.
    q.exempt = grasping_.partAt(grasping_.toolFrame(after).translation());
  }
  return q;
}

World::State World::state() const {
  State s = state_;
  s.grasp = grasping_.state();
  return s;
}

void World::restore(const State& s) {
  state_ = s;
  step_ = {};
  grasping_.restore(s.grasp);
  ++revision_;
}

}  // namespace rs::runtime
