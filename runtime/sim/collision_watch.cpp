#include "runtime/sim/collision_watch.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <fmt/format.h>

#include "base/number_text.h"
#include "runtime/cell/world.h"

namespace rs::runtime {

std::string_view collisionModeName(CollisionMode mode) {
  switch (mode) {
    case CollisionMode::Error: return "error";
    case CollisionMode::Warn: return "warn";
    case CollisionMode::Off: return "off";
  }
  return "";
}

std::optional<CollisionMode> collisionModeByName(std::string_view name) {
  for (CollisionMode m : {CollisionMode::Error, CollisionMode::Warn, CollisionMode::Off})
    if (name == collisionModeName(m)) return m;
  return std::nullopt;
}

CollisionWatch::CollisionWatch(const workcell::Workcell& cell, std::size_t robot)
    : hand_(robot), model_(cell, robot), data_(model_), bounds_(model_), clearance_(model_.robotBodies().size() + 1),
      poses_(cell.objects.size()), worldObjects_(cell.objects.size()) {
  // Objects of the same shape (a feeder's slots, two blocks) get the same
  // number: the same pieces, point for point.
  std::map<std::vector<std::uint64_t>, std::uint64_t> shapes;
  std::vector<std::uint64_t> points;
  for (const workcell::CollisionBody& body : model_.objectBodies()) {
    points.clear();
    for (const workcell::CollisionPiece& piece : body.pieces) {
      points.push_back(piece.points.size());
      for (const Eigen::Vector3d& p : piece.points)
        for (int k = 0; k < 3; ++k) points.push_back(std::bit_cast<std::uint64_t>(p[k]));
    }
    shapeOf_.push_back(shapes.try_emplace(points, shapes.size()).first->second);
  }
}

void CollisionWatch::alsoAvoid(std::size_t worldObjects, MovingParts& others, std::string label) {
  label_ = std::move(label);
  worldObjects_ = std::min(worldObjects, poses_.size());
  others_ = &others;
  memo_ = SweepMemo();
}

std::string CollisionWatch::describe(const workcell::Contact& contact) const {
  const bool ofRobot = contact.a.kind != workcell::BodyKind::Object && contact.a.kind != workcell::BodyKind::Floor;
  return fmt::format("{}{} hits {}", model_.describe(contact.a),
                     ofRobot && !label_.empty() ? fmt::format(" of robot '{}'", label_) : std::string(),
                     model_.describe(contact.b));
}

std::string CollisionWatch::describe(const CollisionEvent& event) const {
  return fmt::format("{}, {} deep", describe(event.contact), base::formatNumber(event.depth, 2));
}

std::string CollisionWatch::hint(const CollisionEvent& event) const {
  if (!event.endsIn) return {};
  const workcell::Overlap& o = *event.endsIn;
  const std::string d = base::formatNumber(o.depth, 2);
  // y is up in every cell: a part that leaves the other upwards ends too low.
  constexpr double kNearlyVertical = 0.866;  // within 30 degrees
  const std::string way = o.away.y() > kNearlyVertical    ? fmt::format("end it {} higher", d)
                          : o.away.y() < -kNearlyVertical ? fmt::format("end it {} lower", d)
                                                          : fmt::format("end it {} short of there", d);
  return fmt::format("the move ends with {} {} into {}: {}", model_.describe(event.contact.a), d,
                     model_.describe(event.contact.b), way);
}

namespace {

// Two motor vectors (of one length) into a memo key at `w`: each motor's
// pair of values in one word.
void writePairs(std::uint64_t*& w, std::span<const std::int32_t> from, std::span<const std::int32_t> to) {
  for (std::size_t m = 0; m < from.size(); ++m)
    *w++ = static_cast<std::uint64_t>(static_cast<std::uint32_t>(from[m])) << 32 | static_cast<std::uint32_t>(to[m]);
}

// The same, appended.
void appendPairs(std::vector<std::uint64_t>& key, std::span<const std::int32_t> from,
                 std::span<const std::int32_t> to) {
  const std::size_t n = std::min(from.size(), to.size()), at = key.size();
  key.resize(at + n);
  std::uint64_t* w = key.data() + at;
  writePairs(w, from.first(n), to.first(n));
}

}  // namespace

// Everything a move's verdict depends on, exactly: where the objects rest
// (a number per set of places), what is carried and how, the motors at
// both ends, and for a knot of a straight line the line's ends (the
// gripper's exemptions come from them).
void CollisionWatch::keyOf(const World& world, std::span<const std::int32_t> before,
                           std::span<const std::int32_t> after, std::span<const std::int32_t> lineFrom,
                           std::span<const std::int32_t> lineTo) {
  if (others_) {
    // The other robots' parts move without the world's revision: the key
    // holds their poses as they are now posed.
    for (std::size_t o = 0; o < worldObjects_; ++o) poses_[o] = world.restingPose(o);
    othersPose();
    placesId_ = memo_.placesId(poses_);
    worldRevision_.reset();
  } else if (!worldRevision_) {
    resting_.resize(worldObjects_);
    for (std::size_t o = 0; o < resting_.size(); ++o) resting_[o] = world.restingPose(o);
    placesId_ = memo_.placesId(resting_);
    worldRevision_ = world.revision();
  } else if (*worldRevision_ != world.revision()) {
    // What changed since the last places: a change seen before gives the
    // number at once (SweepMemo::changed); the parts a belt moves change
    // the same way in every cycle of a loop.
    change_.clear();
    change_.push_back(placesId_);
    // The objects the world set a rest for since (a part or two a belt
    // moved, among a feeder's many slots), or else every one.
    const bool logged = world.restChangedSince(*worldRevision_, restChanged_);
    const std::size_t n = logged ? restChanged_.size() : resting_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t o = logged ? restChanged_[i] : i;
      if (o >= resting_.size()) break;
      if (!world.restMayDifferSince(o, *worldRevision_)) continue;  // as it was: no look at its pose
      const Eigen::Isometry3d& now = world.restingPose(o);
      if (std::memcmp(now.matrix().data(), resting_[o].matrix().data(), sizeof(double) * 16) == 0) continue;
      resting_[o] = now;
      const std::size_t at = change_.size();
      change_.resize(at + 17);
      change_[at] = o;
      std::memcpy(&change_[at + 1], now.matrix().data(), sizeof(double) * 16);  // its 16 words, as bits
    }
    if (change_.size() > 1) {
      if (const std::optional<std::uint64_t> known = memo_.changed(change_)) {
        placesId_ = *known;
      } else {
        placesId_ = memo_.placesId(resting_);
        memo_.rememberChange(change_, placesId_);
      }
    }
    worldRevision_ = world.revision();
  }
  // Written in place: every move asks.
  const std::optional<std::size_t>& held = world.held(hand_);
  const std::size_t pairs = std::min(before.size(), after.size()),
                    linePairs = lineFrom.empty() || lineTo.empty() ? 0 : std::min(lineFrom.size(), lineTo.size());
  key_.resize(2 + (held ? 12 : 0) + pairs + linePairs);
  std::uint64_t* w = key_.data();
  *w++ = placesId_;
  *w++ = held ? *held + 1 : 0;
  if (held) {
    world.writeHeldOffset(hand_, w);
    w += 12;
  }
  writePairs(w, before.first(pairs), after.first(pairs));
  if (linePairs) writePairs(w, lineFrom.first(linePairs), lineTo.first(linePairs));
}

