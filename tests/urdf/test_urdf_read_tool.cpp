// The tool frame a URDF tip brings (a tool centre point that no D-H frame
// can be): in the chain model (forward and inverse kinematics) and as a
// description's TOOL statement, which `convert` writes.
#include <catch2/catch.hpp>

#include "compiler/description/library.h"
#include "model/kinematics/ik.h"
#include "tests/cli/cli_support.h"
#include "tests/urdf/urdf_read_test_util.h"

namespace {

// A planar two-link arm (a = 300, 200) whose tool sits 50 along x and 30
// along z of frame 2, turned 90 degrees about y.
const char* kToolRobot = R"(LINK b
  LINE 0 0 0 10 0 0
END
LINK l1
  LINE 0 0 0 300 0 0
END
LINK l2
  LINE 300 0 0 500 0 0
END
ROBOT toolarm
  LINK b   FRAME ORIGIN 0 0 0    XAXIS 100 0 0  ZAXIS 0 100 0
  LINK l1  FRAME ORIGIN 300 0 0  XAXIS 400 0 0  ZAXIS 300 100 0
  LINK l2  FRAME ORIGIN 500 0 0  XAXIS 600 0 0  ZAXIS 500 100 0
  JOINT 1 REVOLUTE  LETTER A  PRECISION 0.1  RANGE -1800 1800
  JOINT 2 REVOLUTE  LETTER B  PRECISION 0.1  RANGE -1800 1800
  TOOL ORIGIN 550 30 0  XAXIS 550 30 -100  ZAXIS 650 30 0
END
)";

}  // namespace

TEST_CASE("urdf tool: a description's TOOL is the tool centre point, in forward and inverse kinematics", "[urdf]") {
  rs::testing::TempDir dir;
  const std::string file = dir.write("toolarm.rsd", kToolRobot);
  rs::compiler::Library library({});
  const std::optional<rs::workcell::Robot> robot = library.robot(file);
  for (const auto& d : library.diagnostics()) INFO(d.message);
  REQUIRE(robot);
  REQUIRE(robot->chain->hasTool());
  const rs::kinematics::ChainModel& chain = *robot->chain;
  rs::kinematics::ChainData data(chain);
  // Home: the tool where TOOL put it.
  std::vector<double> q{chain.joint(1).home, chain.joint(2).home};
  rs::kinematics::forwardKinematics(chain, data, q);
  Eigen::Isometry3d tool = rs::kinematics::toolPose(chain, data);
  CHECK((tool.translation() - Eigen::Vector3d(550, 30, 0)).norm() < 1e-9);
  CHECK((tool.linear().col(0) - Eigen::Vector3d(0, 0, -1)).norm() < 1e-12);
  // Joint 1 at 90 degrees turns the whole arm about y (the first axis):
  // by hand, (x, y, z) -> (z, y, -x) for a turn of +90 about y.
  q[0] += 90;
  rs::kinematics::forwardKinematics(chain, data, q);
  tool = rs::kinematics::toolPose(chain, data);
  CHECK((tool.translation() - Eigen::Vector3d(0, 30, -550)).norm() < 1e-9);
  // Inverse kinematics finds joint values that put the tool where a bent
  // arm has it (straight, the elbow is singular).
  q[1] += 40;
  rs::kinematics::forwardKinematics(chain, data, q);
  tool = rs::kinematics::toolPose(chain, data);
  const rs::kinematics::InverseKinematics ik(chain);
  rs::kinematics::ToolTarget target;
  target.position = chain.F_world_0().inverse() * tool.translation();
  target.rotation = chain.F_world_0().linear().transpose() * tool.linear();
  target.approachGiven = target.normalGiven = true;
  const rs::kinematics::IkSolutions solved = ik.solve(target, std::vector<double>{0.0, 0.0});
  INFO(rs::kinematics::familyName(ik.family()) << ": " << solved.error.message);
  REQUIRE(solved.ok());
  std::vector<double> found(solved.solutions[0].q.begin(), solved.solutions[0].q.begin() + 2);
  rs::kinematics::forwardKinematics(chain, data, found);
  CHECK((rs::kinematics::toolPose(chain, data).translation() - tool.translation()).norm() < 1e-6);
}

TEST_CASE("urdf tool: TOOL and GRIPPER exclude each other - TOOL needs its three points", "[urdf]") {
  rs::testing::TempDir dir;
  std::string text = kToolRobot;
  text.replace(text.find("  TOOL ORIGIN 550 30 0  XAXIS 550 30 -100  ZAXIS 650 30 0"),
               std::string("  TOOL ORIGIN 550 30 0  XAXIS 550 30 -100  ZAXIS 650 30 0").size(), "  TOOL ORIGIN 550 30 0");
  const std::string file = dir.write("bad.rsd", text);
  rs::compiler::Library library({});
  CHECK_FALSE(library.robot(file));
  REQUIRE_FALSE(library.diagnostics().empty());
  CHECK(library.diagnostics().front().message.find("TOOL needs ORIGIN, XAXIS and ZAXIS") != std::string::npos);
  CHECK(library.diagnostics().front().pos.line == 16);
}
