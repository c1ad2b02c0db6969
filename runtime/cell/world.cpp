#include "runtime/cell/world.h"

#include <algorithm>

namespace rs::runtime {

World::World(const workcell::Workcell& cell) : cell_(cell), grasping_(cell) {
  state_.rests.assign(cell.objects.size(), std::nullopt);
  restRevision_.assign(cell.objects.size(), 0);
  const std::size_t hands = cell.robots.size();
  state_.heldSince.assign(hands, 0);
  step_.assign(hands, {});
  handMachines_.assign(hands, nullptr);
  tools_.resize(hands);
  for (std::size_t r = 0; r < hands; ++r)
    if (cell.robots[r].robot.chain) tools_[r].emplace(cell.robots[r]);
}

void World::moved(std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
                  vm::Micros end, std::size_t hand) {
  if (hand >= step_.size()) return;
  const bool closing = grasping_.closes(before, after, hand);
  const bool heldBefore = grasping_.held(hand).has_value();
  if (closing && !heldBefore) noteCarried(hand);
  const std::optional<workcell::GraspChange> change = grasping_.step(before, after, true, hand);
  if (closing) ++state_.closes;
  if (closing && !heldBefore && !change && !cell_.objects.empty()) {
    EmptyClose& e = state_.lastEmptyClose;
    e.at = end;
    e.hand = hand;
    e.tcp = grasping_.toolFrame(after, hand).translation();
    e.fixture = grasping_.objectAt(e.tcp);  // no part holds it: a fixture, if anything
    if (e.fixture) ++state_.fixtureCloses;
    const auto nearest = grasping_.nearestObject(e.tcp);
    e.nearest = nearest ? std::optional<std::size_t>(nearest->first) : std::nullopt;
    e.distance = nearest ? nearest->second : 0.0;
    e.centre = nearest ? grasping_.boxCentre(nearest->first) : Eigen::Vector3d::Zero();
    ++state_.emptyCloses;
    step_[hand].closedEmpty = true;
  }
  if (!change) return;
  noteRest(change->object);
  if (change->held) ++state_.takes;
  const std::size_t o = change->object;
  const workcell::Settled& s = change->settled;
  state_.last = change->held ? GraspEvent{end, o, true, grasping_.heldOffset(hand)}
                             : GraspEvent{start, o, false, grasping_.restingPose(o), s.on, s.support, s.drop};
  state_.last.hand = hand;
  state_.last.other = change->other;
  if (change->held) state_.heldSince[hand] = end;
  // A part handed over is still held: it rests nowhere yet.
  state_.rests[o] = change->held || change->other ? std::nullopt : std::optional<GraspEvent>(state_.last);
  if (!change->held && s.drop > kLongDrop) ++state_.longDrops;
  ++state_.events;
  step_[hand].grasped = true;
}

void World::reset(vm::Micros at, std::size_t hand) {
  if (hand >= step_.size()) return;
  // The let-go reported is the resetting robot's own (or the first other one's).
  std::optional<std::size_t> held = grasping_.held(hand), from = hand;
  for (std::size_t h = 0; h < grasping_.handCount() && !held; ++h)
    if (grasping_.held(h)) held = grasping_.held(h), from = h;
  grasping_.reset();
  noteEveryRest();
  state_.rests.assign(cell_.objects.size(), std::nullopt);
  if (!held) return;
  state_.last = {at, *held, false, grasping_.restingPose(*held)};
  state_.last.hand = *from;
  ++state_.events;
  step_[hand].grasped = true;
}

Eigen::Isometry3d World::objectPose(std::size_t o, std::span<const std::int32_t> encoders, vm::Micros at,
                                    std::size_t hand) const {
  const std::optional<std::size_t> by = grasping_.holder(o);
  if (!by || grasping_.shared(o)) return grasping_.restingPose(o);
  if (at < heldSince(*by)) return grasping_.restingPose(o);
  if (*by == hand) return grasping_.objectPose(o, encoders, hand);
  const vm::Machine* other = handMachines_[*by];
  if (!other) return grasping_.restingPose(o);
  const auto motors = other->positions();
  otherMotors_.assign(motors.begin(), motors.end());
  return grasping_.objectPose(o, otherMotors_, *by);
}

std::optional<std::array<double, 3>> World::tcp(std::span<const std::int32_t> encoders, std::size_t hand) const {
  if (hand >= tools_.size() || !tools_[hand]) return std::nullopt;
  return tools_[hand]->tcp(encoders);
}

workcell::CollisionQuery World::collisionQuery(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                              std::span<Eigen::Isometry3d> poses, std::size_t hand) const {
  workcell::CollisionQuery q;
  // Where each rests, but a part another hand holds (its first holder not
  // this one): where that hand carries it. By hand, not by object: a cell
  // has a hand or two and many objects.
  for (std::size_t o = 0; o < poses.size(); ++o) poses[o] = grasping_.restingPose(o);
  for (std::size_t h = 0; h < grasping_.handCount(); ++h) {
    const std::optional<std::size_t>& o = grasping_.held(h);
    if (h == hand || !o || *o >= poses.size() || grasping_.holder(*o) == hand) continue;
    poses[*o] = objectPose(*o, {}, INT64_MAX, hand);
  }
  q.held = grasping_.held(hand);
  if (hand < grasping_.handCount()) q.heldOffset = grasping_.heldOffset(hand);
  q.objectPoses = poses;
  q.inCell = &grasping_.inCell(), q.cellObjects = cell_.objects.size();
  if (!grasping_.hasGripper(hand)) return q;
  if (q.held && grasping_.shared(*q.held)) {
    // Two hands hold it: it stays put, with these fingers round it.
    q.exempt = q.held;
    q.held.reset();
  } else if (q.held && grasping_.opens(before, after, hand)) {
    // Let go as the move starts and settled at once: the fingers open round it.
    poses[*q.held] = grasping_.settleHeld(before, hand).pose;
    q.exempt = q.held;
    q.held.reset();
  } else if (!q.held && grasping_.closes(before, after, hand)) {
    // The fingers close round the part they take at the end (perhaps from
    // another hand).
    noteCarried(hand);
    q.exempt = grasping_.partAt(grasping_.toolFrame(after, hand).translation(), hand);
  }
  return q;
}

void World::noteCarried(std::size_t hand) const {
  for (std::size_t h = 0; h < grasping_.handCount(); ++h) {
    const std::optional<std::size_t> o = grasping_.held(h);
    if (h != hand && o) grasping_.carriedAt(*o, objectPose(*o, {}, INT64_MAX, hand));
  }
}

void World::noteRest(std::size_t o) {
  restRevision_[o] = ++revision_;
  restLog_.emplace_back(revision_, o);
  if (restLog_.size() > kRestLog) {
    const auto half = restLog_.begin() + static_cast<std::ptrdiff_t>(kRestLog / 2);
    restLogFrom_ = half->first - 1;
    restLog_.erase(restLog_.begin(), half);
  }
}

void World::noteEveryRest() {
  restRevision_.assign(restRevision_.size(), ++revision_);
  restLog_.clear();
  restLogFrom_ = revision_;
}

bool World::restChangedSince(std::uint64_t since, std::vector<std::size_t>& out) const {
  out.clear();
  if (since < restLogFrom_) return false;
  // The entries after `since`, from the back (they are in revision order).
  for (auto it = restLog_.rbegin(); it != restLog_.rend() && it->first > since; ++it) out.push_back(it->second);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return true;
}

World::State World::state() const {
  State s = state_;
  s.grasp = grasping_.state();
  return s;
}

void World::restore(const State& s) {
  state_ = s;
  step_.assign(step_.size(), {});
  grasping_.restore(s.grasp);
  noteEveryRest();
}

}  // namespace rs::runtime
