#include "model/workcell/support.h"

#include <algorithm>
#include <cmath>

namespace rs::workcell {

namespace {

// Faces "touch" within this much of the larger coordinate: descriptions
// are written in decimals, so a block AT y 780 on a deck of top 750 + 30
// meets it exactly or within rounding.
bool sameHeight(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); }

double overlap(double lo1, double hi1, double lo2, double hi2) { return std::min(hi1, hi2) - std::max(lo1, lo2); }

}  // namespace

Eigen::AlignedBox3d worldBoxOf(const Shape& shape, const Eigen::Isometry3d& F_world_design) {
  Eigen::AlignedBox3d box;
  for (const Segment& s : shape.segments) box.extend(F_world_design * s.a), box.extend(F_world_design * s.b);
  return box;
}

Support supportOf(const Eigen::AlignedBox3d& box, std::span<const PlacedObject> objects,
                  std::optional<std::size_t> self) {
  Support best;
  if (box.isEmpty()) return best;
  const double bottom = box.min().y();
  double bestArea = 0;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (self == i) continue;
    // The extent of the object's level lines at the box's bottom; the
    // object must reach below them (lines at its own bottom, a pallet's
    // runners on the floor, hold nothing up).
    Eigen::AlignedBox3d level;
    double lowest = INFINITY;
    for (const Segment& s : objects[i].shape.segments) {
      const Eigen::Vector3d a = objects[i].F_world_design * s.a, b = objects[i].F_world_design * s.b;
      lowest = std::min({lowest, a.y(), b.y()});
      if (sameHeight(a.y(), bottom) && sameHeight(b.y(), bottom)) level.extend(a), level.extend(b);
    }
    if (level.isEmpty() || sameHeight(lowest, bottom)) continue;
    const double dx = overlap(box.min().x(), box.max().x(), level.min().x(), level.max().x());
    const double dz = overlap(box.min().z(), box.max().z(), level.min().z(), level.max().z());
    if (dx <= 0 || dz <= 0 || dx * dz <= bestArea) continue;
    bestArea = dx * dz;
    best = {Support::Kind::Object, i};
  }
  if (best.kind == Support::Kind::Nothing && sameHeight(bottom, 0.0)) best.kind = Support::Kind::Floor;
  return best;
}

}  // namespace rs::workcell
