// Inverse-kinematics benchmark (issue 14): ns per call of
// InverseKinematics::solve (all closed-form solutions of one pose, each
// orientation-checked where the family needs it) and of solveConfig (only
// the configuration wanted: each pose asks for the configuration of one of
// its solutions, in turn) on every arm of stdlib/robots, over 1024 reachable poses made up front (random joint
// values within the motors' ranges → forward kinematics; fixed seed).
// With Orocos KDL: its ChainIkSolverPos_LMA (numeric, one solution) on the
// same poses as the peer, and KDL's own forward kinematics of our solutions
// as an independent check (the largest difference is printed).
// Run by `make bench`; figures go to docs/performance.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include "bench/bench_args.h"
#include "compiler/description/library.h"
#include "model/kinematics/angles.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/ik.h"
#include "model/kinematics/joint_values.h"

#ifdef ROBOTSIM_WITH_KDL
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#endif

namespace {

namespace kin = rs::kinematics;
using Clock = std::chrono::steady_clock;

struct Sample {
  kin::ToolTarget target;
  std::vector<double> q;  // the joint values it came from
  std::uint8_t config = 0;  // one of its solutions' configurations, for solveConfig
};

std::vector<Sample> samples(const rs::workcell::Robot& robot, const kin::InverseKinematics& ik) {
  const kin::ChainModel& chain = *robot.chain;
  kin::ChainData data(chain);
  std::mt19937_64 rng(14);
  const auto n = static_cast<std::size_t>(chain.size());
  std::vector<double> enc(static_cast<std::size_t>(chain.encoderCount())), q(n), home(n);
  for (std::size_t i = 0; i < n; ++i) home[i] = chain.joints()[i].home;
  std::vector<Sample> out;
  while (out.size() < 1024) {
    for (std::size_t i = 0; i < n; ++i)
      enc[static_cast<std::size_t>(chain.joints()[i].encoder)] =
          std::uniform_real_distribution<double>(robot.joints[i].min, robot.joints[i].max)(rng);
    kin::jointValuesFromEncoders(chain, std::span<const double>(enc), q);
    kin::forwardKinematics(chain, data, q);
    const Eigen::Isometry3d F = data.F_0_i.back();
    Sample s{{F.translation(), F.linear(), true, true}, q};
    const kin::IkSolutions all = ik.solve(s.target, home);
    if (!all.ok()) continue;  // near-singular poses left out
    s.config = all.solutions[out.size() % static_cast<std::size_t>(all.count)].config;
    out.push_back(s);
  }
  return out;
}

#ifdef ROBOTSIM_WITH_KDL
KDL::Chain kdlChain(const kin::ChainModel& m) {
  KDL::Chain c;
  for (const kin::Joint& j : m.joints()) {
    const double a = j.dh.a, alpha = j.dh.alpha * kin::kDegToRad;
    if (j.type() == kin::JointType::Revolute)
      c.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::RotZ), KDL::Frame::DH(a, alpha, j.dh.d, 0.0)));
    else
      c.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::TransZ), KDL::Frame::DH(a, alpha, 0.0, j.dh.theta * kin::kDegToRad)));
  }
  return c;
}

// KDL's joint array for our q (degrees → radians for revolute joints).
KDL::JntArray kdlQ(const kin::ChainModel& m, const double* q) {
  KDL::JntArray k(static_cast<unsigned>(m.size()));
  for (int i = 0; i < m.size(); ++i)
    k(static_cast<unsigned>(i)) = m.joint(i + 1).type() == kin::JointType::Revolute ? q[i] * kin::kDegToRad : q[i];
  return k;
}

KDL::Frame kdlFrame(const kin::ToolTarget& t) {
  KDL::Rotation R(t.rotation(0, 0), t.rotation(0, 1), t.rotation(0, 2), t.rotation(1, 0), t.rotation(1, 1),
                  t.rotation(1, 2), t.rotation(2, 0), t.rotation(2, 1), t.rotation(2, 2));
  return KDL::Frame(R, KDL::Vector(t.position.x(), t.position.y(), t.position.z()));
}
#endif

}  // namespace

