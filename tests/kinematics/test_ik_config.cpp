// InverseKinematics::solveConfig (one configuration) against solve (every
// configuration) on every arm of the library (stdlib/robots, listed from
// the directory): for random reachable poses, each solution solve gives is
// exactly (bit for bit) what solveConfig gives for its configuration, and
// each configuration solve does not list is refused by solveConfig too.
// Targets alternate between a whole orientation and the approach alone
// (the families that keep what was not written from the reference, and
// those that filter by forward kinematics, are both walked).
//
// Fixed seed. ROBOTSIM_IK_CONFIG_SAMPLES sets the poses per arm (default 500).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <vector>

#include "compiler/description/library.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/ik.h"
#include "model/kinematics/joint_values.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

namespace kin = rs::kinematics;

int configSamples() {
  if (const char* s = std::getenv("ROBOTSIM_IK_CONFIG_SAMPLES")) return std::max(1, std::atoi(s));
  return 500;
}

using kintest::libraryRobots;

bool sameBits(const kin::IkSolution& a, const kin::IkSolution& b) {
  return a.config == b.config && std::memcmp(a.q.data(), b.q.data(), sizeof(a.q)) == 0;
}

}  // namespace

TEST_CASE("one configuration's inverse kinematics is bit for bit that entry of all of them", "[kinematics][ik]") {
  const int count = configSamples();
  const auto files = libraryRobots();
  REQUIRE(files.size() >= 6);
  for (const auto& file : files) {
    rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
    const auto robot = lib.robot(file.string());
    REQUIRE(robot);
    REQUIRE(robot->chain);
    const kin::ChainModel& chain = *robot->chain;
    const kin::InverseKinematics ik(chain);
    INFO(robot->name << " (" << kin::familyName(ik.family()) << ")");
    const std::span<const std::uint8_t> configs = ik.configurations();
    kin::ChainData data(chain);
    const auto n = static_cast<std::size_t>(chain.size());
    std::mt19937_64 rng(1414);
    std::vector<double> encoders(static_cast<std::size_t>(chain.encoderCount()), 0.0), q(n), home(n);
    for (std::size_t i = 0; i < n; ++i) home[i] = chain.joints()[i].home;
    int compared = 0, refused = 0;
    for (int k = 0; k < count; ++k) {
      for (std::size_t i = 0; i < n; ++i)
        encoders[static_cast<std::size_t>(chain.joints()[i].encoder)] =
            std::uniform_real_distribution<double>(robot->joints[i].min, robot->joints[i].max)(rng);
      REQUIRE(kin::jointValuesFromEncoders(chain, std::span<const double>(encoders), q));
      REQUIRE(kin::forwardKinematics(chain, data, q));
      const Eigen::Isometry3d pose = data.F_0_i.back();
      const kin::ToolTarget target{pose.translation(), pose.linear(), true, k % 2 == 0};
      const kin::IkSolutions all = ik.solve(target, home);
      INFO("sample " << k);
      // solve lists its solutions in the order of configurations().
      std::size_t next = 0;
      for (const kin::IkSolution& s : all.view()) {
        const auto at = std::find(configs.begin() + static_cast<long>(next), configs.end(), s.config);
        REQUIRE(at != configs.end());
        next = static_cast<std::size_t>(at - configs.begin()) + 1;
      }
      for (const std::uint8_t c : configs) {
        INFO("configuration " << int(c));
        const kin::IkSolutions one = ik.solveConfig(target, home, c);
        const auto listed = std::find_if(all.view().begin(), all.view().end(),
                                         [c](const kin::IkSolution& s) { return s.config == c; });
        if (listed == all.view().end()) {
          CHECK_FALSE(one.ok());
          CHECK(one.error.kind != kin::IkErrorKind::NoSuchConfiguration);
          CHECK_FALSE(one.error.message.empty());
          ++refused;
          continue;
        }
        REQUIRE(one.count == 1);
        CHECK(sameBits(one.solutions[0], *listed));
        ++compared;
      }
    }
    INFO(compared << " compared, " << refused << " refused");
    CHECK(compared >= count);  // at least one solution a pose on average
  }
}

TEST_CASE("solveConfig refuses a configuration its family does not have", "[kinematics][ik]") {
  for (const auto& file : libraryRobots()) {
    rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
    const auto robot = lib.robot(file.string());
    REQUIRE(robot);
    const kin::InverseKinematics ik(*robot->chain);
    INFO(robot->name);
    const std::span<const std::uint8_t> configs = ik.configurations();
    // The sizes by family (ik_family.h): 1, 2, 4 or 8, every bit pattern distinct.
    const std::size_t expected = ik.family() == kin::IkFamily::Scara          ? 2
                                 : ik.family() == kin::IkFamily::Articulated5 ? 4
                                 : ik.family() == kin::IkFamily::Articulated6 ||
                                         ik.family() == kin::IkFamily::Spherical6
                                     ? 8
                                     : 1;
    CHECK(configs.size() == expected);
    std::vector<double> home(static_cast<std::size_t>(robot->chain->size()));
    for (std::size_t i = 0; i < home.size(); ++i) home[i] = robot->chain->joints()[i].home;
    for (int c = 0; c < 8; ++c) {
      if (std::find(configs.begin(), configs.end(), c) != configs.end()) continue;
      const kin::IkSolutions r = ik.solveConfig(kin::ToolTarget{}, home, static_cast<std::uint8_t>(c));
      CHECK_FALSE(r.ok());
      CHECK(r.error.kind == kin::IkErrorKind::NoSuchConfiguration);
    }
  }
}
