// robotsim's robots exported as URDF, checked against a library nobody
// here wrote: Orocos KDL reads each export with its own URDF parser
// (kdl_parser), builds the chain base_link -> tool0, and its forward
// kinematics must agree with robotsim's at 1,000 seeded random encoder
// values per robot, to 1e-9 of the arm's reach for the tool centre point's
// position and orientation. All ten library robots, and an arm whose
// joints are coupled (COUPLING ON written as mimic joints). The geometry
// too: every box KDL's tree places, at random poses, has the corners of the
// BOX robotsim draws there.
#include <catch2/catch.hpp>

#include <kdl/treefksolverpos_recursive.hpp>

#include <algorithm>
#include <filesystem>
#include <random>

#include "compiler/description/library.h"
#include "model/kinematics/angles.h"
#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/gripper.h"
#include "model/kinematics/joint_values.h"
#include "model/urdf/urdf_export.h"
#include "tests/kdl/kdl_support.h"

namespace {

namespace fs = std::filesystem;
using rs::kinematics::JointType;

constexpr int kSamples = 1000;

struct Exported {
  rs::workcell::Robot robot;
  rs::urdf::ExportOptions options;
  std::string xml;
  std::vector<rs::kdltest::Mimic> mimics;
};

// The paper's two robots are drawn in units of 2 mm, scorobot z up
// (stdlib/README.md); the rest in millimetres, y up.
rs::urdf::ExportOptions optionsFor(const std::string& name) {
  rs::urdf::ExportOptions o;
  if (name == "scorobot" || name == "rhino-scara") o.millimetresPerUnit = 2;
  if (name == "scorobot") o.up = rs::urdf::UpAxis::Z;
  return o;
}

Exported exported(const std::string& robotFile) {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Robot> robot = library.robot(robotFile);
  REQUIRE(robot);
  const rs::urdf::ExportOptions options = optionsFor(robot->name);
  rs::diag::Result<std::string> xml = rs::urdf::exportUrdf(*robot, options);
  REQUIRE(xml);
  std::vector<rs::kdltest::Mimic> mimics = rs::kdltest::mimicsOf(*xml);
  return {std::move(*robot), options, std::move(xml).value(), std::move(mimics)};
}

// The robots the test exports: the library's ten and the coupled arm.
std::vector<std::string> robotFiles() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(ROBOTSIM_SOURCE_DIR) / "stdlib" / "robots"))
    if (e.path().extension() == ".rsd") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

const std::string kCoupledArm = std::string(ROBOTSIM_SOURCE_DIR) + "/tests/kdl/data/coupled-arm.rsd";

// A design-coordinates pose in URDF's base_link: the documented turn
// (Rx(+90°) for a y-up drawing, none for z up) and millimetres to metres.
Eigen::Isometry3d inBase(const Eigen::Isometry3d& F_design, const rs::urdf::ExportOptions& o) {
  const Eigen::Matrix3d turn = o.up == rs::urdf::UpAxis::Y
                                   ? Eigen::AngleAxisd(rs::kinematics::kDegToRad * 90, Eigen::Vector3d::UnitX()).toRotationMatrix()
                                   : Eigen::Matrix3d::Identity();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = turn * F_design.linear();
  T.translation() = turn * F_design.translation() * o.millimetresPerUnit / 1000;
  return T;
}

// Random encoder counts within every motor's range (the gripper's last).
std::vector<double> randomEncoders(const rs::workcell::Robot& robot, std::mt19937_64& rng) {
  std::vector<double> e;
  for (const rs::workcell::JointSpec& j : robot.joints)
    e.push_back(std::uniform_int_distribution<int>(j.min, j.max)(rng));
  if (robot.hasGripper) e.push_back(std::uniform_int_distribution<int>(robot.gripper.min, robot.gripper.max)(rng));
  return e;
}

