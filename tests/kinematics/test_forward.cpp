// Forward kinematics against hand calculations: a planar arm's closed form,
// a cylindrical arm with two prismatic joints, encoders, coupling, and the
// MATRIX transforms.
#include <array>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "compiler/description/library.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using kintest::frameAt;
using rs::kinematics::ChainData;
using rs::kinematics::ChainModel;
using rs::kinematics::forwardKinematics;
using rs::kinematics::JointDrive;
using rs::kinematics::JointType;
using rs::kinematics::jointValuesFromEncoders;

using kintest::P;
using kintest::R;

double rad(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Two links in the xy-plane, l1 = 300 and l2 = 200, stretched along +x at home.
ChainModel planarArm(std::vector<JointDrive> drives = {}) {
  return kintest::modelFromFrames({frameAt({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), frameAt({300, 0, 0}, {1, 0, 0}, {0, 0, 1}),
                                   frameAt({500, 0, 0}, {1, 0, 0}, {0, 0, 1})},
                                  {R, R}, std::move(drives));
}

}  // namespace

TEST_CASE("a two-link planar arm follows the closed form", "[kinematics]") {
  const ChainModel arm = planarArm();
  ChainData data(arm);
  for (const auto& [t1, t2] :
       std::vector<std::array<double, 2>>{{0, 0}, {30, 45}, {-120, 170}, {90, -90}, {180, 180}}) {
    const std::array<double, 2> q{t1, t2};
    REQUIRE(forwardKinematics(arm, data, q));
    const Isometry3d tool = rs::kinematics::toolPose(arm, data);
    const double x = 300 * std::cos(rad(t1)) + 200 * std::cos(rad(t1 + t2));
    const double y = 300 * std::sin(rad(t1)) + 200 * std::sin(rad(t1 + t2));
    INFO("θ1 = " << t1 << ", θ2 = " << t2);
    CHECK((tool.translation() - Vector3d(x, y, 0)).norm() < 1e-9);
    CHECK((tool.linear().col(0) - Vector3d(std::cos(rad(t1 + t2)), std::sin(rad(t1 + t2)), 0)).norm() < 1e-12);
    CHECK((tool.linear().col(2) - Vector3d(0, 0, 1)).norm() < 1e-12);
    // The elbow is frame 1.
    CHECK((data.F_0_i[1].translation() - Vector3d(300 * std::cos(rad(t1)), 300 * std::sin(rad(t1)), 0)).norm() < 1e-9);
  }
}

TEST_CASE("a cylindrical arm with two prismatic joints, by hand", "[kinematics]") {
  // Joint 1 turns about the vertical z0; joint 2 slides up along z1
  // (vertical); joint 3 slides out along z2 = +x (radial). Home frames:
  //   F0 (0,0,0)     x +x z +z
  //   F1 (0,0,300)   x +x z +z   θ1 = 0,  α1 = 0,  a = 0, d1 = 300
  //   F2 (0,0,500)   x +y z +x   θ2 = 90, α2 = 90 (z1 → z2 about +y), d2 = 200 (home)
  //   F3 (400,0,500) x +y z +x   θ3 = 0,  α3 = 0, d3 = 400 (home)
  const ChainModel arm = kintest::modelFromFrames(
      {frameAt({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), frameAt({0, 0, 300}, {1, 0, 0}, {0, 0, 1}),
       frameAt({0, 0, 500}, {0, 1, 0}, {1, 0, 0}), frameAt({400, 0, 500}, {0, 1, 0}, {1, 0, 0})},
      {R, P, P}, {{0.5, -1, false}, {0.1, -1, false}, {0.1, -1, false}});
  const auto table = arm.table();
  CHECK(table[1].type == P);
  CHECK(table[1].theta == Approx(90).margin(1e-12));
  CHECK(table[1].alpha == Approx(90).margin(1e-12));
  CHECK(table[1].home() == Approx(200).margin(1e-12));
  CHECK(table[2].home() == Approx(400).margin(1e-12));

  // Encoders (180, 500, -1000): θ1 = 0 + 0.5·180 = 90, d2 = 200 + 0.1·500 = 250,
  // d3 = 400 − 0.1·1000 = 300. The arm now points along +y, 300 out, at
  // height 300 + 250 = 550; z3 = +y and x3 = Rotz(90)(+y) = −x.
  const std::array<std::int32_t, 3> encoders{180, 500, -1000};
  std::array<double, 3> q{};
  REQUIRE(jointValuesFromEncoders(arm, encoders, q));
  CHECK(q == std::array<double, 3>{90, 250, 300});
  ChainData data(arm);
  REQUIRE(forwardKinematics(arm, data, q));
  const Isometry3d tool = rs::kinematics::toolPose(arm, data);
  CHECK((tool.translation() - Vector3d(0, 300, 550)).norm() < 1e-9);
  CHECK((tool.linear().col(2) - Vector3d(0, 1, 0)).norm() < 1e-12);
  CHECK((tool.linear().col(0) - Vector3d(-1, 0, 0)).norm() < 1e-12);
}

TEST_CASE("coupling: joint n+1 cancels joint n's motion, by hand", "[kinematics]") {
  // The planar arm with link 2 pointing up at home (θ2 home = 90), coupling
  // ON for joint 1, precision 0.5 degrees per count.
  const ChainModel arm =
      kintest::modelFromFrames({frameAt({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), frameAt({100, 0, 0}, {1, 0, 0}, {0, 0, 1}),
                                frameAt({100, 50, 0}, {0, 1, 0}, {0, 0, 1})},
                               {R, R}, {{0.5, -1, true}, {0.5, -1, false}});
  REQUIRE(arm.joint(2).home == Approx(90).margin(1e-12));
  // Encoders (60, 20): θ1 = 0 + 30 = 30; θ2 = 90 + 10 − (30 − 0) = 70, so
  // link 2 points at θ1 + θ2 = 100 degrees: its own 10 beyond home, as if
  // joint 1 had not moved it.
  const std::array<double, 2> encoders{60, 20};
  std::array<double, 2> q{};
  REQUIRE(jointValuesFromEncoders(arm, encoders, q));
  CHECK(q[0] == Approx(30).margin(1e-12));
  CHECK(q[1] == Approx(70).margin(1e-12));
  ChainData data(arm);
  REQUIRE(forwardKinematics(arm, data, q));
  const Vector3d expected(100 * std::cos(rad(30)) + 50 * std::cos(rad(100)),
                          100 * std::sin(rad(30)) + 50 * std::sin(rad(100)), 0);
  CHECK((rs::kinematics::toolPose(arm, data).translation() - expected).norm() < 1e-9);
}

TEST_CASE("coupling cascades in joint order on coupled values", "[kinematics]") {
  // Three parallel revolute joints, homes 0, 0, 0; coupling ON for 1 and 2.
  const ChainModel arm =
      kintest::modelFromFrames({frameAt({0, 0, 0}, {1, 0, 0}, {0, 0, 1}), frameAt({100, 0, 0}, {1, 0, 0}, {0, 0, 1}),
                                frameAt({200, 0, 0}, {1, 0, 0}, {0, 0, 1}), frameAt({300, 0, 0}, {1, 0, 0}, {0, 0, 1})},
                               {R, R, R}, {{1, -1, true}, {1, -1, true}, {1, -1, false}});
  // Encoders (10, 20, 40): q1 = 10; q2 = 20 − 10 = 10; q3 = 40 − 10 = 30.
  const std::array<double, 3> encoders{10, 20, 40};
  std::array<double, 3> q{};
  REQUIRE(jointValuesFromEncoders(arm, encoders, q));
  CHECK(q == std::array<double, 3>{10, 10, 30});
}

TEST_CASE("encoders map to joints through the model", "[kinematics]") {
  // Joint 1 reads motor 2, joint 2 reads motor 0 (motor 1 is someone else's).
  const ChainModel arm = planarArm({{2.0, 2, false}, {-1.0, 0, false}});
  CHECK(arm.encoderCount() == 3);
  std::array<double, 2> q{};
  const std::array<std::int32_t, 4> encoders{5, 999, 7, 999};  // longer is fine
  REQUIRE(jointValuesFromEncoders(arm, encoders, q));
  CHECK(q == std::array<double, 2>{14, -5});
  // Too few encoders or a wrong q size: refused, q untouched.
  const std::array<std::int32_t, 2> tooFew{1, 2};
  CHECK_FALSE(jointValuesFromEncoders(arm, tooFew, q));
  std::array<double, 3> wrongSize{};
  CHECK_FALSE(jointValuesFromEncoders(arm, encoders, wrongSize));
  CHECK(q == std::array<double, 2>{14, -5});
}

TEST_CASE("transform(i, j) is T_j^i", "[kinematics]") {
  const ChainModel arm = planarArm();
  ChainData data(arm);
  const std::array<double, 2> q{30, 45};
  REQUIRE(forwardKinematics(arm, data, q));
  using rs::kinematics::transform;
  CHECK(kintest::maxDiff(*transform(arm, data, 1, 1), Isometry3d::Identity()) == 0.0);
  CHECK(kintest::maxDiff(*transform(arm, data, 0, 1), data.A[1]) == 0.0);
  CHECK(kintest::maxDiff(*transform(arm, data, 0, 2), data.F_0_i[2]) < 1e-12);
  CHECK(kintest::maxDiff(*transform(arm, data, 2, 0), data.F_0_i[2].inverse()) < 1e-12);
  // T_2^1 maps frame 2's origin to (200, 0, 0) in frame 1... rotated by θ2.
  CHECK((*transform(arm, data, 1, 2) * Vector3d::Zero() - Vector3d(200 * std::cos(rad(45)), 200 * std::sin(rad(45)), 0))
            .norm() < 1e-9);
  CHECK_FALSE(transform(arm, data, 0, 3));
  CHECK_FALSE(transform(arm, data, -1, 1));
  // A wrong number of joint values is refused.
  const std::array<double, 3> three{1, 2, 3};
  CHECK_FALSE(forwardKinematics(arm, data, three));
}

TEST_CASE("a placed chain moves its tool with the base", "[kinematics]") {
  Isometry3d place = Isometry3d::Identity();
  place.translate(Vector3d(1000, 0, 50)).rotate(Eigen::AngleAxisd(rad(90), Vector3d::UnitZ()));
  const ChainModel arm = planarArm().placedAt(place);
  const ChainData data(arm);  // at home: the tool at (500, 0, 0) in the base
  CHECK((rs::kinematics::toolPose(arm, data).translation() - Vector3d(1000, 500, 50)).norm() < 1e-9);
}

TEST_CASE("positionWithJoint is forward kinematics of the changed joint, to the bit, on every library arm",
          "[kinematics][straight]") {
  // The straight-line planner asks it of each joint at every knot instead
  // of a whole forward pass (model/workcell/line_path.cpp): its knots stay
  // the same only if the answer is the very same double.
  const auto files = kintest::libraryRobots();
  REQUIRE(files.size() >= 6);
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> angle(-180.0, 180.0), length(-500.0, 500.0);
  std::size_t compared = 0;
  for (const auto& file : files) {
    rs::compiler::Library library(rs::compiler::librarySearchPath({}));
    const std::optional<rs::workcell::Robot> robot = library.robot(file.string());
    REQUIRE(robot);
    REQUIRE(robot->chain);
    const ChainModel& chain = *robot->chain;
    INFO(robot->name);
    const auto n = static_cast<std::size_t>(chain.size());
    ChainData before(chain), whole(chain);
    for (int trial = 0; trial < 50; ++trial) {
      std::vector<double> q(n);
      for (std::size_t i = 0; i < n; ++i)
        q[i] = chain.joints()[i].type() == JointType::Revolute ? angle(rng) : length(rng);
      REQUIRE(forwardKinematics(chain, before, q));
      for (std::size_t i = 0; i < n; ++i) {
        std::vector<double> changed = q;
        changed[i] = chain.joints()[i].type() == JointType::Revolute ? angle(rng) : length(rng);
        REQUIRE(forwardKinematics(chain, whole, changed));
        const Vector3d expected = whole.F_0_i.back().translation();
        const Vector3d got = rs::kinematics::positionWithJoint(chain, before, i, changed[i]);
        for (int k = 0; k < 3; ++k) REQUIRE(std::bit_cast<std::uint64_t>(got[k]) == std::bit_cast<std::uint64_t>(expected[k]));
        ++compared;
      }
    }
  }
  CHECK(compared >= 6 * 50 * 4);
}
