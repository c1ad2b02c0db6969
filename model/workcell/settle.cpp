#include "model/workcell/settle.h"

#include <algorithm>
#include <cmath>

namespace rs::workcell {

namespace {

// A drop smaller than this is none: the part stays bit for bit where it
// was let go (a loop that puts a part down exactly on its support and
// takes it again leaves the world unchanged).
constexpr double kNoDrop = 1e-9;

Eigen::AlignedBox3d boxOf(const ConvexPiece& piece, const Eigen::Isometry3d& T) {
  Eigen::AlignedBox3d b;
  for (const Eigen::Vector3d& p : piece.points) b.extend(T * p);
  return b;
}

// Footprints in x and z overlap by more than a sliver (edges that only
// touch hold nothing up).
bool footprintsMeet(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  constexpr double kSliver = 1e-6;
  return std::min(a.max().x(), b.max().x()) - std::max(a.min().x(), b.min().x()) > kSliver &&
         std::min(a.max().z(), b.max().z()) - std::max(a.min().z(), b.min().z()) > kSliver;
}

}  // namespace

double settleReach(const PlacedObject& o) {
  double r = 0;
  for (const ConvexPiece& piece : o.shape.collision)
    for (const Eigen::Vector3d& p : piece.points) r = std::max(r, p.norm());
  if (o.belt && !o.belt->surface.isEmpty())
    for (int c = 0; c < 8; ++c)
      r = std::max(r, o.belt->surface.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)).norm());
  return r;
}

namespace {

// Object `o`'s pieces' and belt's world boxes at `pose`, from the cache when
// it holds them for this very pose.
const SupportBoxes::Object& supportBoxes(const PlacedObject& other, std::size_t o, const Eigen::Isometry3d& pose,
                                         SupportBoxes& cache) {
  if (cache.objects.size() <= o) cache.objects.resize(o + 1);
  SupportBoxes::Object& c = cache.objects[o];
  if (c.at == pose.matrix()) return c;
  c.at = pose.matrix();
  c.pieces.clear();
  for (const ConvexPiece& piece : other.shape.collision) c.pieces.push_back(boxOf(piece, pose));
  c.belt = other.belt ? other.belt->surface.transformed(pose) : Eigen::AlignedBox3d();
  return c;
}

}  // namespace

Settled settle(const Workcell& cell, std::span<const Eigen::Isometry3d> poses, std::size_t part,
               const Eigen::Isometry3d& pose, std::optional<std::size_t> skip, std::span<const double> reach,
               SupportBoxes* boxes, const std::vector<std::size_t>* among) {
  SupportBoxes once;
  if (!boxes) boxes = &once;
  Settled s;
  s.pose = pose;
  Eigen::AlignedBox3d self;
  for (const ConvexPiece& piece : cell.objects[part].shape.collision) self.extend(boxOf(piece, pose));
  if (self.isEmpty()) self = boundsOf(cell.objects[part].shape).transformed(pose);
  if (self.isEmpty()) return s;
  // A support's top is at most the tolerance above the part's bottom, or
  // below its middle: a part let go deeper in its support is lifted out
  // onto it rather than dropped through it.
  const double bottom = self.min().y(), highest = std::max(bottom + kSettleTolerance, self.center().y());
  std::optional<double> top;
  const auto consider = [&](double t, Settled::On on, std::size_t o) {
    if (t > highest || (top && t <= *top)) return;  // strictly higher wins: the first of equals
    top = t, s.on = on, s.support = o;
  };
  const std::size_t n = among ? among->size() : cell.objects.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t o = among ? (*among)[i] : i;
    if (o >= cell.objects.size() || o >= poses.size()) break;
    if (o == part || skip == o) continue;
    if (o < reach.size()) {
      // Every footprint of it lies within its reach of where it stands: a
      // part let go beyond that (a feeder's parked slots, far corners of
      // the cell) it cannot hold up.
      const Eigen::Vector3d at = poses[o].translation();
      const double r = reach[o] + 1e-6;
      if (self.min().x() > at.x() + r || self.max().x() < at.x() - r || self.min().z() > at.z() + r ||
          self.max().z() < at.z() - r)
        continue;
    }
    const PlacedObject& other = cell.objects[o];
    const SupportBoxes::Object& world = supportBoxes(other, o, poses[o], *boxes);
    for (const Eigen::AlignedBox3d& b : world.pieces)
      if (!b.isEmpty() && footprintsMeet(self, b)) consider(b.max().y(), Settled::On::Object, o);
    if (other.belt) {
      const Eigen::AlignedBox3d& b = world.belt;
      // The belt's surface is where its part rides: on a tie with the
      // object's own top, the belt.
      if (footprintsMeet(self, b) && b.max().y() <= highest && (!top || b.max().y() >= *top))
        top = b.max().y(), s.on = Settled::On::Belt, s.support = o;
    }
  }
  if (cell.floor) consider(*cell.floor, Settled::On::Floor, 0);
  if (!top) return s;
  s.drop = bottom - *top;
  if (std::abs(s.drop) <= kNoDrop) {
    s.drop = 0;
    return s;
  }
  s.pose = Eigen::Translation3d(0, -s.drop, 0) * pose;
  return s;
}

}  // namespace rs::workcell