// The URDF joint values the documented mapping gives: joint_i moves by its
// motor's precision × count (radians, or metres), finger_2_joint by the
// gripper's; the mimic joints as the file says.
std::map<std::string, double> urdfValues(const Exported& x, const std::vector<double>& e) {
  std::map<std::string, double> v;
  for (std::size_t i = 0; i < x.robot.joints.size(); ++i) {
    const rs::workcell::JointSpec& j = x.robot.joints[i];
    const double q = j.precision * e[i];
    v[rs::urdf::jointName(static_cast<int>(i + 1))] =
        j.type == JointType::Revolute ? rs::kinematics::kDegToRad * q : q * x.options.millimetresPerUnit / 1000;
  }
  if (x.robot.hasGripper) v["finger_2_joint"] = rs::kinematics::kDegToRad * x.robot.gripper.model.precision * e.back();
  return rs::kdltest::withMimics(x.mimics, v);
}

// robotsim's tool pose (design coordinates) for encoder counts.
Eigen::Isometry3d robotsimTool(const rs::workcell::Robot& robot, const std::vector<double>& e) {
  const rs::kinematics::ChainModel& chain = *robot.chain;
  rs::kinematics::ChainData data(chain);
  std::vector<double> q(static_cast<std::size_t>(chain.size()));
  REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, std::span<const double>(e), q));
  REQUIRE(rs::kinematics::forwardKinematics(chain, data, q));
  return rs::kinematics::toolPose(chain, data);
}

}  // namespace

TEST_CASE("kdl: the library's ten robots and a coupled arm, exported, agree with robotsim's kinematics", "[urdf][kdl]") {
  std::vector<std::string> files = robotFiles();
  REQUIRE(files.size() == 10);
  files.push_back(kCoupledArm);
  std::uint64_t seed = 20261202;
  for (const std::string& file : files) {
    const Exported x = exported(file);
    INFO("robot " << x.robot.name);
    const rs::kdltest::KdlChain kdl = rs::kdltest::kdlChain(x.xml, "base_link", "tool0");
    // KDL's chain holds every arm joint and every coupling's mimic joint.
    CHECK(kdl.joints.size() >= x.robot.joints.size());
    std::mt19937_64 rng(seed++);
    std::vector<Eigen::Isometry3d> expected, kdlPoses;
    double reach = 0;
    for (int s = 0; s < kSamples; ++s) {
      const std::vector<double> e = randomEncoders(x.robot, rng);
      expected.push_back(inBase(robotsimTool(x.robot, e), x.options));
      kdlPoses.push_back(rs::kdltest::kdlTip(kdl, urdfValues(x, e)));
      // The reach: how far the tool centre point gets from frame 0's origin.
      const Eigen::Vector3d base = inBase(x.robot.chain->F_world_0(), x.options).translation();
      reach = std::max(reach, (expected.back().translation() - base).norm());
    }
    REQUIRE(reach > 0.05);
    double worstPosition = 0, worstRotation = 0;
    for (int s = 0; s < kSamples; ++s) {
      const rs::kdltest::PoseError err = rs::kdltest::poseError(expected[static_cast<std::size_t>(s)], kdlPoses[static_cast<std::size_t>(s)]);
      worstPosition = std::max(worstPosition, err.position);
      worstRotation = std::max(worstRotation, err.rotation);
    }
    INFO("reach " << reach << " m, worst position error " << worstPosition << " m, worst rotation entry " << worstRotation);
    CHECK(worstPosition <= 1e-9 * reach);
    CHECK(worstRotation <= 1e-9);
  }
}

namespace {

// The 8 corners of a box of `size` centred at `F`'s origin along its axes.
std::vector<Eigen::Vector3d> corners(const Eigen::Isometry3d& F, const Eigen::Vector3d& size) {
  std::vector<Eigen::Vector3d> c;
  for (int i = 0; i < 8; ++i)
    c.push_back(F * Eigen::Vector3d((i & 4 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                                    (i & 1 ? 0.5 : -0.5) * size.z()));
  return c;
}

// Each corner of `a` has one of `b` within `tolerance`.
bool sameCorners(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, double tolerance) {
  return std::all_of(a.begin(), a.end(), [&](const Eigen::Vector3d& p) {
    return std::any_of(b.begin(), b.end(), [&](const Eigen::Vector3d& q) { return (p - q).norm() <= tolerance; });
  });
}

Eigen::Isometry3d fromPose(const ::urdf::Pose& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).toRotationMatrix();
  T.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  return T;
}

}  // namespace

