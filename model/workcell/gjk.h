// Do two convex hulls share a point? The Gilbert–Johnson–Keerthi
// algorithm on point sets: each hull is only asked for its support point
// (the point farthest along a direction), so a piece needs no faces, a
// flat plate or a lone line is as good as a box, and nothing allocates.
// Written for robotsim (docs/models.md, "Collisions"; the choice against
// libfcl is measured in bench/bench_collision.cpp, docs/performance.md).
#pragma once

#include <Eigen/Geometry>
#include <span>

namespace rs::workcell {

/// A hull placed in the world: the convex hull of `points` (its own
/// coordinates) moved by `pose`.
struct PlacedHull {
  std::span<const Eigen::Vector3d> points;
  const Eigen::Isometry3d* pose = nullptr;
};

/// True when the hulls overlap or lie closer than about 1e-9 of their size
/// (numerically touching). Both must have at least one point. Deterministic:
/// a fixed start direction and at most 64 iterations.
bool hullsOverlap(const PlacedHull& a, const PlacedHull& b);

/// The distance between the hulls (0 when they overlap), by the same
/// iteration; for tests and for messages.
double hullDistance(const PlacedHull& a, const PlacedHull& b);

/// For the swept check: 0 exactly when hullsOverlap says they overlap
/// (the same iteration, up to the first separating plane); otherwise a
/// positive lower bound L on their distance, refined until it reaches
/// `enough` or 98% of the distance. With `normal`, the unit
/// direction n of the plane that gives L: (p − q)·n ≥ L for every point p
/// of `a` and q of `b`. A pair that is apart with no useful bound yet
/// (numerically touching) gets the least positive double and no normal.
double hullClearance(const PlacedHull& a, const PlacedHull& b, double enough, Eigen::Vector3d* normal = nullptr);

}  // namespace rs::workcell
