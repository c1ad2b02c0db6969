// Link frames from the description's points, and their errors.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "model/kinematics/frame.h"

namespace {

using Eigen::Vector3d;
using rs::kinematics::ErrorKind;
using rs::kinematics::frameFromPoints;
using rs::kinematics::KinematicsError;

}  // namespace

TEST_CASE("a frame from points is normalised and right-handed", "[kinematics]") {
  // x from (10,20,30) towards +y (length 5), z from there towards -x (length 200).
  const auto frame = frameFromPoints({10, 20, 30}, {10, 25, 30}, {-190, 20, 30});
  REQUIRE(frame.errors.empty());
  const Eigen::Matrix3d R = frame.value->linear();
  CHECK((R.col(0) - Vector3d(0, 1, 0)).norm() < 1e-15);
  CHECK((R.col(2) - Vector3d(-1, 0, 0)).norm() < 1e-15);
  CHECK((R.col(1) - Vector3d(0, 0, -1)).norm() < 1e-15);  // y = z × x
  CHECK((frame.value->translation() - Vector3d(10, 20, 30)).norm() == 0.0);
  CHECK(R.determinant() == Approx(1.0).margin(1e-15));
}

TEST_CASE("frame axes that are not perpendicular are an error", "[kinematics]") {
  // x along (1,0,0), z along (1,0,1): 45 degrees apart.
  const auto frame = frameFromPoints({0, 0, 0}, {100, 0, 0}, {100, 0, 100}, {}, 3);
  CHECK_FALSE(frame.ok());
  REQUIRE(frame.errors.size() == 1);
  CHECK(frame.errors[0] == KinematicsError{ErrorKind::AxesNotPerpendicular, 3,
                                           "x axis and z axis are not perpendicular (the angle between them "
                                           "is 45 degrees)"});
}

TEST_CASE("the perpendicularity tolerance is configurable", "[kinematics]") {
  // cos(x, z) = 1e-4 / |(1e-4, 0, 1)| ≈ 1e-4.
  const Vector3d o(0, 0, 0), q(1, 0, 0), r(1e-4, 0, 1);
  CHECK_FALSE(frameFromPoints(o, q, r).ok());
  rs::kinematics::Tolerances loose;
  loose.cosine = 1e-3;
  const auto frame = frameFromPoints(o, q, r, loose);
  REQUIRE(frame.ok());
  // z is made exactly perpendicular to x; x keeps its direction.
  CHECK(std::abs(frame.value->linear().col(0).dot(frame.value->linear().col(2))) < 1e-15);
  CHECK((frame.value->linear().col(0) - Vector3d(1, 0, 0)).norm() == 0.0);
}

TEST_CASE("a degenerate frame axis is an error", "[kinematics]") {
  const auto xZero = frameFromPoints({5, 5, 5}, {5, 5, 5}, {5, 5, 6}, {}, 2);
  REQUIRE(xZero.errors.size() == 1);
  CHECK(xZero.errors[0] == KinematicsError{ErrorKind::DegenerateAxis, 2, "x axis has zero length"});

  const auto both = frameFromPoints({5, 5, 5}, {5, 5, 5}, {5, 5, 5}, {}, 1);
  REQUIRE(both.errors.size() == 2);
  CHECK(both.errors[0].message == "x axis has zero length");
  CHECK(both.errors[1] == KinematicsError{ErrorKind::DegenerateAxis, 1, "z axis has zero length"});
}

TEST_CASE("a frame with a coordinate that is not a number is an error", "[kinematics]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto frame = frameFromPoints({0, 0, 0}, {1, 0, 0}, {0, nan, 1}, {}, 4);
  REQUIRE(frame.errors.size() == 1);
  CHECK(frame.errors[0] ==
        KinematicsError{ErrorKind::NotFinite, 4, "z axis has a coordinate that is not a finite number"});
}

TEST_CASE("a line through two points, and a rotation about it", "[kinematics]") {
  const auto line = rs::kinematics::lineThrough({1, 2, 0}, {1, 2, 7}, "axis r2");
  REQUIRE(line.ok());
  CHECK((line.value->direction - Vector3d(0, 0, 1)).norm() == 0.0);
  // A quarter turn about the vertical line through (1, 2): (2, 2, 5) goes to (1, 3, 5).
  const auto motion = rs::kinematics::rotationAboutLine(*line.value, 90);
  CHECK((motion * Vector3d(2, 2, 5) - Vector3d(1, 3, 5)).norm() < 1e-12);

  const auto bad = rs::kinematics::lineThrough({1, 2, 0}, {1, 2, 0}, "axis r2");
  REQUIRE(bad.errors.size() == 1);
  CHECK(bad.errors[0].message == "axis r2 has zero length");
}
