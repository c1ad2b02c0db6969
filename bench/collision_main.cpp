// Collision benchmark (issue 14, "Collisions"): robotsim's own GJK on point
// hulls (model/workcell/gjk.h) against libfcl 0.7 (Debian's libfcl-dev,
// when found at configure time) on the same random box pairs, and the cost
// of the swept check of a whole run: a SCARA program on the library's
// scara-pick cell with --collisions=error against off. Run by `make bench`;
// figures go to docs/performance.md ("Collisions").
#include <chrono>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "bench/bench_args.h"
#include "compiler/compiler.h"
#include "compiler/library.h"
#include "launch/program.h"
#include "model/workcell/collision_model.h"
#include "model/workcell/gjk.h"
#include "runtime/run/run.h"

#ifdef ROBOTSIM_BENCH_FCL
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#endif

namespace {

using Clock = std::chrono::steady_clock;
using Eigen::Isometry3d;
using Eigen::Vector3d;

struct Pair {
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
    const auto start = Clock::now();
    for (long i = 0; i < calls; ++i) f(i);
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    best = std::min(best, ns / static_cast<double>(calls));
  }
  return best;
}

// A SCARA program that sweeps its arm over the whole range, up and down,
// with the gripper opening and closing: every move checked.
constexpr const char* kProgram =
    "        SET N 0\n"
    "loop:   MOVETO 1000 -550 0 0 0\n"
    "        MOVETO -1000 550 0 700 120\n"
    "        MOVETO 0 0 0 -700 0\n"
    "        ADD N 1\n"
    "        JMPVAR N < 50 loop\n"
    "        END\n";

}  // namespace

int main(int argc, char** argv) {
  const rs::bench::CountArgument counts[] = {{"REPS", "runs (the best is printed)", 5, 1}};
  const rs::bench::BenchArguments args = rs::bench::parseBenchArguments(
      argc, argv, "collision_bench", "GJK against libfcl, and the swept check of a run (docs/performance.md).", counts);
  if (args.exitCode) return *args.exitCode;
  const int reps = static_cast<int>(args[0]);
  constexpr long kCalls = 1'000'000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> size(0.2, 2.0);
  std::vector<Pair> pairs(1024);
  for (Pair& p : pairs) p = {{size(rng), size(rng), size(rng)}, {size(rng), size(rng), size(rng)}, randomPose(rng), randomPose(rng)};
  std::vector<std::vector<Vector3d>> ca, cb;
  for (const Pair& p : pairs) ca.push_back(corners(p.halfA)), cb.push_back(corners(p.halfB));

  std::printf("collision tests on 1024 random box pairs (about half overlap), best of %d\n", reps);
  long hits = 0;
  const double gjk = bestNsPerCall(reps, kCalls, [&](long i) {
    const std::size_t k = static_cast<std::size_t>(i & 1023);
    hits += rs::workcell::hullsOverlap({ca[k], &pairs[k].A}, {cb[k], &pairs[k].B});
  });
  std::printf("  robotsim GJK on 8-point hulls  %7.1f ns per pair (%ld overlaps)\n", gjk, hits);
#ifdef ROBOTSIM_BENCH_FCL
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> oa, ob;
  for (const Pair& p : pairs) {
    oa.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Boxd>(2 * p.halfA), p.A));
    ob.push_back(std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Boxd>(2 * p.halfB), p.B));
  }
  long fclHits = 0;
  const fcl::CollisionRequestd request;
  const double fclNs = bestNsPerCall(reps, kCalls, [&](long i) {
    const std::size_t k = static_cast<std::size_t>(i & 1023);
    fcl::CollisionResultd result;
    fcl::collide(oa[k].get(), ob[k].get(), request, result);
    fclHits += result.isCollision();
  });
  std::printf("  libfcl 0.7 Boxd / Boxd         %7.1f ns per pair (%ld overlaps)\n", fclNs, fclHits);
#else
  std::printf("  libfcl: not found at configure time, not compared\n");
#endif

  // The swept check of a whole run.
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> cell = library.workcell("scara-pick");
  if (!cell) return 1;
  auto shared = std::make_shared<const rs::workcell::Workcell>(*cell);
  const rs::diag::SourceFile source("sweep.rsp", kProgram);
  rs::compiler::CompileResult compiled = rs::compiler::compile(source, rs::launch::cellTarget(*cell));
  if (!compiled.image) return 1;
  auto image = std::make_shared<const rs::vm::Image>(*compiled.image);
  const auto runOnce = [&](rs::runtime::CollisionMode mode, std::uint64_t* checks, double* simulated) {
    rs::runtime::RunSpec spec;
    spec.image = image;
    spec.cell = shared;
    spec.collisions = mode;
    rs::runtime::Run run(std::move(spec));
    const auto start = Clock::now();
    const rs::vm::RunOutcome outcome = run.runToEnd();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (!outcome.ok()) std::printf("  (the run stopped: %s)\n", outcome.message.c_str());
    if (checks) *checks = run.collisionWatch() ? run.collisionWatch()->checks() : 0;
    if (simulated) *simulated = static_cast<double>(run.clock()) / 1e6;
    return ms;
  };
  double off = 1e300, on = 1e300, simulated = 0;
  std::uint64_t checks = 0;
  for (int r = 0; r < reps; ++r) {
    off = std::min(off, runOnce(rs::runtime::CollisionMode::Off, nullptr, nullptr));
    on = std::min(on, runOnce(rs::runtime::CollisionMode::Error, &checks, &simulated));
  }
  std::printf("swept check, rhino-scara on scara-pick, 150 moves over the whole range (%.1f s simulated)\n", simulated);
  std::printf("  --collisions=off    %8.2f ms\n", off);
  std::printf("  --collisions=error  %8.2f ms: %llu poses checked, %.2f us per pose, %.1f us per move\n", on,
              static_cast<unsigned long long>(checks), (on - off) * 1e3 / static_cast<double>(checks),
              (on - off) * 1e3 / 150);
  return 0;
}
