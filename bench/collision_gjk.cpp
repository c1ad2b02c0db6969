// collision_bench's gjk part: robotsim's GJK on point hulls against libfcl
// 0.7 (when found at configure time) on the same random box pairs; and the
// swept check's question, a clearance (a lower bound on the distance,
// refined only as far as asked), beside the plain overlap test.
#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <random>
#include <vector>

#include "bench/collision_runs.h"
#include "model/workcell/gjk.h"

#ifdef ROBOTSIM_BENCH_FCL
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#endif

namespace rs::bench {

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

struct BoxPair {
  Vector3d halfA, halfB;
  Isometry3d A, B;
};

Isometry3d randomPose(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
  Isometry3d T = Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = 3 * Vector3d(u(rng), u(rng), u(rng));
  return T;
}

std::vector<Vector3d> corners(const Vector3d& h) {
  std::vector<Vector3d> c;
  for (int i = 0; i < 8; ++i) c.emplace_back((i & 4 ? 1 : -1) * h.x(), (i & 2 ? 1 : -1) * h.y(), (i & 1 ? 1 : -1) * h.z());
  return c;
}

template <typename F>
double bestNsPerCall(int reps, long calls, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < calls; ++i) f(i);
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, ns / static_cast<double>(calls));
  }
  return best;
}

}  // namespace

void benchGjk(const CollisionBenchOptions& options) {
  const long calls = options.smoke ? 2'000 : 1'000'000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> size(0.2, 2.0);
  std::vector<BoxPair> pairs(1024);
  for (BoxPair& p : pairs) p = {{size(rng), size(rng), size(rng)}, {size(rng), size(rng), size(rng)}, randomPose(rng), randomPose(rng)};
  std::vector<std::vector<Vector3d>> ca, cb;
  for (const BoxPair& p : pairs) ca.push_back(corners(p.halfA)), cb.push_back(corners(p.halfB));

  fmt::print("collision tests on 1024 random box pairs (about half overlap), {} calls, best of {}\n", calls, options.reps);
  long hits = 0, clearHits = 0;
  const double gjk = bestNsPerCall(options.reps, calls, [&](long i) {
    const std::size_t k = static_cast<std::size_t>(i & 1023);
    hits += workcell::hullsOverlap({ca[k], &pairs[k].A}, {cb[k], &pairs[k].B});
  });
  fmt::print("  robotsim GJK on 8-point hulls  {:7.1f} ns per pair ({} overlaps)\n", gjk, hits);
  const double clearance = bestNsPerCall(options.reps, calls, [&](long i) {
    const std::size_t k = static_cast<std::size_t>(i & 1023);
    clearHits += workcell::hullClearance({ca[k], &pairs[k].A}, {cb[k], &pairs[k].B}, 1e9) == 0.0;
  });
  fmt::print("  the same, clearance to the distance {:7.1f} ns per pair ({} overlaps)\n", clearance, clearHits);
#ifdef ROBOTSIM_BENCH_FCL
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> oa, ob;
  for (const BoxPair& p : pairs) {
    oa.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Boxd>(2 * p.halfA), p.A));
    ob.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Boxd>(2 * p.halfB), p.B));
  }
  long fclHits = 0;
  const fcl::CollisionRequestd request;
  const double fclNs = bestNsPerCall(options.reps, calls, [&](long i) {
    const std::size_t k = static_cast<std::size_t>(i & 1023);
    fcl::CollisionResultd result;
    fcl::collide(oa[k].get(), ob[k].get(), request, result);
    fclHits += result.isCollision();
  });
  fmt::print("  libfcl 0.7 Boxd / Boxd         {:7.1f} ns per pair ({} overlaps)\n", fclNs, fclHits);
#else
  fmt::print("  libfcl: not found at configure time, not compared\n");
#endif
}

}  // namespace rs::bench
