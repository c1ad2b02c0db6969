// The paper's SCOROBOT: its TABLE (Fig. 6) derived from link frames written
// by hand, and its MATRIX example (Fig. 7).
#include <array>
#include <catch2/catch.hpp>
#include <vector>

#include "model/kinematics/dh_derive.h"
#include "model/kinematics/forward_kinematics.h"
#include "tests/kinematics/kinematics_test_util.h"

namespace {

using Eigen::Vector3d;
using kintest::frameAt;
using rs::kinematics::JointType;

// SCOROBOT at home, frames worked out by hand from Fig. 6 in global
// coordinates (base frame = global frame). Row i applies Rotz(θ) Transz(d)
// Transx(a) Rotx(α) to frame i-1, so with frame i-1's axes X, Y, Z:
//   x_i = cosθ X + sinθ Y,  z_i = sinα sinθ X − sinα cosθ Y + cosα Z,
//   o_i = o_{i-1} + d Z + a x_i.
// F0: o (0,0,0),       x (1,0,0),  z (0,0,1).
// F1: θ=0, d=1220, a=0, α=90:  x1 = X0 = (1,0,0); z1 = −Y0 = (0,−1,0);
//     o1 = (0,0,1220); y1 = z1 × x1 = (0,0,1).
// F2: θ=90, a=777, α=0:  x2 = Y1 = (0,0,1); z2 = z1 = (0,−1,0);
//     o2 = o1 + 777 x2 = (0,0,1997); y2 = z2 × x2 = (−1,0,0).
// F3: θ=−90, a=707, α=0:  x3 = −Y2 = (1,0,0); z3 = (0,−1,0);
//     o3 = o2 + 707 x3 = (707,0,1997); y3 = (0,0,1).
// F4: θ=0, a=50, α=90:  x4 = X3 = (1,0,0); z4 = −Y3 = (0,0,−1);
//     o4 = o3 + 50 x4 = (757,0,1997); y4 = z4 × x4 = (0,−1,0).
// F5 (the gripper's n and a): θ=90, d=600, a=0, α=0:  x5 = Y4 = (0,−1,0);
//     z5 = z4 = (0,0,−1); o5 = o4 + 600 z4 = (757,0,1397).
std::vector<Eigen::Isometry3d> scorobotFrames() {
  return {
      frameAt({0, 0, 0}, {1, 0, 0}, {0, 0, 1}),       frameAt({0, 0, 1220}, {1, 0, 0}, {0, -1, 0}),
      frameAt({0, 0, 1997}, {0, 0, 1}, {0, -1, 0}),   frameAt({707, 0, 1997}, {1, 0, 0}, {0, -1, 0}),
      frameAt({757, 0, 1997}, {1, 0, 0}, {0, 0, -1}), frameAt({757, 0, 1397}, {0, -1, 0}, {0, 0, -1}),
  };
}

const std::vector<JointType> kFiveRevolute(5, JointType::Revolute);

}  // namespace

TEST_CASE("SCOROBOT's derived table is the paper's Fig. 6", "[kinematics]") {
  const auto table = rs::kinematics::deriveDh(scorobotFrames(), kFiveRevolute);
  REQUIRE(table.errors.empty());
  REQUIRE(table.value->size() == 5);
  const std::array<double, 5> alpha{90, 0, 0, 90, 0}, a{0, 777, 707, 50, 0}, d{1220, 0, 0, 0, 600},
      home{0, 90, -90, 0, 90};
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& row = (*table.value)[i];
    INFO("axis " << i + 1);
    CHECK(row.type == JointType::Revolute);
    CHECK(row.alpha == Approx(alpha[i]).margin(1e-9));
    CHECK(row.a == Approx(a[i]).margin(1e-9));
    CHECK(row.d == Approx(d[i]).margin(1e-9));
    CHECK(row.home() == Approx(home[i]).margin(1e-9));
    CHECK(row.theta == row.home());
  }
}

TEST_CASE("SCOROBOT's T_5^2 at the paper's angles is Fig. 7", "[kinematics]") {
  const auto model = kintest::modelFromFrames(scorobotFrames(), kFiveRevolute);
  rs::kinematics::ChainData data(model);
  const std::array<double, 5> theta{76, 72, -90, 34, -49};
  REQUIRE(rs::kinematics::forwardKinematics(model, data, theta));
  const auto T = rs::kinematics::transform(model, data, 2, 5);
  REQUIRE(T);
  Eigen::Matrix4d paper;
  paper << 0.3669, 0.4220, -0.8290, -469.50,  //
      -0.5439, -0.6257, -0.5592, -1084,       //
      -0.7547, 0.6561, 0.0000, 0.0000,        //
      0, 0, 0, 1;
  // The paper prints its rotation to 4 decimals, so 1e-4 bounds the rounding.
  CHECK((T->linear() - paper.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff() < 1e-4);
  // The exact product's translation is (-469.4629, -1083.9676, 0); the paper
  // shows it with fewer digits (-469.50, -1084), hence the looser 0.05.
  CHECK((T->translation() - paper.topRightCorner<3, 1>()).cwiseAbs().maxCoeff() < 0.05);
  CHECK(T->translation().x() == Approx(-469.4629).margin(1e-4));
  CHECK(T->translation().y() == Approx(-1083.9676).margin(1e-4));
  // T_5^2 is A_3 A_4 A_5 whatever θ_1 and θ_2 are.
  const auto direct = rs::kinematics::dhTransform(model.joint(3).dh, -90) *
                      rs::kinematics::dhTransform(model.joint(4).dh, 34) *
                      rs::kinematics::dhTransform(model.joint(5).dh, -49);
  CHECK(kintest::maxDiff(*T, direct) < 1e-9);
}

TEST_CASE("SCOROBOT at home puts every frame where it was drawn", "[kinematics]") {
  const auto frames = scorobotFrames();
  const auto model = kintest::modelFromFrames(frames, kFiveRevolute);
  const rs::kinematics::ChainData data(model);  // made at home
  for (int i = 0; i <= 5; ++i) {
    INFO("frame " << i);
    CHECK(kintest::maxDiff(model.F_world_0() * data.F_0_i[static_cast<std::size_t>(i)],
                           frames[static_cast<std::size_t>(i)]) < 1e-9);
  }
  CHECK((rs::kinematics::toolPose(model, data).translation() - Vector3d(757, 0, 1397)).norm() < 1e-9);
}
