// Property test of inverse kinematics on every robot of the library
// (stdlib/robots/*.rsd, listed from the directory, so a robot added there is
// covered without touching this file): random joint values within the
// motors' ranges → forward kinematics → the pose → inverse kinematics →
// forward kinematics of every solution equals the pose within 1e-6. Poses
// the solver refuses as near-singular are counted and must stay rare; any
// other refusal fails. Then points beyond the arm's size are always refused.
//
// Fixed seed. ROBOTSIM_IK_SAMPLES sets the poses per arm (default 10,000;
// 1,000 in a sanitizer build, where each call is ~20 times slower).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <random>
#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "model/kinematics/angles.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/ik.h"
#include "model/kinematics/joint_values.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

using rs::kinematics::ChainData;
using rs::kinematics::ChainModel;
using rs::kinematics::InverseKinematics;
using rs::kinematics::ToolTarget;

#if defined(__SANITIZE_ADDRESS__)
constexpr int kDefaultSamples = 1000;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kDefaultSamples = 1000;
#else
constexpr int kDefaultSamples = 10000;
#endif
#else
constexpr int kDefaultSamples = 10000;
#endif

int samples() {
  if (const char* s = std::getenv("ROBOTSIM_IK_SAMPLES")) return std::max(1, std::atoi(s));
  return kDefaultSamples;
}

using kintest::libraryRobots;

rs::workcell::Robot load(const std::filesystem::path& file) {
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  auto robot = lib.robot(file.string());
  REQUIRE(robot);
  REQUIRE(robot->chain);
  return *robot;
}

// The tool frame in frame 0 for joint values q.
Eigen::Isometry3d fk(const ChainModel& chain, ChainData& data, const std::vector<double>& q) {
  REQUIRE(rs::kinematics::forwardKinematics(chain, data, q));
  return data.F_0_i.back();
}

}  // namespace

TEST_CASE("inverse kinematics of every library arm meets the pose it was given", "[kinematics][ik][slow]") {
  const int count = samples();
  const auto files = libraryRobots();
  REQUIRE(files.size() >= 6);
  for (const auto& file : files) {
    const rs::workcell::Robot robot = load(file);
    const ChainModel& chain = *robot.chain;
    const InverseKinematics ik(chain);
    INFO(robot.name << " (" << rs::kinematics::familyName(ik.family()) << ")");
    // Every library arm has a closed form.
    CHECK(ik.family() != rs::kinematics::IkFamily::Numeric);
    ChainData data(chain);
    const auto n = static_cast<std::size_t>(chain.size());
    std::mt19937_64 rng(20261124);
    std::vector<double> encoders(static_cast<std::size_t>(chain.encoderCount()), 0.0), q(n), home(n);
    for (std::size_t i = 0; i < n; ++i) home[i] = chain.joints()[i].home;
    int singular = 0;
    double worst = 0;
    for (int k = 0; k < count; ++k) {
      for (std::size_t i = 0; i < n; ++i) {
        const auto& spec = robot.joints[i];
        encoders[static_cast<std::size_t>(chain.joints()[i].encoder)] =
            std::uniform_real_distribution<double>(spec.min, spec.max)(rng);
      }
      REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, std::span<const double>(encoders), q));
      const Eigen::Isometry3d pose = fk(chain, data, q);
      ToolTarget target{pose.translation(), pose.linear(), true, true};
      const auto result = ik.solve(target, home);
      if (!result.ok()) {
        INFO("sample " << k << ": " << result.error.message);
        REQUIRE(result.error.kind == rs::kinematics::IkErrorKind::Singular);
        ++singular;
        continue;
      }
      for (const auto& s : result.view()) {
        const std::vector<double> qs(s.q.begin(), s.q.begin() + static_cast<long>(n));
        const double diff = (fk(chain, data, qs).matrix() - pose.matrix()).cwiseAbs().maxCoeff();
        worst = std::max(worst, diff);
        if (diff > 1e-6) {
          INFO("sample " << k << " config " << int(s.config));
          REQUIRE(diff <= 1e-6);
        }
      }
    }
    INFO("worst difference " << worst << ", " << singular << " near-singular of " << count);
    CHECK(singular * 20 < count);  // under 5 %
  }
}

TEST_CASE("inverse kinematics refuses every point beyond an arm's size", "[kinematics][ik]") {
  for (const auto& file : libraryRobots()) {
    const rs::workcell::Robot robot = load(file);
    const ChainModel& chain = *robot.chain;
    const InverseKinematics ik(chain);
    INFO(robot.name);
    // No point farther from the base than every |a| and |d| together (and
    // the prismatic joints' whole ranges) can be reached.
    double size = 0;
    for (std::size_t i = 0; i < robot.joints.size(); ++i) {
      const auto& j = chain.joints()[i];
      size += std::abs(j.dh.a) + std::abs(j.dh.d);
      if (j.type() == rs::kinematics::JointType::Prismatic)
        size += std::abs(j.precision) * std::max(std::abs(robot.joints[i].min), std::abs(robot.joints[i].max));
    }
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss;
    std::vector<double> home(static_cast<std::size_t>(chain.size()));
    for (std::size_t i = 0; i < home.size(); ++i) home[i] = chain.joints()[i].home;
    for (int k = 0; k < 1000; ++k) {
      Eigen::Vector3d dir(gauss(rng), gauss(rng), gauss(rng));
      dir.normalize();
      const double r = size * (1.01 + std::uniform_real_distribution<double>(0, 3)(rng));
      ToolTarget target{r * dir, Eigen::Matrix3d::Identity(), false, false};
      const auto result = ik.solve(target, home);
      if (result.ok()) {
        // A prismatic axis may reach the point only beyond its range:
        // every solution then lies outside the motors' ranges.
        for (const auto& s : result.view()) {
          bool outside = false;
          for (std::size_t i = 0; i < home.size(); ++i) {
            const auto& j = chain.joints()[i];
            const double e = (s.q[i] - j.home) / j.precision;
            if (j.type() == rs::kinematics::JointType::Prismatic &&
                (e < robot.joints[i].min - 1e-9 || e > robot.joints[i].max + 1e-9))
              outside = true;
          }
          INFO("point " << k << " at " << r);
          REQUIRE(outside);
        }
      }
    }
  }
}