const CollisionEvent* CollisionWatch::sweep(const SimMachine& machine, const World& world,
                                            std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                            vm::Micros start, vm::Micros end, std::span<const std::int32_t> lineFrom,
                                            std::span<const std::int32_t> lineTo) {
  if (!model_.movable()) return nullptr;
  const bool knot = !lineFrom.empty() && !lineTo.empty();
  // The line this knot belongs to has collided already: one move, one report.
  if (knot && events_.size() > lineFirstEvent_ && events_.back().instruction == instruction_) return nullptr;
  ++moves_;
  // The other robots stand where they are at the move's start, or move
  // with each check (advance). The sweep runs at the move's end, when
  // each other robot's motion since it began its latest move is known
  // (SimMachine::positionAt; before then it stood where that move began):
  // of two moves at once, the check of the one that ends first sees both.
  othersMove_ = false;
  if (others_) othersAt_ = start, othersMove_ = others_->travel(start, end) > 0;
  return sweepPosed(machine, world, before, after, start, end, lineFrom, lineTo);
}

void CollisionWatch::othersPose() {
  others_->pose(othersAt_, std::span(poses_).subspan(worldObjects_));
}

// The other robots, and the parts they carry, where they are at time t;
// how far they can go from there by the move's end.
void CollisionWatch::othersAt(const World& world, vm::Micros t, vm::Micros end) {
  othersAt_ = checkAt_ = t;
  othersPose();
  for (const auto& [o, hand] : carried_)
    if (const std::span<const std::int32_t> motors = others_->motorsAt(hand, t); !motors.empty())
      poses_[o] = world.objectPose(o, motors, t, hand);
  bounds_.othersMove(others_->travel(t, end));
}

