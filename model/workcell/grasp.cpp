#include "model/workcell/grasp.h"

#include <algorithm>
#include <cmath>

namespace rs::workcell {

namespace {

// Points on a face of the box count as inside (a tool centre point on a
// block's top face grips it); the slack absorbs rounding in the kinematics.
constexpr double kInsideSlack = 1e-6;

// How far a part another hand carries is moved aside while a let-go
// settles: out of every footprint (settle.h judges footprints in x and z).
constexpr double kParked = 1e12;

}  // namespace

Grasping::Grasping(const Workcell& cell) : cell_(&cell) {
  for (const PlacedObject& o : cell.objects) {
    resting_.push_back(o.F_world_design);
    boxes_.push_back(boundsOf(o.shape));
    double r = 0;
    if (!boxes_.back().isEmpty())
      for (int c = 0; c < 8; ++c)
        r = std::max(r, boxes_.back().corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)).norm());
    boxReach_.push_back(r + 2 * kInsideSlack);
    settleReach_.push_back(settleReach(o));
  }
  letGo_.assign(resting_.size(), std::nullopt);
  for (const PlacedObject& o : cell.objects) present_.push_back(o.inCell ? 1 : 0);
  listInCell();
  carried_ = resting_;
  hands_.resize(cell.robots.size());
  for (std::size_t r = 0; r < cell.robots.size(); ++r) {
    const PlacedRobot& placed = cell.robots[r];
    if (!placed.robot.hasGripper || !placed.robot.chain) continue;
    hands_[r].tool.emplace(placed);
    hands_[r].gripperMotor = static_cast<std::size_t>(placed.robot.chain->size());
  }
}

std::optional<std::size_t> Grasping::otherHolder(std::size_t o, std::size_t hand) const {
  for (std::size_t h = 0; h < hands_.size(); ++h)
    if (h != hand && hands_[h].hold.held == o) return h;
  return std::nullopt;
}

Grasping::State Grasping::state() const {
  State s{{}, resting_, letGo_, present_};
  for (const Hand& h : hands_) s.hands.push_back(h.hold);
  return s;
}

void Grasping::restore(const State& s) {
  for (std::size_t h = 0; h < hands_.size() && h < s.hands.size(); ++h) hands_[h].hold = s.hands[h];
  resting_ = s.resting, letGo_ = s.letGo;
  if (s.present.size() == present_.size()) present_ = s.present;
  listInCell();
}

void Grasping::setInCell(std::size_t o, bool in) {
  if (o >= present_.size() || (present_[o] != 0) == in) return;
  present_[o] = in ? 1 : 0;
  // In index order, by one insertion or erasure: a feeder feeds and a sink takes every cycle.
  const auto at = std::lower_bound(inCell_.begin(), inCell_.end(), o);
  if (in) inCell_.insert(at, o);
  else inCell_.erase(at);
}

void Grasping::listInCell() {
  inCell_.clear();
  for (std::size_t o = 0; o < present_.size(); ++o)
    if (present_[o]) inCell_.push_back(o);
}

std::optional<std::size_t> Grasping::smallestAt(const Eigen::Vector3d& point, bool partsOnly,
                                                std::optional<std::size_t> takingHand) const {
  std::optional<std::size_t> best;
  double bestVolume = 0;
  for (const std::size_t o : inCell_) {
    // An isometry keeps distances: a point farther from the object's
    // origin than its box's corners is in no slack of the box. Most of a
    // cell's objects (a feeder's parked slots among them) are passed over
    // here, by their height alone, before anything else is asked of them.
    const double reach = boxReach_[o];
    const auto near = [&](const Eigen::Isometry3d& at) {
      return std::abs(point.y() - at.translation().y()) <= reach &&
             (point - at.translation()).squaredNorm() <= reach * reach;
    };
    if (!near(resting_[o]) && (!partsOnly || !near(carried_[o]))) continue;
    if (boxes_[o].isEmpty() || (partsOnly && cell_->objects[o].kind != ObjectKind::Part)) continue;
    const std::optional<std::size_t> by = partsOnly ? holder(o) : std::nullopt;
    // A part another hand carries (and only that one) may be handed over.
    const bool handOver = by && takingHand && *by != *takingHand && !shared(o);
    if (by && !handOver) continue;
    const Eigen::Isometry3d& at = handOver ? carried_[o] : resting_[o];
    if (!near(at)) continue;
    const Eigen::Vector3d local = at.inverse(Eigen::Isometry) * point;
    const Eigen::AlignedBox3d slack(boxes_[o].min().array() - kInsideSlack, boxes_[o].max().array() + kInsideSlack);
    if (!slack.contains(local)) continue;
    const double volume = boxes_[o].volume();
    if (!best || volume < bestVolume) best = o, bestVolume = volume;  // strict: the first of equals
  }
  return best;
}

std::optional<std::pair<std::size_t, double>> Grasping::nearestObject(const Eigen::Vector3d& point) const {
  std::optional<std::pair<std::size_t, double>> best;
  for (const std::size_t o : inCell_) {
    if (boxes_[o].isEmpty()) continue;
    const Eigen::Vector3d local = resting_[o].inverse(Eigen::Isometry) * point;
    const double d = boxes_[o].exteriorDistance(local);
    if (!best || d < best->second) best = {o, d};
  }
  return best;
}