constexpr rs::bench::CountArgument kCounts[] = {{"CALLS", "calls per run, per arm", 1'000'000, 1'000},
                                                {"REPS", "runs (the best is printed)", 5, 1}};

int main(int argc, char** argv) {
  const rs::bench::BenchArguments args = rs::bench::parseBenchArguments(
      argc, argv, "ik_bench", "Inverse kinematics of every library arm, ns per call (docs/performance.md).", kCounts);
  if (args.exitCode) return *args.exitCode;
  const long calls = args[0];
  const int reps = static_cast<int>(args[1]);
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(ROBOTSIM_SOURCE_DIR) / "stdlib/robots"))
    if (e.path().extension() == ".rsd") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::printf("inverse kinematics, all solutions of a pose per call, %ld calls per run, best of %d\n", calls, reps);
  bool met = true, metOne = true;
  for (const auto& file : files) {
    rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
    const auto robot = lib.robot(file.string());
    if (!robot || !robot->chain) continue;
    const kin::ChainModel& chain = *robot->chain;
    const kin::InverseKinematics ik(chain);
    const std::vector<Sample> poses = samples(*robot, ik);
    std::vector<double> home(static_cast<std::size_t>(chain.size()));
    for (std::size_t i = 0; i < home.size(); ++i) home[i] = chain.joints()[i].home;
    double best = 1e300, checksum = 0;
    int solutions = 0;
    for (int r = 0; r < reps; ++r) {
      const auto start = Clock::now();
      for (long i = 0; i < calls; ++i) {
        const kin::IkSolutions s = ik.solve(poses[static_cast<std::size_t>(i & 1023)].target, home);
        checksum += s.solutions[0].q[0];
        solutions += s.count;
      }
      best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - start).count() / double(calls));
    }
    const bool closed = ik.family() != kin::IkFamily::Numeric;
    met = met && (!closed || best <= 1000.0);
    std::printf("  %-14s %-14s %7.1f ns per call, %.2f solutions per pose (checksum %.6g)\n", robot->name.c_str(),
                std::string(kin::familyName(ik.family())).c_str(), best,
                double(solutions) / double(calls) / reps, checksum);
    // One configuration per call: the same poses, each asking for one of
    // its own solutions' configurations (so every call succeeds).
    double bestOne = 1e300, checksumOne = 0;
    long found = 0;
    for (int r = 0; r < reps; ++r) {
      const auto start = Clock::now();
      for (long i = 0; i < calls; ++i) {
        const Sample& p = poses[static_cast<std::size_t>(i & 1023)];
        const kin::IkSolutions s = ik.solveConfig(p.target, home, p.config);
        checksumOne += s.solutions[0].q[0];
        found += s.count;
      }
      bestOne = std::min(bestOne, std::chrono::duration<double, std::nano>(Clock::now() - start).count() / double(calls));
    }
    metOne = metOne && (!closed || bestOne <= 1000.0);
    std::printf("  %-14s %-14s %7.1f ns per call of one configuration, %.3f solutions per call (checksum %.6g)\n", "",
                "", bestOne, double(found) / double(calls) / reps, checksumOne);
#ifdef ROBOTSIM_WITH_KDL
    const KDL::Chain kc = kdlChain(chain);
    KDL::ChainFkSolverPos_recursive fk(kc);
    // Independent check: KDL's forward kinematics of every solution we give.
    double worst = 0;
    for (const Sample& s : poses) {
      const kin::IkSolutions sol = ik.solve(s.target, home);
      for (const kin::IkSolution& x : sol.view()) {
        KDL::Frame F;
        fk.JntToCart(kdlQ(chain, x.q.data()), F);
        const KDL::Frame G = kdlFrame(s.target);
        worst = std::max(worst, (F.p - G.p).Norm());
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) worst = std::max(worst, std::abs(F.M(a, b) - G.M(a, b)));
      }
    }
    // The peer: KDL's Levenberg-Marquardt solver from home, one solution per pose.
    Eigen::Matrix<double, 6, 1> weights;
    weights << 1, 1, 1, 1, 1, 1;
    KDL::ChainIkSolverPos_LMA lma(kc, weights);
    const KDL::JntArray start = kdlQ(chain, home.data());
    KDL::JntArray out(kc.getNrOfJoints());
    const long kdlCalls = std::max(1L, calls / 100);
    double kdlBest = 1e300;
    int converged = 0;
    for (int r = 0; r < reps; ++r) {
      converged = 0;
      const auto t0 = Clock::now();
      for (long i = 0; i < kdlCalls; ++i)
        converged += lma.CartToJnt(start, kdlFrame(poses[static_cast<std::size_t>(i & 1023)].target), out) >= 0;
      kdlBest = std::min(kdlBest, std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / double(kdlCalls));
    }
    std::printf("  %-14s KDL check: largest difference %.2g; KDL LMA %9.1f ns per call (%.0f x), converged %d of %ld\n",
                "", worst, kdlBest, kdlBest / best, converged, kdlCalls);
#endif
  }
  std::printf("  target <= 1000 ns per closed-form call: all solutions %s, one configuration %s\n",
              met ? "met" : "missed", metOne ? "met" : "missed");
  return 0;
}