const CollisionEvent* CollisionWatch::sweepPosed(const SimMachine& machine, const World& world,
                                                 std::span<const std::int32_t> before,
                                                 std::span<const std::int32_t> after, vm::Micros start, vm::Micros end,
                                                 std::span<const std::int32_t> lineFrom,
                                                 std::span<const std::int32_t> lineTo) {
  const bool knot = !lineFrom.empty() && !lineTo.empty();
  keyOf(world, before, after, lineFrom, lineTo);
  // A part another robot carries moves without the world's revision: no
  // memory answers while one does.
  bool othersCarry = false;
  for (std::size_t h = 0; h < world.handCount(); ++h) othersCarry |= h != hand_ && world.held(h).has_value();
  // Nor while one of them moves: the verdict hangs on how.
  const bool remember = !othersCarry && !othersMove_;
  const SweepVerdict* verdict = remember ? memo_.find(key_) : nullptr;
  SweepVerdict fresh;
  if (verdict) {
    ++remembered_;
  } else {
    workcell::CollisionQuery query = world.collisionQuery(knot ? lineFrom : before, knot ? lineTo : after,
                                                          std::span(poses_).first(worldObjects_), hand_);
    query.objectPoses = poses_;  // the other robots' parts too
    // The same move among the same objects within its reach, the others
    // anywhere: the same verdict (reachKeyOf).
    const bool byReach = remember && !others_;
    if (byReach) {
      reachKeyOf(machine, query, before, after, start, end);
      if (const SweepVerdict* near = memo_.find(reachKey_)) {
        ++remembered_;
        fresh = *near;
        memo_.remember(key_, fresh);
        return noteVerdict(start, fresh);
      }
    }
    carried_.clear();
    if (othersMove_)
      for (std::size_t o = 0; o < worldObjects_; ++o)
        if (const std::optional<std::size_t> by = world.holder(o); by && *by != hand_ && !world.shared(o))
          carried_.emplace_back(o, *by);
    fresh = advance(machine, world, query, before, after, start, end);
    if (fresh.collides) {
      fresh.depth = data_.overlap(fresh.contact, query).depth;
      // Where the move ends: the same two parts, still in each other by a little?
      const std::optional<workcell::Overlap> o = data_.overlapAt(knot ? lineTo : after, query, fresh.contact);
      if (o && o->depth <= kEndsInBy) fresh.endsIn = o;
    }
    if (remember) memo_.remember(key_, fresh);
    // A collision names the object it hits: by number, under key_ alone.
    if (byReach && !fresh.collides) memo_.remember(reachKey_, fresh);
    verdict = &fresh;
  }
  return noteVerdict(start, *verdict);
}

const CollisionEvent* CollisionWatch::noteVerdict(vm::Micros start, const SweepVerdict& verdict) {
  if (!verdict.collides) return nullptr;
  events_.push_back(
      {start + verdict.after, verdict.contact, verdict.encoders, instruction_, verdict.depth, verdict.endsIn});
  return &events_.back();
}

