// The clearance of one pose, for the swept check's conservative
// advancement (runtime/sim/collision_watch.h): the same pairs in the same order
// as CollisionData::scan, the same overlap decision for each (the first
// overlap is findContact's), and for each moving part the gaps it could
// close before its move ends, each a distance along a direction. A gap
// comes from the world boxes first (two boxes apart are separated along
// the vector between their nearest points, and so is everything inside
// them): a whole body's while the union of its boxes is apart from the
// other's, else each piece's; a piece's gap that the part could close is
// refined by GJK, whose separating plane gives a distance and a direction
// of its own.
#include <algorithm>
#include <limits>

#include "model/workcell/collision_model.h"
#include "model/workcell/gjk.h"

namespace rs::workcell {

namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

// One side of a pair: a body at a pose, its piece boxes and their union.
struct Side {
  const CollisionBody* body;
  const Eigen::Isometry3d* pose;
  const Eigen::AlignedBox3d* boxes;
  const Eigen::AlignedBox3d* all;
};

// The gap between two boxes: its length, and the unit vector along it
// (the boxes' nearest points differ by it); 0 when they meet.
double boxGap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, Eigen::Vector3d& along) {
  const Eigen::Vector3d gap = (b.min() - a.max()).cwiseMax(0.0) - (a.min() - b.max()).cwiseMax(0.0);
  const double length2 = gap.squaredNorm();
  if (length2 == 0) return 0.0;
  const double length = std::sqrt(length2);
  along = gap / length;
  return length;
}

// Where a pair's gaps go: the moving part's list, relative to the frame
// the other side moves with; a gap the part cannot close is left out.
struct GapSink {
  SweepMotion& motion;
  PartClearance& gaps;
  std::size_t part, from;
  double anyWay;  // how far the part can still go in any direction
  bool closable(const Eigen::Vector3d& normal, double distance) const {
    return distance < anyWay && distance <= motion.along(part, normal, from);
  }
  void add(const Eigen::Vector3d& normal, double distance) const {
    if (closable(normal, distance)) gaps.add({normal, distance, from});
  }
};

// false when the bodies overlap (some pair of pieces whose boxes meet and
// whose hulls overlap: bodiesOverlap's decision); otherwise the gaps the
// mover `a` could close go to `sink`.
bool pairGaps(const Side& a, const Side& b, const GapSink& sink) {
  Eigen::Vector3d along = Eigen::Vector3d::UnitY();
  if (const double far = boxGap(*a.all, *b.all, along); far > 0 && !sink.closable(along, far))
    return true;  // no two boxes meet: no overlap, and nothing to close
  for (std::size_t i = 0; i < a.body->pieces.size(); ++i)
    for (std::size_t k = 0; k < b.body->pieces.size(); ++k) {
      const double boxes = boxGap(a.boxes[i], b.boxes[k], along);
      if (boxes > 0 && !sink.closable(along, boxes)) continue;
      // Boxes that meet need the exact test (an overlap); boxes apart that
      // the part could close get GJK's distance and direction.
      Eigen::Vector3d normal = along;
      const double exact = hullClearance({a.body->pieces[i].points, a.pose}, {b.body->pieces[k].points, b.pose},
                                         sink.anyWay, &normal);
      if (exact == 0.0 && boxes == 0.0) return false;  // boxes apart never overlap, as in findContact
      if (exact > boxes) sink.add(normal, exact);
      else sink.add(along, boxes);
    }
  return true;
}

// The lowest point of the body's pieces above the floor (negative: below).
double aboveFloor(const CollisionBody& body, const Eigen::AlignedBox3d* boxes, double floor) {
  double least = kFar;
  for (std::size_t i = 0; i < body.pieces.size(); ++i)
    if (!boxes[i].isEmpty()) least = std::min(least, boxes[i].min().y() - floor);
  return least;
}

}  // namespace

void PartClearance::reset() {
  count = 0;
  elsewhere = kFar;
}

namespace {

// Gaps in a total order (by distance, then frame and direction): the
// gaps a part keeps do not hang on the order they come in, so a move's
// verdict is the same whatever numbers the objects have
// (CollisionWatch::reachKeyOf keys moves by shapes and places, not numbers).
bool narrower(const Gap& a, const Gap& b) {
  if (a.distance != b.distance) return a.distance < b.distance;
  if (a.from != b.from) return a.from < b.from;
  for (int k = 0; k < 3; ++k)
    if (a.normal[k] != b.normal[k]) return a.normal[k] < b.normal[k];
  return false;
}

}  // namespace

