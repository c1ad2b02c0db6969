#include "model/workcell/gjk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace rs::workcell {

namespace {

using Eigen::Vector3d;

constexpr int kMaxIterations = 64;
// A clearance within this share of the distance is good enough.
constexpr double kCloseEnough = 0.98;

// The point of the hull farthest along world direction d.
Vector3d support(const PlacedHull& h, const Vector3d& d) {
  const Vector3d local = h.pose->linear().transpose() * d;
  std::size_t best = 0;
  double bestDot = h.points[0].dot(local);
  for (std::size_t i = 1; i < h.points.size(); ++i)
    if (const double v = h.points[i].dot(local); v > bestDot) bestDot = v, best = i;
  return *h.pose * h.points[best];
}

// The simplex (1 to 4 points of the Minkowski difference a − b) and the
// point of it closest to the origin; `reduce` keeps only the points whose
// barycentric weight is not zero (the smallest face holding that point).
struct Simplex {
  std::array<Vector3d, 4> p;
  int n = 0;

  void keep(std::initializer_list<int> which) {
    std::array<Vector3d, 4> q = p;
    int m = 0;
    for (int i : which) q[static_cast<std::size_t>(m++)] = p[static_cast<std::size_t>(i)];
    p = q, n = m;
  }

  Vector3d closestOnSegment(int ia, int ib, bool reduce) {
    const Vector3d& a = p[static_cast<std::size_t>(ia)];
    const Vector3d& b = p[static_cast<std::size_t>(ib)];
    const Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp(-a.dot(ab) / len2, 0.0, 1.0) : 0.0;
    // Worked out before `keep`, which moves the points `a` and `b` refer to.
    const Vector3d closestPoint = a + t * ab;
    if (reduce) {
      if (t <= 0) keep({ia});
      else if (t >= 1) keep({ib});
      else keep({ia, ib});
    }
    return closestPoint;
  }

  // Ericson, "Real-Time Collision Detection" 5.1.5, for the origin, with a
  // fall back to the edges when the triangle has no area.
  Vector3d closestOnTriangle(int ia, int ib, int ic, bool reduce) {
    const Vector3d& a = p[static_cast<std::size_t>(ia)];
    const Vector3d& b = p[static_cast<std::size_t>(ib)];
    const Vector3d& c = p[static_cast<std::size_t>(ic)];
    const Vector3d ab = b - a, ac = c - a;
    if (ab.cross(ac).squaredNorm() <= 1e-20 * std::max(ab.squaredNorm(), ac.squaredNorm()) * std::max(ab.squaredNorm(), ac.squaredNorm()))
      return closestOnDegenerateTriangle(ia, ib, ic, reduce);
    const Vector3d ap = -a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return reduce ? (keep({ia}), p[0]) : a;
    const Vector3d bp = -b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return reduce ? (keep({ib}), p[0]) : b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
      const Vector3d r = a + d1 / (d1 - d3) * ab;
      if (reduce) keep({ia, ib});
      return r;
    }
    const Vector3d cp = -c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return reduce ? (keep({ic}), p[0]) : c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
      const Vector3d r = a + d2 / (d2 - d6) * ac;
      if (reduce) keep({ia, ic});
      return r;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
      const Vector3d r = b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
      if (reduce) keep({ib, ic});
      return r;
    }
    const double denom = 1.0 / (va + vb + vc);
    const Vector3d r = a + ab * (vb * denom) + ac * (vc * denom);
    if (reduce) keep({ia, ib, ic});
    return r;
  }

  Vector3d closestOnDegenerateTriangle(int ia, int ib, int ic, bool reduce) {
    const std::array<std::array<int, 2>, 3> edges{{{ia, ib}, {ia, ic}, {ib, ic}}};
    int best = 0;
    double bestD = INFINITY;
    Vector3d bestP = Vector3d::Zero();
    for (int e = 0; e < 3; ++e) {
      const Vector3d q = closestOnSegment(edges[static_cast<std::size_t>(e)][0], edges[static_cast<std::size_t>(e)][1], false);
      if (q.squaredNorm() < bestD) bestD = q.squaredNorm(), best = e, bestP = q;
    }
    if (reduce) closestOnSegment(edges[static_cast<std::size_t>(best)][0], edges[static_cast<std::size_t>(best)][1], true);
    return bestP;
  }

  // The origin inside the tetrahedron: the origin itself (an overlap).
  // Otherwise the closest point of the faces the origin lies outside of.
  Vector3d closestOnTetrahedron(bool& inside) {
    static constexpr std::array<std::array<int, 4>, 4> kFaces{{{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}}};
    const double volume = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
    const double scale = std::max({(p[1] - p[0]).norm(), (p[2] - p[0]).norm(), (p[3] - p[0]).norm()});
    const bool flat = volume <= 1e-12 * scale * scale * scale;
    inside = !flat;
    double bestD = INFINITY;
    std::array<int, 3> bestFace{0, 1, 2};
    Vector3d bestP = Vector3d::Zero();
    for (const auto& f : kFaces) {
      const Vector3d& a = p[static_cast<std::size_t>(f[0])];
      const Vector3d n = (p[static_cast<std::size_t>(f[1])] - a).cross(p[static_cast<std::size_t>(f[2])] - a);
      const double sideOrigin = n.dot(-a), sideOther = n.dot(p[static_cast<std::size_t>(f[3])] - a);
      if (!flat && sideOrigin * sideOther >= 0) continue;  // the origin is on the inner side of this face
      inside = false;
      const Vector3d q = closestOnTriangle(f[0], f[1], f[2], false);
      if (q.squaredNorm() < bestD) bestD = q.squaredNorm(), bestFace = {f[0], f[1], f[2]}, bestP = q;
    }
    if (inside) return Vector3d::Zero();
    closestOnTriangle(bestFace[0], bestFace[1], bestFace[2], true);
    return bestP;
  }

  Vector3d closest(bool& inside) {
    inside = false;
    switch (n) {
      case 1: return p[0];
      case 2: return closestOnSegment(0, 1, true);
      case 3: return closestOnTriangle(0, 1, 2, true);
      default: return closestOnTetrahedron(inside);
    }
  }
};