// How far the carried object's points lie from the tool centre point.
std::optional<double> CollisionWatch::carriedReach(const workcell::CollisionQuery& query) const {
  if (!query.held) return std::nullopt;
  double reach = 0;
  for (const workcell::CollisionPiece& piece : model_.objectBodies()[*query.held].pieces)
    for (const Eigen::Vector3d& p : piece.points) reach = std::max(reach, (query.heldOffset * p).norm());
  return reach;
}

// A move cut into stretches over which no part goes much farther than a
// check looks (MotionBounds::kLookAhead): each part's box at a stretch's
// start, and how near an object must come to it to count in a check of
// the stretch (CollisionData::reachBoxes' reasoning: twice its travel
// over the stretch plus how far it looks).
CollisionWatch::MoveReach CollisionWatch::moveReach(const SimMachine& machine, const workcell::CollisionQuery& query,
                                                    std::span<const std::int32_t> before,
                                                    std::span<const std::int32_t> after, vm::Micros start,
                                                    vm::Micros end) {
  bounds_.startMove(carriedReach(query));
  MoveReach r;
  r.parts = clearance_.size();
  double farthest = 0;
  for (std::size_t p = 0; p < r.parts; ++p) farthest = std::max(farthest, bounds_.mostTravel(p, before, after));
  const auto stretches = static_cast<vm::Micros>(
      std::clamp(std::ceil(farthest / MotionBounds::kLookAhead), 1.0, static_cast<double>(kStretches)));
  stretchFrom_.assign(before.begin(), before.end());
  for (vm::Micros i = 1; i <= stretches; ++i) {
    const bool last = i == stretches || end <= start;
    if (last) {
      stretchTo_.assign(after.begin(), after.end());
    } else {
      const vm::Micros t = start + (end - start) * i / stretches;
      stretchTo_.resize(before.size());
      for (std::size_t m = 0; m < stretchTo_.size(); ++m) stretchTo_[m] = machine.positionAt(m, t);
    }
    data_.reachBoxes(stretchFrom_, query, boxes_);
    Eigen::AlignedBox3d all;
    double most = 0;
    for (std::size_t p = 0; p < r.parts; ++p) {
      const double reach = 2 * bounds_.mostTravel(p, stretchFrom_, stretchTo_) +
                           std::min(MotionBounds::kLookAhead, bounds_.mostTravel(p, stretchFrom_, after));
      const Eigen::AlignedBox3d box = p < boxes_.size() ? boxes_[p] : Eigen::AlignedBox3d();
      r.boxes.push_back(box), r.reaches.push_back(reach);
      if (!box.isEmpty()) all.extend(box), most = std::max(most, reach);
    }
    r.stretchAll.push_back(all), r.stretchReach.push_back(most);
    if (!all.isEmpty()) r.all.extend(all), r.allReach = std::max(r.allReach, most);
    if (last) break;
    stretchFrom_.swap(stretchTo_);
  }
  return r;
}