void PartClearance::add(const Gap& gap) {
  if (count < kGaps) {
    gaps[count++] = gap;
    return;
  }
  std::size_t widest = 0;
  for (std::size_t i = 1; i < kGaps; ++i)
    if (narrower(gaps[widest], gaps[i])) widest = i;
  if (narrower(gap, gaps[widest])) {
    elsewhere = std::min(elsewhere, gaps[widest].distance);
    gaps[widest] = gap;
  } else {
    elsewhere = std::min(elsewhere, gap.distance);
  }
}

double PartClearance::least() const {
  double d = elsewhere;
  for (std::size_t i = 0; i < count; ++i) d = std::min(d, gaps[i].distance);
  return d;
}

void CollisionData::boxParts(const CollisionQuery& query, bool holds) {
  const auto& robot = model_.robotBodies_;
  const auto& objects = model_.objectBodies_;
  for (std::size_t b = 0; b < robot.size(); ++b) {
    pieceBoxes(robot[b], robotPoses_[b], robotBoxes_[b].data());
    robotHull_[b].setEmpty();
    for (const Eigen::AlignedBox3d& box : robotBoxes_[b]) robotHull_[b].extend(box);
  }
  heldHull_.setEmpty();
  heldRaisedHull_.setEmpty();
  if (!holds) return;
  const Eigen::Isometry3d heldPose = F_world_i_.back() * query.heldOffset;
  pieceBoxes(objects[*query.held], heldPose, heldBoxes_.data());
  pieceBoxes(objects[*query.held], raisedForRest(heldPose), heldRaisedBoxes_.data());
  for (std::size_t i = 0; i < objects[*query.held].pieces.size(); ++i)
    heldHull_.extend(heldBoxes_[i]), heldRaisedHull_.extend(heldRaisedBoxes_[i]);
}

// What a move's reach is measured from (runtime/sim/collision_watch.cpp,
// CollisionWatch::moveReach): each part's box at the start of a stretch
// of the move. A part's box at a later check of the stretch lies within
// its travel since the stretch's start of that box, on every axis: its gap
// to an object shrinks by at most sqrt(3) times that travel (a corner's
// way), so a gap of more than twice the travel plus how far a check looks
// stays longer than any check of the stretch looks, and pairGaps adds
// nothing for it (the reasoning of markOutOfReach, for a stretch).
void CollisionData::reachBoxes(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                               std::vector<Eigen::AlignedBox3d>& out) {
  const auto& robot = model_.robotBodies_;
  pose(encoders);
  const bool holds = query.held && *query.held < model_.objectBodies_.size();
  boxParts(query, holds);
  out.assign(robot.size() + 1, Eigen::AlignedBox3d());
  for (std::size_t b = 0; b < robot.size(); ++b)
    if (!robot[b].pieces.empty() && robot[b].frame != 0) out[b] = robotHull_[b];
  if (holds) out[robot.size()] = heldRaisedHull_;
}

bool CollisionData::outOfReach(const Eigen::AlignedBox3d& part, double reach, const Eigen::AlignedBox3d& object) {
  if (part.isEmpty() || object.isEmpty()) return true;
  Eigen::Vector3d along;
  const double gap = boxGap(part, object, along);
  return gap > reach + 1e-6 * (1 + gap);  // a margin for the rounding of the poses the checks compute
}

// The objects whose gap to the box round every moving part (the links
// that are checked against objects, the carried object as raised for rest)
// is at least as long as the farthest any of them can still go: for each
// part alone that gap is no shorter (its box lies in that box), so
// pairGaps would find the part's box apart from the object's and the gap
// not closable, and add nothing. Skipping them is the same answer at one
// look per object instead of one per part and object: a feeder's parked
// slots, far below the floor, cost next to nothing.
void CollisionData::markOutOfReach(const CollisionQuery& query, SweepMotion& motion, bool holds) {
  const auto& robot = model_.robotBodies_;
  const auto& objects = model_.objectBodies_;
  Eigen::AlignedBox3d moving;
  double farthest = 0;
  for (std::size_t b = 0; b < robot.size(); ++b) {
    if (robot[b].pieces.empty() || robot[b].frame == 0) continue;
    moving.extend(robotHull_[b]);
    farthest = std::max(farthest, motion.anyWay(b));
  }
  if (holds) moving.extend(heldRaisedHull_), farthest = std::max(farthest, motion.anyWay(robot.size()));
  // Only the objects the query checks (not a feeder's empty slots): the
  // loops below ask outOfReach_ of those alone.
  query.anyObject(objects.size(), [&](std::size_t o) {
    outOfReach_[o] = 0;
    if (moving.isEmpty() || objects[o].pieces.empty()) return false;
    objectBoxes(o, query.objectPoses[o]);
    if (objectHull_[o].isEmpty()) return false;
    // Far above or below what moves: out of reach by the height alone,
    // well past rounding (the gap is at least that).
    const double apart = std::max(objectHull_[o].min().y() - moving.max().y(), moving.min().y() - objectHull_[o].max().y());
    if (apart > farthest * (1 + 1e-9) + 1e-9) {
      outOfReach_[o] = 1;
      return false;
    }
    Eigen::Vector3d along;
    const double gap = boxGap(moving, objectHull_[o], along);
    outOfReach_[o] = gap > 0 && gap >= farthest;
    return false;
  });
}

