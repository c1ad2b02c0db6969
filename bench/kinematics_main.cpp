// Forward-kinematics benchmark (issue 3, "Tests and numbers"): ns per call
// of forwardKinematics on a 6-axis arm (the PUMA 560's D-H table), with a
// preallocated ChainData and fixed-size Eigen types: nothing allocates in
// the loop. Run by `make bench`; figures go to docs/performance.md.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "bench/bench_args.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/chain_model.h"
#include "model/kinematics/forward_kinematics.h"

namespace {

namespace kin = rs::kinematics;

// PUMA 560 in standard D-H (Craig's table shifted one row; stdlib/robots/puma560.rsd).
kin::ChainModel puma560() {
  const kin::JointType R = kin::JointType::Revolute;
  const std::vector<kin::DhRow> table{{R, 0, -90, 0, 0},     {R, 0, 0, 431.8, 0}, {R, 0, -90, 20.32, 149.09},
                                      {R, 0, 90, 0, 433.07}, {R, 0, -90, 0, 0},   {R, 0, 0, 0, 56.25}};
  const std::vector<kin::JointDrive> drives(table.size());
  return *kin::ChainModel::fromDh(Eigen::Isometry3d::Identity(), table, drives).value;
}

}  // namespace

constexpr rs::bench::CountArgument kCounts[] = {{"CALLS", "calls per run", 5'000'000, 1'000},
                                                {"REPS", "runs (the best is printed)", 5, 1}};

int main(int argc, char** argv) {
  const rs::bench::BenchArguments args = rs::bench::parseBenchArguments(
      argc, argv, "kinematics_bench", "Forward kinematics of a 6-axis arm, ns per call (docs/performance.md).", kCounts);
  if (args.exitCode) return *args.exitCode;
  const long calls = args[0];
  const int reps = static_cast<int>(args[1]);
  const kin::ChainModel model = puma560();
  kin::ChainData data(model);
  // 1024 joint vectors made up front (fixed seed), so the loop only computes.
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> angle(-170.0, 170.0);
  std::vector<double> q(1024 * 6);
  for (double& v : q) v = angle(rng);

  std::printf("forward kinematics, 6-axis arm (PUMA 560 D-H), %ld calls per run, best of %d\n", calls, reps);
  double best = 1e300, checksum = 0;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < calls; ++i) {
      const std::span<const double> qi(q.data() + (i & 1023) * 6, 6);
      kin::forwardKinematics(model, data, qi);
      checksum += data.F_0_i[6](0, 3);  // keeps the work observable
    }
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, ns / static_cast<double>(calls));
  }
  std::printf("  %.1f ns per call (checksum %.6g)\n", best, checksum);
  std::printf("  target <= 100 ns per call: %s\n", best <= 100.0 ? "met" : "missed");
  return 0;
}
