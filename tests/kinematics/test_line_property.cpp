// Property test of straight-line moves (model/workcell/line_path.h) on
// every robot of the library (stdlib/robots/*.rsd, listed from the
// directory): random lines between two poses of the arm, each planned,
// then run knot by knot on the simulated machine (SimMachine::moveLockStep,
// the real timing and whole-count positions), sampled at many moments.
// Every sample's tool centre point, computed here by forward kinematics
// from the sampled encoder counts (not by the planner), lies within the
// documented bound of the line: kLineTolerance (0.1) plus 1.5 times the
// resolution r at that pose (the sum over the arm's motors of how far one
// count moves the tool centre point, also worked out here by forward
// kinematics). The line ends on the point's encoder counts exactly, so its
// end pose is the point's.
//
// Lines the planner refuses (a pose out of reach, out of a motor's range,
// near a singular pose, in another configuration) are not "reachable" and
// are drawn again; the test counts them and needs 10,000 planned lines per
// arm (1,000 in a sanitizer build, where each plan is ~20 times slower;
// ROBOTSIM_LINE_SAMPLES sets it). Fixed seed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "launch/program.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"
#include "model/workcell/line_path.h"
#include "runtime/sim/sim_machine.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kLineDefaultSamples = 1000;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kLineDefaultSamples = 1000;
#else
constexpr int kLineDefaultSamples = 10000;
#endif
#else
constexpr int kLineDefaultSamples = 10000;
#endif

int lineSamples() {
  if (const char* s = std::getenv("ROBOTSIM_LINE_SAMPLES")) return std::max(1, std::atoi(s));
  return kLineDefaultSamples;
}

// The tool centre point (frame 0) for whole encoder counts.
Eigen::Vector3d lineTcp(const rs::kinematics::ChainModel& chain, rs::kinematics::ChainData& data,
                        const std::vector<std::int32_t>& counts) {
  std::vector<double> q(static_cast<std::size_t>(chain.size()));
  REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, counts, q));
  REQUIRE(rs::kinematics::forwardKinematics(chain, data, q));
  return data.F_0_i.back().translation();
}

double lineDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

TEST_CASE("straight lines of every library arm stay within the bound and end on the point",
          "[kinematics][straight][property][slow]") {
  const int want = lineSamples();
  const auto files = kintest::libraryRobots();
  REQUIRE(files.size() >= 6);
  std::mt19937_64 rng(20261127);
  for (const auto& file : files) {
    rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
    auto robot = lib.robot(file.string());
    REQUIRE(robot);
    REQUIRE(robot->chain);
    rs::workcell::Workcell cell;
    cell.name = robot->name;
    cell.robots.push_back({*robot, Eigen::Isometry3d::Identity()});
    const rs::workcell::PlacedRobot& placed = cell.robots.front();
    const std::vector<rs::vm::MotorSpec> motors = rs::launch::cellTarget(cell).motors;
    const rs::kinematics::ChainModel& chain = *placed.robot.chain;
    rs::kinematics::ChainData data(chain);
    const rs::workcell::LinePlanner planner(placed);
    rs::workcell::LinePath path(planner);
    INFO(robot->name);
    REQUIRE(planner.motorCount() == motors.size());
    const std::size_t joints = robot->joints.size();

    // A start anywhere in the inner 90% of every range; the end a random
    // change of every joint of up to 4% of its range (the gripper stays):
    // lines of a few to a few hundred length units, tens of knots each.
    const auto draw = [&](std::vector<std::int32_t>& start, std::vector<std::int32_t>& end) {
      start.assign(motors.size(), 0);
      end.assign(motors.size(), 0);
      for (std::size_t m = 0; m < joints; ++m) {
        const double lo = robot->joints[m].min, hi = robot->joints[m].max, span = hi - lo;
        std::uniform_real_distribution<double> at(lo + 0.05 * span, hi - 0.05 * span), by(-0.04 * span, 0.04 * span);
        start[m] = static_cast<std::int32_t>(std::lround(at(rng)));
        end[m] = static_cast<std::int32_t>(std::clamp(std::lround(start[m] + by(rng)), std::lround(lo), std::lround(hi)));
      }
    };

    int planned = 0, refused = 0, samples = 0;
    double worstExcess = -1e9;  // the largest (distance − bound) seen
    std::vector<std::int32_t> start, end, counts(motors.size());
    while (planned < want && refused < 20 * want) {
      draw(start, end);
      if (planner.planTo(start, end, path)) {
        ++refused;
        continue;
      }
      ++planned;
      REQUIRE(path.size() >= 1);
      const Eigen::Vector3d a = lineTcp(chain, data, start), b = lineTcp(chain, data, end);
      // The end: the point's counts for every arm motor, so the point's pose.
      const auto last = path.knot(path.size() - 1);
      for (std::size_t m = 0; m < joints; ++m) REQUIRE(last[m] == end[m]);
      rs::runtime::SimMachine sim(motors, {});
      REQUIRE(sim.moveTo(start));
      for (std::size_t k = 0; k < path.size(); ++k) {
        const rs::vm::Micros t0 = sim.now();
        REQUIRE(sim.moveLockStep(path.knot(k), path.lead(k)));
        const rs::vm::Micros t1 = sim.now();
        // Two moments of each small move, its middle and its end, whole-count positions as the machine has them.
        for (int i = 1; i <= 2; ++i) {
          const rs::vm::Micros t = t0 + (t1 - t0) * i / 2;
          for (std::size_t m = 0; m < motors.size(); ++m) counts[m] = sim.positionAt(m, t);
          const Eigen::Vector3d p = lineTcp(chain, data, counts);
          double r = 0;
          for (std::size_t m = 0; m < joints; ++m) {
            ++counts[m];
            r += (lineTcp(chain, data, counts) - p).norm();
            --counts[m];
          }
          const double bound = rs::workcell::kLineTolerance + 1.5 * r;
          const double d = lineDistance(p, a, b);
          worstExcess = std::max(worstExcess, d - bound);
          ++samples;
          if (d > bound) {
            INFO("line " << planned << " knot " << k << " of " << path.size() << " at " << t << " us: " << d
                         << " from the line, bound " << bound);
            REQUIRE(d <= bound);
          }
        }
      }
      const auto now = sim.positions();
      for (std::size_t m = 0; m < joints; ++m) REQUIRE(now[m] == end[m]);
      REQUIRE((lineTcp(chain, data, std::vector<std::int32_t>(now.begin(), now.end())) - b).norm() < 1e-9);
    }
    INFO(planned << " lines planned, " << refused << " refused, " << samples << " samples, worst excess "
                 << worstExcess);
    CHECK(planned == want);
    CHECK(worstExcess <= 0);
  }
}