// A move's key by what it can reach (a second chance for a move whose
// world is new: the first cycles of a production loop, before the parts
// upstream on a belt stand where they will stand in every later cycle):
// the objects some check of the move could count, by shape and place, and
// the motors at both ends. The move is cut into stretches over which no
// part goes much farther than a check looks (MotionBounds::kLookAhead);
// an object is left out when it lies out of every stretch's reach
// (moveReach, CollisionData::reachBoxes): no check looks at it, wherever it
// stands. The objects go by shape, not number, in an order of their own
// (the clearance keeps its gaps in a total order, so the checks are the
// same whatever the numbers): the same block fed into another slot is the
// same move. Only a clear verdict goes under this key (a collision names
// its object). Starts with a word no places id reaches.
void CollisionWatch::reachKeyOf(const SimMachine& machine, const workcell::CollisionQuery& query,
                                std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                vm::Micros start, vm::Micros end) {
  // The move's stretches depend on the move and what it carries, not on
  // the world: worked out once for each.
  moveWords_.clear();
  appendPairs(moveWords_, before, after);
  moveWords_.push_back(query.held ? shapeNumber(*query.held) + 1 : 0);
  if (query.held) {
    const Eigen::Matrix<double, 3, 4> offset = query.heldOffset.affine();
    for (int i = 0; i < 12; ++i) moveWords_.push_back(std::bit_cast<std::uint64_t>(offset.data()[i]));
  }
  auto found = reaches_.find(moveWords_);
  if (found == reaches_.end()) {
    if (reaches_.size() >= kMoveReaches) reaches_.clear();  // all at once, as the memo forgets
    found = reaches_.emplace(moveWords_, moveReach(machine, query, before, after, start, end)).first;
  }
  const MoveReach& r = found->second;
  // What the query does not check (a feeder's empty slots) stays out of reach.
  outOfReach_.assign(query.objectPoses.size(), 1);
  query.anyObject(query.objectPoses.size(), [&](std::size_t o) {
    const Eigen::AlignedBox3d& hull = data_.objectHull(o, query.objectPoses[o]);
    if (workcell::CollisionData::outOfReach(r.all, r.allReach, hull)) return false;
    for (std::size_t s = 0; s < r.stretchAll.size() && outOfReach_[o]; ++s) {
      if (workcell::CollisionData::outOfReach(r.stretchAll[s], r.stretchReach[s], hull)) continue;
      for (std::size_t p = s * r.parts; p < (s + 1) * r.parts && outOfReach_[o]; ++p)
        outOfReach_[o] = workcell::CollisionData::outOfReach(r.boxes[p], r.reaches[p], hull);
    }
    return false;
  });
  constexpr std::size_t kPoseWords = 12;  // the affine part (the last row is fixed)
  const auto words = [](const Eigen::Isometry3d& pose, std::uint64_t* out) {
    for (std::size_t i = 0; i < kPoseWords; ++i) out[i] = std::bit_cast<std::uint64_t>(pose.matrix().data()[i]);
  };
  // Per object: its shape, whether the fingers may overlap it, its place.
  constexpr std::size_t kEntry = 2 + kPoseWords;
  entries_.clear();
  for (std::size_t o = 0; o < query.objectPoses.size(); ++o) {
    if ((o < outOfReach_.size() && outOfReach_[o]) || query.held == o) continue;
    const std::size_t at = entries_.size();
    entries_.resize(at + kEntry);
    entries_[at] = shapeNumber(o);
    entries_[at + 1] = query.exempt == o;
    words(query.objectPoses[o], &entries_[at + 2]);
  }
  order_.clear();
  for (std::size_t at = 0; at < entries_.size(); at += kEntry) order_.push_back(at);
  std::sort(order_.begin(), order_.end(), [this](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(entries_.begin() + static_cast<std::ptrdiff_t>(a),
                                        entries_.begin() + static_cast<std::ptrdiff_t>(a + kEntry),
                                        entries_.begin() + static_cast<std::ptrdiff_t>(b),
                                        entries_.begin() + static_cast<std::ptrdiff_t>(b + kEntry));
  });
  reachKey_.clear();
  reachKey_.push_back(~std::uint64_t{0});
  reachKey_.push_back(order_.size());
  for (const std::size_t at : order_)
    reachKey_.insert(reachKey_.end(), entries_.begin() + static_cast<std::ptrdiff_t>(at),
                     entries_.begin() + static_cast<std::ptrdiff_t>(at + kEntry));
  reachKey_.push_back(query.held ? shapeNumber(*query.held) + 1 : 0);
  if (query.held) {
    reachKey_.resize(reachKey_.size() + kPoseWords);
    words(query.heldOffset, &reachKey_[reachKey_.size() - kPoseWords]);
  }
  appendPairs(reachKey_, before, after);
}

// The largest share of its allowance any limit has used by time t, with
// what the other robots moved since the check when they move.
double CollisionWatch::used(const SimMachine& machine, vm::Micros t) {
  for (std::size_t m = 0; m < probe_.size(); ++m) probe_[m] = machine.positionAt(m, t);
  return bounds_.used(probe_, othersMove_ ? others_->travel(checkAt_, t) : 0.0);
}