// What a run of GJK answers: whether the hulls overlap (it stops at the
// first separating plane), their distance, or a lower bound on it that is
// refined only up to a bound the caller needs.
enum class Ask : std::uint8_t { Overlap, Distance, Clearance };

// The least positive double: "apart, but no useful bound".
constexpr double kApart = 4.9406564584124654e-324;

// Runs GJK; returns the distance (0 for an overlap). Asked for an overlap,
// returns a positive value as soon as a separating plane is found. Asked
// for a clearance, goes the same way until that plane (so it decides an
// overlap exactly as the overlap question does), then keeps the best lower
// bound v·w/|v| it has seen and stops once it reaches `enough`.
double gjk(const PlacedHull& a, const PlacedHull& b, Ask ask, double enough = 0, Vector3d* normal = nullptr) {
  Vector3d v = support(a, Vector3d::UnitX()) - support(b, -Vector3d::UnitX());
  // How close to zero counts as touching: relative to the shapes' size.
  const double scale = std::max(1.0, v.norm());
  const double touching2 = 1e-18 * scale * scale;
  bool separated = false;  // a separating plane has been seen (Clearance)
  double lower = kApart;   // the best lower bound so far, once separated
  const auto apart = [&](double distance) { return ask == Ask::Clearance ? lower : distance; };
  Simplex s;
  s.p[0] = v, s.n = 1;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double v2 = v.squaredNorm();
    if (v2 <= touching2) return separated ? lower : 0.0;
    const Vector3d w = support(a, -v) - support(b, v);
    const double vw = v.dot(w);
    if (vw > 0) {
      if (ask == Ask::Overlap) return std::sqrt(v2);  // a plane with normal v separates them
      if (ask == Ask::Clearance) {
        separated = true;
        if (const double bound = vw / std::sqrt(v2); bound > lower) {
          lower = bound;
          if (normal) *normal = v / std::sqrt(v2);
        }
        // Enough asked for, or within 2% of the distance (|v| bounds it
        // from above): more iterations would hardly change what it allows.
        if (lower >= enough || vw >= kCloseEnough * v2) return lower;
      }
    }
    if (v2 - vw <= 1e-12 * v2) return apart(std::sqrt(v2));  // no nearer point: converged
    bool duplicate = false;
    for (int i = 0; i < s.n; ++i) duplicate |= s.p[static_cast<std::size_t>(i)] == w;
    if (duplicate) return apart(std::sqrt(v2));
    s.p[static_cast<std::size_t>(s.n++)] = w;
    bool inside = false;
    v = s.closest(inside);
    if (inside) return separated ? lower : 0.0;
  }
  if (ask == Ask::Clearance) return separated || v.norm() != 0.0 ? lower : 0.0;
  return v.norm();
}

}  // namespace

bool hullsOverlap(const PlacedHull& a, const PlacedHull& b) { return gjk(a, b, Ask::Overlap) == 0.0; }

double hullDistance(const PlacedHull& a, const PlacedHull& b) { return gjk(a, b, Ask::Distance); }

double hullClearance(const PlacedHull& a, const PlacedHull& b, double enough, Eigen::Vector3d* normal) {
  return gjk(a, b, Ask::Clearance, enough, normal);
}

}  // namespace rs::workcell
