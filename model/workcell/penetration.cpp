#include "model/workcell/penetration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rs::workcell {

namespace {

// The hull's extent along unit axis `d`.
std::pair<double, double> extent(const PlacedHull& h, const Eigen::Vector3d& d) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Eigen::Vector3d& p : h.points) {
    const double x = (*h.pose * p).dot(d);
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return {lo, hi};
}

}  // namespace

Overlap hullOverlap(const PlacedHull& a, const PlacedHull& b) {
  std::array<Eigen::Vector3d, 18> axes;  // the world's 3, each hull's 3, their 9 cross products
  std::size_t n = 0;
  for (int k = 0; k < 3; ++k) axes[n++] = Eigen::Vector3d::Unit(k);
  for (int k = 0; k < 3; ++k) axes[n++] = a.pose->linear().col(k);
  for (int k = 0; k < 3; ++k) axes[n++] = b.pose->linear().col(k);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d c = a.pose->linear().col(i).cross(b.pose->linear().col(k));
      if (c.norm() > 1e-6) axes[n++] = c.normalized();
    }
  Overlap best{std::numeric_limits<double>::infinity(), Eigen::Vector3d::UnitY()};
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& d = axes[i];
    const auto [aLo, aHi] = extent(a, d);
    const auto [bLo, bHi] = extent(b, d);
    // Along +d, a clears b once its low end passes b's high end; along -d, once its high end passes b's low end.
    const double up = bHi - aLo, down = aHi - bLo;
    const Overlap o = up <= down ? Overlap{up, d} : Overlap{down, -d};
    if (o.depth < best.depth) best = o;
  }
  best.depth = std::max(best.depth, 0.0);
  return best;
}

}  // namespace rs::workcell
