// D-H derivation on hand-made frames: the special cases (parallel,
// antiparallel, intersecting, coincident axes, prismatic joints, θ = 180)
// and every error a frame can cause.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/kinematics/dh_derive.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using kintest::frameAt;
using rs::kinematics::deriveDh;
using rs::kinematics::DhRow;
using rs::kinematics::ErrorKind;
using rs::kinematics::JointType;
using rs::kinematics::KinematicsError;

using kintest::P;
using kintest::R;

Isometry3d base() { return frameAt({0, 0, 0}, {1, 0, 0}, {0, 0, 1}); }

// The one row derived from the base frame and `second`.
DhRow onlyRow(const Isometry3d& second, JointType type = R) {
  const std::vector<Isometry3d> frames{base(), second};
  const std::vector<JointType> types{type};
  const auto table = deriveDh(frames, types);
  for (const auto& e : table.errors) INFO(e.message);
  REQUIRE(table.ok());
  return table.value->at(0);
}

void checkRow(const DhRow& row, double theta, double alpha, double a, double d) {
  CHECK(row.theta == Approx(theta).margin(1e-9));
  CHECK(row.alpha == Approx(alpha).margin(1e-9));
  CHECK(row.a == Approx(a).margin(1e-9));
  CHECK(row.d == Approx(d).margin(1e-9));
}

// The errors deriving the table of `frames` (all revolute) gives.
std::vector<KinematicsError> errorsOf(const std::vector<Isometry3d>& frames) {
  const std::vector<JointType> types(frames.size() - 1, R);
  auto table = deriveDh(frames, types);
  CHECK_FALSE(table.ok());
  return table.errors;
}

}  // namespace

TEST_CASE("D-H: parallel z axes, d from where x_i meets z_{i-1}", "[kinematics]") {
  // z1 ∥ z0; x1 runs along global x at height 30, meeting z0 at (0,0,30).
  checkRow(onlyRow(frameAt({100, 0, 30}, {1, 0, 0}, {0, 0, 1})), 0, 0, 100, 30);
  // Same axes, o1 turned 90 degrees about z0: θ = 90, a = 100 along +y.
  checkRow(onlyRow(frameAt({0, 100, 0}, {0, 1, 0}, {0, 0, 1})), 90, 0, 100, 0);
  // Antiparallel z1: α = 180 (never -180).
  checkRow(onlyRow(frameAt({100, 0, 0}, {1, 0, 0}, {0, 0, -1})), 0, 180, 100, 0);
}

TEST_CASE("D-H: intersecting z axes give a = 0", "[kinematics]") {
  // z1 along +x meets z0 at (0,0,200); x1 = +y is perpendicular to both;
  // θ: x0 → x1 about z0 is +90; α: z0 → z1 about x1 (= +y) is +90.
  checkRow(onlyRow(frameAt({0, 0, 200}, {0, 1, 0}, {1, 0, 0})), 90, 90, 0, 200);
  // Same axes, x1 = -y: θ = -90, α = -90.
  checkRow(onlyRow(frameAt({0, 0, 200}, {0, -1, 0}, {1, 0, 0})), -90, -90, 0, 200);
}

TEST_CASE("D-H: coincident z axes give a = 0 and α = 0", "[kinematics]") {
  checkRow(onlyRow(frameAt({0, 0, 300}, {0, -1, 0}, {0, 0, 1})), -90, 0, 0, 300);
  // x1 = -x0: θ is 180 (never -180).
  checkRow(onlyRow(frameAt({0, 0, -40}, {-1, 0, 0}, {0, 0, 1})), 180, 0, 0, -40);
}

TEST_CASE("D-H: an arbitrary twist", "[kinematics]") {
  // z1 = Rotx(30) z0 = (0, -sin 30, cos 30), offset 50 along x1 = x0.
  const double s = std::sin(30 * std::numbers::pi / 180), c = std::cos(30 * std::numbers::pi / 180);
  checkRow(onlyRow(frameAt({50, 0, 10}, {1, 0, 0}, {0, -s, c})), 0, 30, 50, 10);
}

TEST_CASE("D-H: a prismatic joint's home value is d", "[kinematics]") {
  const DhRow row = onlyRow(frameAt({0, 0, 250}, {0, 1, 0}, {1, 0, 0}), P);
  CHECK(row.type == P);
  checkRow(row, 90, 90, 0, 250);
  CHECK(row.home() == row.d);
}

TEST_CASE("D-H error: x_i not perpendicular to z_{i-1}", "[kinematics]") {
  // x1 = (1,0,1)/√2 makes 45 degrees with z0; z1 = +y is a valid frame axis.
  const auto errors = errorsOf({base(), frameAt({0, 0, 100}, {1, 0, 1}, {0, 1, 0})});
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == KinematicsError{ErrorKind::XNotPerpendicularToPreviousZ, 1,
                                     "x1 is not perpendicular to z0 (the angle between them is 45 degrees), as the "
                                     "D-H convention requires"});
}

TEST_CASE("D-H error: x_i does not meet z_{i-1}", "[kinematics]") {
  // x1 runs along global x through (0, 50, 100): it passes 50 from z0.
  const auto errors = errorsOf({base(), frameAt({0, 50, 100}, {1, 0, 0}, {0, 0, 1})});
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] == KinematicsError{ErrorKind::XMissesPreviousZ, 1,
                                     "x1 does not meet z0 (they pass 50 apart), as the D-H convention requires"});
}

TEST_CASE("D-H errors: every bad frame is reported, with its number", "[kinematics]") {
  const auto good1 = frameAt({0, 0, 100}, {1, 0, 0}, {0, 0, 1});
  const auto bad2 = frameAt({0, -7, 200}, {1, 0, 0}, {0, 0, 1});     // passes 7 from z1
  const auto good3 = frameAt({300, -7, 200}, {1, 0, 0}, {0, 0, 1});  // fine relative to frame 2
  const auto bad4 = frameAt({300, -7, 400}, {0, 0, 1}, {1, 0, 0});   // x4 ∥ z3
  const auto errors = errorsOf({base(), good1, bad2, good3, bad4});
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].index == 2);
  CHECK(errors[0].message == "x2 does not meet z1 (they pass 7 apart), as the D-H convention requires");
  CHECK(errors[1].index == 4);
  CHECK(errors[1].message ==
        "x4 is not perpendicular to z3 (the angle between them is 0 degrees), as the D-H convention requires");
}

TEST_CASE("D-H tolerances: rounding passes, a real gap does not", "[kinematics]") {
  CHECK(deriveDh(std::vector<Isometry3d>{base(), frameAt({0, 1e-8, 100}, {1, 0, 0}, {0, 0, 1})},
                 std::vector<JointType>{R})
            .ok());
  rs::kinematics::Tolerances strict;
  strict.distance = 1e-9;
  CHECK_FALSE(deriveDh(std::vector<Isometry3d>{base(), frameAt({0, 1e-8, 100}, {1, 0, 0}, {0, 0, 1})},
                       std::vector<JointType>{R}, strict)
                  .ok());
}

TEST_CASE("D-H error: frames and joints must match", "[kinematics]") {
  const std::vector<Isometry3d> frames{base(), base()};
  const std::vector<JointType> types{R, R};
  const auto table = deriveDh(frames, types);
  REQUIRE(table.errors.size() == 1);
  CHECK(table.errors[0] == KinematicsError{ErrorKind::CountMismatch, -1,
                                           "2 joints need 3 frames (base to end effector), but 2 are given"});
}