std::optional<GraspChange> Grasping::step(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                          bool mayTake, std::size_t hand) {
  if (!gripping(hand, before, after)) return std::nullopt;
  Hand& h = hands_[hand];
  std::optional<std::size_t>& held = h.hold.held;
  Eigen::Isometry3d& offset = h.hold.offset;
  const std::int32_t from = before[h.gripperMotor], to = after[h.gripperMotor];
  if (from == to) return std::nullopt;
  const bool closing = to > from;  // RANGE max is closed (min <= max always)
  if (!closing) {
    if (!held) return std::nullopt;
    const std::size_t o = *held;
    if (const std::optional<std::size_t> other = otherHolder(o, hand)) {
      // A hand-over: the other hand has it, where it is (it stayed put).
      held.reset();
      return GraspChange{o, false, Settled{resting_[o], Settled::On::Nothing, 0, 0.0}, other};
    }
    // Let go as the opening begins, and settle from where it is then.
    const Eigen::Isometry3d F_world_E = h.tool->frame(before);
    const Settled settled = settleFrom(o, F_world_E * offset);
    resting_[o] = settled.pose;
    // Settled by no more than the rest tolerance, a take at this very frame
    // holds it by the offset it had (it goes back up or down by that
    // little): a loop that puts a part down a hair off its support and
    // takes it again leaves the world bit for bit as it was.
    letGo_[o] = LetGo{F_world_E, std::abs(settled.drop) <= kSettleTolerance
                                     ? offset
                                     : F_world_E.inverse(Eigen::Isometry) * settled.pose};
    held.reset();
    return GraspChange{o, false, settled};
  }
  if (held || !mayTake) return std::nullopt;  // closing further on what it holds
  const Eigen::Isometry3d F_world_E = h.tool->frame(after);
  const std::optional<std::size_t> o = partAt(F_world_E.translation(), hand);
  if (!o) return std::nullopt;
  const std::optional<std::size_t> giver = otherHolder(*o, hand);
  if (giver) {
    // Taken from another hand: it stays where that hand holds it now.
    resting_[*o] = carried_[*o];
    letGo_[*o].reset();
  }
  held = o;
  const std::optional<LetGo>& letGo = letGo_[*o];
  offset = letGo && letGo->frame.matrix() == F_world_E.matrix() ? letGo->offset
                                                                  : F_world_E.inverse(Eigen::Isometry) * resting_[*o];
  return GraspChange{*o, true, {}, giver};
}

Settled Grasping::settleHeld(std::span<const std::int32_t> encoders, std::size_t hand) {
  if (hand >= hands_.size() || !hands_[hand].hold.held || !hands_[hand].tool) return {};
  Hand& h = hands_[hand];
  const std::size_t o = *h.hold.held;
  if (otherHolder(o, hand)) return Settled{resting_[o], Settled::On::Nothing, 0, 0.0};  // the other keeps it
  return settleFrom(o, h.tool->frame(encoders) * h.hold.offset);
}

Settled Grasping::settleFrom(std::size_t o, const Eigen::Isometry3d& pose, std::optional<std::size_t> skip) const {
  // Onto anything but a part a hand carries: where that one last rested is
  // no support, so it is moved out of every footprint for the search.
  // (By hand, not by object: a cell has a hand or two and many objects.)
  bool carried = false;
  for (const Hand& h : hands_) carried |= h.hold.held && *h.hold.held != o && *h.hold.held < resting_.size();
  if (!carried) return settle(*cell_, resting_, o, pose, skip, settleReach_, &supportBoxes_, &inCell_);
  std::vector<Eigen::Isometry3d> poses = resting_;
  for (std::size_t p = 0; p < poses.size(); ++p)
    if (p != o && holder(p)) poses[p].pretranslate(Eigen::Vector3d(kParked, 0, 0));
  return settle(*cell_, poses, o, pose, skip, settleReach_, &supportBoxes_, &inCell_);
}

void Grasping::reset() {
  for (Hand& h : hands_) h.hold.held.reset();
  for (std::size_t o = 0; o < resting_.size(); ++o) resting_[o] = cell_->objects[o].F_world_design;
  letGo_.assign(resting_.size(), std::nullopt);
  for (std::size_t o = 0; o < present_.size(); ++o) present_[o] = cell_->objects[o].inCell ? 1 : 0;
  listInCell();
}

Eigen::Isometry3d Grasping::toolFrame(std::span<const std::int32_t> encoders, std::size_t hand) {
  return hasGripper(hand) ? hands_[hand].tool->frame(encoders) : Eigen::Isometry3d::Identity();
}

Eigen::Isometry3d Grasping::objectPose(std::size_t o, std::span<const std::int32_t> encoders, std::size_t hand) {
  if (hasGripper(hand) && hands_[hand].hold.held == o && !shared(o)) return hands_[hand].tool->frame(encoders) * hands_[hand].hold.offset;
  return resting_[o];
}

}  // namespace rs::workcell
