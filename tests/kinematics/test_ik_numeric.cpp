// The numeric method (damped least squares) on a chain no closed form fits:
// a 4-axis arm with 45-degree twists. From a start near the answer it meets
// the pose within 1e-6; it gives the same bits every time; a point beyond
// the arm's size is refused with the distance it got to.
#include <catch2/catch.hpp>
#include <cstring>
#include <random>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/ik.h"

namespace {

namespace kin = rs::kinematics;

kin::ChainModel oddArm() {
  const kin::JointType R = kin::JointType::Revolute;
  const std::vector<kin::DhRow> table{{R, 0, 45, 50, 300}, {R, 0, -45, 250, 20}, {R, 0, 60, 200, 0}, {R, 0, 0, 0, 80}};
  const std::vector<kin::JointDrive> drives(table.size());
  return *kin::ChainModel::fromDh(Eigen::Isometry3d::Identity(), table, drives).value;
}

}  // namespace

TEST_CASE("the numeric method solves a chain no family fits, deterministically", "[kinematics][ik]") {
  const kin::ChainModel chain = oddArm();
  const kin::InverseKinematics ik(chain);
  REQUIRE(ik.family() == kin::IkFamily::Numeric);
  kin::ChainData data(chain);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(-150, 150), nudge(-10, 10);
  int solved = 0;
  for (int k = 0; k < 200; ++k) {
    std::vector<double> q(4), start(4);
    for (std::size_t i = 0; i < 4; ++i) q[i] = angle(rng), start[i] = q[i] + nudge(rng);
    REQUIRE(kin::forwardKinematics(chain, data, q));
    const Eigen::Isometry3d pose = data.F_0_i.back();
    // Position and approach: 5 constraints on 4 joints is too many in general; the
    // approach alone with the position is what this arm can meet (it came from one).
    const kin::ToolTarget target{pose.translation(), pose.linear(), true, false};
    const kin::IkSolutions a = ik.solve(target, start), b = ik.solve(target, start);
    REQUIRE(a.ok() == b.ok());
    if (!a.ok()) continue;
    ++solved;
    CHECK(std::memcmp(a.solutions[0].q.data(), b.solutions[0].q.data(), 4 * sizeof(double)) == 0);
    const std::vector<double> qs(a.solutions[0].q.begin(), a.solutions[0].q.begin() + 4);
    REQUIRE(kin::forwardKinematics(chain, data, qs));
    CHECK((data.F_0_i.back().translation() - pose.translation()).norm() < 1e-6);
    CHECK((data.F_0_i.back().linear().col(2) - pose.linear().col(2)).norm() < 1e-6);
  }
  CHECK(solved >= 190);  // from 10 degrees away it nearly always converges
  // Beyond the arm's size (|a| + |d| = 900): refused, with how near it got.
  const kin::ToolTarget far{Eigen::Vector3d(2000, 0, 0), Eigen::Matrix3d::Identity(), false, false};
  const kin::IkSolutions r = ik.solve(far, std::vector<double>(4, 0.0));
  REQUIRE_FALSE(r.ok());
  CHECK(r.error.kind == kin::IkErrorKind::NotConverged);
  CHECK(r.error.distance > 1000);
}