std::optional<Contact> CollisionData::findContactOrClearance(std::span<const std::int32_t> encoders,
                                                             const CollisionQuery& query, SweepMotion& motion,
                                                             std::span<PartClearance> clearance) {
  pose(encoders);
  const auto& robot = model_.robotBodies_;
  const auto& objects = model_.objectBodies_;
  const std::size_t heldIndex = robot.size();
  for (PartClearance& c : clearance) c.reset();
  const bool holds = query.held && *query.held < objects.size();
  const Eigen::Isometry3d heldPose = F_world_i_.back() * query.heldOffset, heldRaised = raisedForRest(heldPose);
  boxParts(query, holds);
  motion.posed(*this);
  markOutOfReach(query, motion, holds);

  const std::optional<double> floor = model_.cell_->floor;
  const int last = static_cast<int>(F_world_i_.size()) - 1;
  const auto robotSide = [&](std::size_t b) { return Side{&robot[b], &robotPoses_[b], robotBoxes_[b].data(), &robotHull_[b]}; };
  const auto objectSide = [&](std::size_t o) {
    const Eigen::AlignedBox3d* boxes = objectBoxes(o, query.objectPoses[o]);
    return Side{&objects[o], &query.objectPoses[o], boxes, &objectHull_[o]};
  };
  // The gaps of a mover (a part, its side, how far it can go) to what
  // stands still (from 0) or moves with the arm's frame `from`.
  struct Mover {
    std::size_t part;
    Side side;
    double anyWay;
  };
  const auto against = [&](const Mover& m, const Side& other, std::size_t from) {
    return !pairGaps(m.side, other, GapSink{motion, clearance[m.part], m.part, from, m.anyWay});
  };
  const auto underFloor = [&](const Mover& m, const Eigen::AlignedBox3d* boxes) {
    if (!floor) return false;
    const double d = aboveFloor(*m.side.body, boxes, *floor);
    if (d < 0) return true;
    GapSink{motion, clearance[m.part], m.part, 0, m.anyWay}.add(Eigen::Vector3d::UnitY(), d);
    return false;
  };
  for (std::size_t b = 0; b < robot.size(); ++b) {
    const CollisionBody& body = robot[b];
    if (body.pieces.empty()) continue;
    const Mover self{b, robotSide(b), motion.anyWay(b)};
    if (body.frame != 0) {
      if (underFloor(self, robotBoxes_[b].data())) return Contact{body.ref, {BodyKind::Floor, 0}};
      std::size_t hit = 0;
      if (query.anyObject(objects.size(), [&](std::size_t o) {
            if (query.held == o || (isFinger(body) && query.exempt == o) || outOfReach_[o]) return false;
            return against(self, objectSide(o), 0) && (hit = o, true);
          }))
        return Contact{body.ref, objects[hit].ref};
    }
    for (std::size_t c = 0; c < robot.size(); ++c) {
      if (robot[c].frame > body.frame - 2 || robot[c].pieces.empty()) continue;
      if (against(self, robotSide(c), static_cast<std::size_t>(robot[c].frame))) return Contact{body.ref, robot[c].ref};
    }
  }
  if (!holds) return std::nullopt;
  const CollisionBody& held = objects[*query.held];
  // Against the floor and the objects as raised for rest (a part put down
  // a little into its support rests on it), against the robot as it is.
  const Mover self{heldIndex, Side{&held, &heldPose, heldBoxes_.data(), &heldHull_}, motion.anyWay(heldIndex)};
  const Mover raised{heldIndex, Side{&held, &heldRaised, heldRaisedBoxes_.data(), &heldRaisedHull_}, self.anyWay};
  if (underFloor(raised, heldRaisedBoxes_.data())) return Contact{held.ref, {BodyKind::Floor, 0}};
  std::size_t hit = 0;
  if (query.anyObject(objects.size(), [&](std::size_t o) {
        if (o == *query.held || outOfReach_[o]) return false;
        return against(raised, objectSide(o), 0) && (hit = o, true);
      }))
    return Contact{held.ref, objects[hit].ref};
  for (std::size_t c = 0; c < robot.size(); ++c) {
    if (robot[c].frame > last - 2 || robot[c].pieces.empty()) continue;
    if (against(self, robotSide(c), static_cast<std::size_t>(robot[c].frame))) return Contact{held.ref, robot[c].ref};
  }
  return std::nullopt;
}

}  // namespace rs::workcell
