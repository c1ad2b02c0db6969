// The gripper: fingers turning about r2 and r3 in the paper's senses, the
// end-effector frame from n and a, and the gripper's errors.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "model/kinematics/gripper.h"

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using rs::kinematics::ErrorKind;
using rs::kinematics::GripperPoints;
using rs::kinematics::KinematicsError;
using rs::kinematics::makeGripper;

// The paper's Fig. 2, drawn in the xz-plane seen from -y (x to the right,
// z up, so "out of the page" is -y): fingers hang down from pivots at
// x = -20 (finger 2) and x = +20 (finger 3); r2 points out of the page, r3
// into it. The tool centre point is at (0, 0, -60), n = +x, a = -z.
GripperPoints fig2() {
  GripperPoints p;
  p.r2From = {-20, 0, 0};
  p.r2To = {-20, -1, 0};
  p.r3From = {20, 0, 0};
  p.r3To = {20, 1, 0};
  p.normalFrom = {0, 0, -60};
  p.normalTo = {10, 0, -60};
  p.approachFrom = {0, 0, -60};
  p.approachTo = {0, 0, -70};
  return p;
}

}  // namespace

TEST_CASE("closing turns both fingers inwards", "[kinematics]") {
  const auto gripper = makeGripper(fig2(), 0.5);
  REQUIRE(gripper.ok());
  // 20 counts × 0.5 = 10 degrees. Finger 2 turns counter-clockwise as seen,
  // so its tip, 50 below the pivot, swings right; finger 3 clockwise, left.
  const auto fingers = rs::kinematics::fingerTransforms(*gripper.value, 20);
  const double s = 50 * std::sin(10 * std::numbers::pi / 180), c = 50 * std::cos(10 * std::numbers::pi / 180);
  CHECK((fingers.finger2 * Vector3d(-20, 0, -50) - Vector3d(-20 + s, 0, -c)).norm() < 1e-12);
  CHECK((fingers.finger3 * Vector3d(20, 0, -50) - Vector3d(20 - s, 0, -c)).norm() < 1e-12);
  // Points on an axis stay put; open (encoder 0) is the drawing.
  CHECK((fingers.finger2 * Vector3d(-20, 7, 0) - Vector3d(-20, 7, 0)).norm() < 1e-12);
  const auto open = rs::kinematics::fingerTransforms(*gripper.value, 0);
  CHECK(open.finger2.isApprox(Isometry3d::Identity()));
}

TEST_CASE("the gripper's n and a are the end-effector frame", "[kinematics]") {
  const auto gripper = makeGripper(fig2(), 0.5);
  REQUIRE(gripper.ok());
  const Isometry3d& E = gripper.value->F_G_E;
  CHECK((E.translation() - Vector3d(0, 0, -60)).norm() == 0.0);
  CHECK((E.linear().col(0) - Vector3d(1, 0, 0)).norm() == 0.0);
  CHECK((E.linear().col(2) - Vector3d(0, 0, -1)).norm() == 0.0);
  // Mounted on a robot whose tool frame is F_world_E, the TCP lands on it.
  Isometry3d tool = Isometry3d::Identity();
  tool.translate(Vector3d(300, 100, 500)).rotate(Eigen::AngleAxisd(0.3, Vector3d(1, 2, 3).normalized()));
  const Isometry3d F_world_G = rs::kinematics::gripperPlacement(tool, *gripper.value);
  CHECK((F_world_G * Vector3d(0, 0, -60) - tool.translation()).norm() < 1e-12);
}

TEST_CASE("gripper errors", "[kinematics]") {
  GripperPoints offTcp = fig2();
  offTcp.approachFrom = {1, 0, -60};
  offTcp.approachTo = {1, 0, -70};
  auto result = makeGripper(offTcp, 0.5);
  REQUIRE(result.errors.size() == 1);
  CHECK(result.errors[0] == KinematicsError{ErrorKind::TcpMismatch, rs::kinematics::kGripperApproach,
                                            "the approach vector starts at (1, 0, -60), not at the normal vector's "
                                            "start (0, 0, -60): both must start at the tool centre point"});

  GripperPoints slanted = fig2();
  slanted.approachTo = {10, 0, -70};  // a = (10, 0, -10): 45 degrees from n
  result = makeGripper(slanted, 0.5);
  REQUIRE(result.errors.size() == 1);
  CHECK(result.errors[0] ==
        KinematicsError{ErrorKind::AxesNotPerpendicular, rs::kinematics::kGripperNormal,
                        "the normal vector and the approach vector are not perpendicular (the angle between them is "
                        "45 degrees)"});

  GripperPoints degenerate = fig2();
  degenerate.r3To = degenerate.r3From;
  result = makeGripper(degenerate, 0);
  REQUIRE(result.errors.size() == 2);
  CHECK(result.errors[0] == KinematicsError{ErrorKind::DegenerateAxis, rs::kinematics::kGripperAxis3, "axis r3 has zero length"});
  CHECK(result.errors[1] ==
        KinematicsError{ErrorKind::BadPrecision, rs::kinematics::kGripperWhole, "the gripper has precision 0, but it must be a non-zero number"});
}