// The motors `k`/`steps` of the way from `from` to `to`, each rounded
// toward `from` (so each moves one way, and the last of the steps is `to`).
void CollisionWatch::partWay(std::span<const std::int32_t> from, std::span<const std::int32_t> to, std::int64_t k,
                             std::int64_t steps) {
  for (std::size_t m = 0; m < probe_.size(); ++m)
    probe_[m] = static_cast<std::int32_t>(from[m] + (static_cast<std::int64_t>(to[m]) - from[m]) * k / steps);
}

SweepVerdict CollisionWatch::advance(const SimMachine& machine, const World& world, const workcell::CollisionQuery& query,
                                     std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                     vm::Micros start, vm::Micros end) {
  bounds_.startMove(carriedReach(query));
  bounds_.othersMove(0);
  at_.assign(before.begin(), before.end());
  probe_.assign(before.begin(), before.end());
  next_.assign(before.begin(), before.end());
  vm::Micros t = start;
  // The checks follow the motors, not the clock: where a motor covers more
  // than a count in one microsecond (a speed over 1,000,000 counts a
  // second) and that microsecond goes farther than the limits allow, the
  // checks step through it by counts, from the motors at t towards their
  // positions at t + 1 (`between`: the last check lies on that way), the
  // other robots where they are at t.
  bool between = false;
  while (true) {
    if (othersMove_ && !between) othersAt(world, t, end);
    ++checks_;
    bounds_.setCheck(at_, after);
    if (const std::optional<workcell::Contact> c = data_.findContactOrClearance(at_, query, bounds_, clearance_))
      return {true, (between ? t + 1 : t) - start, *c, at_};
    if ((t >= end && !between) || !bounds_.limit(clearance_)) return {};
    if (!between) {
      // The latest time within every limit (to 1/512 of the rest of the
      // move); when one microsecond already goes farther, through it by counts.
      vm::Micros next = end;
      if (used(machine, end) > 1) {
        vm::Micros lo = t, hi = end;  // used(lo) <= 1 < used(hi)
        const vm::Micros fine = (end - t) / 512;
        while (hi - lo > 1 && (hi - lo > fine || lo == t)) {
          const vm::Micros mid = lo + (hi - lo) / 2;
          (used(machine, mid) <= 1 ? lo : hi) = mid;
        }
        next = lo > t ? lo : hi;
      }
      if (next > t + 1 || used(machine, next) <= 1) {
        t = next;
        for (std::size_t m = 0; m < at_.size(); ++m) at_[m] = machine.positionAt(m, t);
        continue;
      }
      for (std::size_t m = 0; m < next_.size(); ++m) next_[m] = machine.positionAt(m, t + 1);
    }
    // Towards the motors at t + 1: as many counts as stay within every
    // limit, at least one (of the motor that has the most to go).
    std::int64_t steps = 0;
    for (std::size_t m = 0; m < at_.size(); ++m)
      steps = std::max<std::int64_t>(steps, std::abs(static_cast<std::int64_t>(next_[m]) - at_[m]));
    std::int64_t k = steps;
    if (steps > 1) {
      std::int64_t lo = 1, hi = steps + 1;  // within the limits at lo (or lo is the least step), not at hi
      partWay(at_, next_, steps, steps);
      if (bounds_.used(probe_) > 1) {
        hi = steps;
        while (hi - lo > 1) {
          const std::int64_t mid = lo + (hi - lo) / 2;
          partWay(at_, next_, mid, steps);
          (bounds_.used(probe_) <= 1 ? lo : hi) = mid;
        }
        k = lo;
      }
    }
    if (k >= steps) {
      t += 1;
      between = false;
      at_.assign(next_.begin(), next_.end());
    } else {
      partWay(at_, next_, k, steps);
      at_.assign(probe_.begin(), probe_.end());
      between = true;
    }
  }
}

}  // namespace rs::runtime
