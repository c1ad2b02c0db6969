// GJK on point hulls (model/workcell/gjk.h) against an independent test:
// the separating-axis theorem on oriented boxes (15 axes: 3 + 3 face
// normals and 9 edge cross products), on random boxes; and the cases GJK
// finds hard: a lone segment, a flat plate, touching faces.
#include <catch2/catch.hpp>

#include <array>
#include <random>
#include <vector>

#include "model/workcell/gjk.h"

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using rs::workcell::hullsOverlap;

struct Box {
  Vector3d half;
  Isometry3d pose = Isometry3d::Identity();
  std::vector<Vector3d> corners() const {
    std::vector<Vector3d> c;
    for (int i = 0; i < 8; ++i)
      c.emplace_back((i & 4 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(), (i & 1 ? 1 : -1) * half.z());
    return c;
  }
};

// Separating-axis test: some axis on which the projections do not meet.
bool satOverlap(const Box& a, const Box& b) {
  std::vector<Vector3d> axes;
  for (int k = 0; k < 3; ++k) axes.push_back(a.pose.linear().col(k)), axes.push_back(b.pose.linear().col(k));
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const Vector3d c = a.pose.linear().col(i).cross(b.pose.linear().col(k));
      if (c.norm() > 1e-9) axes.push_back(c.normalized());
    }
  const Vector3d d = b.pose.translation() - a.pose.translation();
  for (const Vector3d& u : axes) {
    double ra = 0, rb = 0;
    for (int k = 0; k < 3; ++k) {
      ra += a.half[k] * std::abs(a.pose.linear().col(k).dot(u));
      rb += b.half[k] * std::abs(b.pose.linear().col(k).dot(u));
    }
    if (std::abs(d.dot(u)) > ra + rb) return false;
  }
  return true;
}

Isometry3d randomPose(std::mt19937_64& rng, double spread) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
  if (q.norm() < 1e-3) q = Eigen::Quaterniond::Identity();
  Isometry3d T = Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = spread * Vector3d(u(rng), u(rng), u(rng));
  return T;
}

}  // namespace

TEST_CASE("GJK agrees with the separating-axis test on random oriented boxes", "[collision][gjk]") {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> size(0.1, 3.0);
  int overlaps = 0, apart = 0, unclear = 0;
  for (int i = 0; i < 4000; ++i) {
    Box a{{size(rng), size(rng), size(rng)}, randomPose(rng, 4)};
    Box b{{size(rng), size(rng), size(rng)}, randomPose(rng, 4)};
    const bool sat = satOverlap(a, b);
    // Cases within 1e-6 of touching are left out: either answer is right.
    Box grown = a, shrunk = a;
    grown.half.array() += 1e-6, shrunk.half.array() -= 1e-6;
    if (satOverlap(grown, b) != satOverlap(shrunk, b)) {
      ++unclear;
      continue;
    }
    const std::vector<Vector3d> ca = a.corners(), cb = b.corners();
    INFO("pair " << i);
    CHECK(hullsOverlap({ca, &a.pose}, {cb, &b.pose}) == sat);
    (sat ? overlaps : apart)++;
  }
  CHECK(overlaps > 500);
  CHECK(apart > 500);
  CHECK(unclear < 10);
}

TEST_CASE("GJK on a lone segment, a flat plate and boxes that touch", "[collision][gjk]") {
  const Isometry3d I = Isometry3d::Identity();
  const std::vector<Vector3d> cube{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  // A segment through the cube, beside it, and ending on its face.
  const std::vector<Vector3d> through{{0.5, 0.5, -2}, {0.5, 0.5, 3}}, beside{{1.5, 0.5, -2}, {1.5, 0.5, 3}};
  CHECK(hullsOverlap({cube, &I}, {through, &I}));
  CHECK_FALSE(hullsOverlap({cube, &I}, {beside, &I}));
  CHECK(rs::workcell::hullDistance({cube, &I}, {beside, &I}) == Approx(0.5));
  // A plate of no thickness across the cube, and one above it.
  const std::vector<Vector3d> plate{{-1, -1, 0.5}, {2, -1, 0.5}, {-1, 2, 0.5}, {2, 2, 0.5}};
  const std::vector<Vector3d> above{{-1, -1, 1.25}, {2, -1, 1.25}, {-1, 2, 1.25}, {2, 2, 1.25}};
  CHECK(hullsOverlap({cube, &I}, {plate, &I}));
  CHECK_FALSE(hullsOverlap({cube, &I}, {above, &I}));
  CHECK(rs::workcell::hullDistance({cube, &I}, {above, &I}) == Approx(0.25));
  // Two plates crossing at right angles, and a single point inside.
  const std::vector<Vector3d> upright{{0.5, -1, -1}, {0.5, 2, -1}, {0.5, -1, 2}, {0.5, 2, 2}};
  CHECK(hullsOverlap({plate, &I}, {upright, &I}));
  const std::vector<Vector3d> point{{0.25, 0.75, 0.5}};
  CHECK(hullsOverlap({cube, &I}, {point, &I}));
  // Cubes apart by 1e-3 and moved by a pose.
  Isometry3d T = Isometry3d::Identity();
  T.translation() = Vector3d(1.001, 0.2, 0.3);
  CHECK_FALSE(hullsOverlap({cube, &I}, {cube, &T}));
  T.translation() = Vector3d(0.999, 0.2, 0.3);
  CHECK(hullsOverlap({cube, &I}, {cube, &T}));
}

TEST_CASE("GJK's clearance: 0 exactly for an overlap, else a lower bound on the distance with its separating plane",
          "[collision][gjk]") {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> size(0.1, 1.5), enoughOf(0.0, 3.0);
  int apart = 0;
  for (int i = 0; i < 3000; ++i) {
    const Box a{{size(rng), size(rng), size(rng)}, randomPose(rng, 3)};
    const Box b{{size(rng), size(rng), size(rng)}, randomPose(rng, 3)};
    const std::vector<Vector3d> ca = a.corners(), cb = b.corners();
    const rs::workcell::PlacedHull ha{ca, &a.pose}, hb{cb, &b.pose};
    const double enough = enoughOf(rng);
    Vector3d normal = Vector3d::Zero();
    const double clearance = rs::workcell::hullClearance(ha, hb, enough, &normal);
    INFO("pair " << i);
    CHECK((clearance == 0.0) == hullsOverlap(ha, hb));
    if (clearance == 0.0) continue;
    ++apart;
    const double distance = rs::workcell::hullDistance(ha, hb);
    CHECK(clearance <= distance * (1 + 1e-9));
    // Refined until it is enough or within 2% of the distance.
    CHECK((clearance >= enough || clearance >= 0.98 * distance * (1 - 1e-9)));
    if (normal.isZero()) continue;  // numerically touching: no plane
    CHECK(normal.norm() == Approx(1.0));
    // The plane: every corner of a at least `clearance` beyond every corner of b.
    double least = 1e300;
    for (const Vector3d& p : ca)
      for (const Vector3d& q : cb) least = std::min(least, (a.pose * p - b.pose * q).dot(normal));
    CHECK(least >= clearance - 1e-9);
  }
  CHECK(apart > 500);
}