TEST_CASE("kdl: every exported BOX stands where robotsim draws it, fingers included", "[urdf][kdl]") {
  std::vector<std::string> files = robotFiles();
  files.push_back(kCoupledArm);
  std::uint64_t seed = 7;
  for (const std::string& file : files) {
    const Exported x = exported(file);
    INFO("robot " << x.robot.name);
    const ::urdf::ModelInterfaceSharedPtr model = ::urdf::parseURDF(x.xml);
    REQUIRE(model);
    KDL::Tree tree;
    REQUIRE(kdl_parser::treeFromString(x.xml, tree));
    KDL::TreeFkSolverPos_recursive fk(tree);
    const rs::workcell::Robot& r = x.robot;
    const rs::kinematics::ChainModel& chain = *r.chain;
    const int n = chain.size();
    rs::kinematics::ChainData home(chain), data(chain);
    std::mt19937_64 rng(seed++);
    for (int s = 0; s < 20; ++s) {
      const std::vector<double> e = randomEncoders(r, rng);
      std::vector<double> q(static_cast<std::size_t>(n));
      REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, std::span<const double>(e), q));
      REQUIRE(rs::kinematics::forwardKinematics(chain, data, q));
      // A link's drawing moves with its frame (as the renderer moves it).
      const auto motion = [&](int frame) {
        const auto f = static_cast<std::size_t>(std::min(frame, n));
        return chain.F_world_0() * data.F_0_i[f] * (chain.F_world_0() * home.F_0_i[f]).inverse(Eigen::Isometry);
      };
      const std::map<std::string, double> values = urdfValues(x, e);
      KDL::JntArray jq(tree.getNrOfJoints());
      for (const auto& [name, segment] : tree.getSegments()) {
        const KDL::Joint& j = segment.segment.getJoint();
        if (j.getType() != KDL::Joint::None) jq(segment.q_nr) = values.at(j.getName());
      }
      // (link name, shape, motion of its drawing in design coordinates)
      std::vector<std::tuple<std::string, const rs::workcell::Shape*, Eigen::Isometry3d>> parts;
      for (int i = 0; i < static_cast<int>(r.links.size()); ++i)
        parts.emplace_back(i == 0 ? "base_link" : rs::urdf::linkName(i), &r.links[static_cast<std::size_t>(i)], motion(i));
      if (r.hasGripper) {
        const rs::kinematics::FingerTransforms fingers = rs::kinematics::fingerTransforms(r.gripper.model, e.back());
        parts.emplace_back(rs::urdf::linkName(n), &r.gripper.base, motion(n));
        parts.emplace_back("finger_2", &r.gripper.finger2, motion(n) * fingers.finger2);
        parts.emplace_back("finger_3", &r.gripper.finger3, motion(n) * fingers.finger3);
      }
      for (const auto& [linkName, shape, move] : parts) {
        INFO("link " << linkName << " (" << shape->name << ")");
        const ::urdf::LinkConstSharedPtr link = model->getLink(linkName);
        REQUIRE(link);
        REQUIRE(link->visual_array.size() >= shape->boxes.size());
        KDL::Frame F_base_link;
        REQUIRE(fk.JntToCart(jq, F_base_link, linkName) >= 0);
        for (std::size_t b = 0; b < shape->boxes.size(); ++b) {
          const rs::workcell::DrawnBox& box = shape->boxes[b];
          const ::urdf::Visual& visual = *link->visual_array[b];
          REQUIRE(visual.geometry->type == ::urdf::Geometry::BOX);
          const ::urdf::Vector3& size = static_cast<const ::urdf::Box&>(*visual.geometry).dim;
          const std::vector<Eigen::Vector3d> urdfCorners =
              corners(rs::kdltest::toEigen(F_base_link) * fromPose(visual.origin), {size.x, size.y, size.z});
          std::vector<Eigen::Vector3d> drawn;
          for (const Eigen::Vector3d& c : corners(box.F_design_box, box.size))
            drawn.push_back(inBase(move, x.options) * (c * x.options.millimetresPerUnit / 1000));
          // Flat BOXes are exported 2 mm thick: their corners stand 1 mm off.
          const double tolerance = box.size.minCoeff() * x.options.millimetresPerUnit < 2 ? 1.01e-3 : 1e-9;
          CHECK(sameCorners(drawn, urdfCorners, tolerance));
        }
      }
    }
  }
}
