// The reading side against Orocos KDL (issue 37): a URDF arm read by
// robotsim's reader (model/urdf/urdf_read.h, in this process) and by KDL's
// own URDF parser gives the same tool centre point at random joint values,
// to 1e-9 of the arm's reach in position and 1e-9 in each axis. robotsim's
// pose is in design coordinates (mm, y up); KDL's in the root link (m, z
// up), turned here by the documented Rx(-90 deg) written out by hand.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <set>

#include "model/kinematics/chain_data.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"
#include "model/urdf/urdf_read.h"
#include "tests/kdl/kdl_support.h"

namespace {

namespace fs = std::filesystem;

std::string readKdlReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A root-link pose (metres, z up) in design coordinates (millimetres, y
// up): x stays, z becomes y, y becomes -z.
Eigen::Isometry3d kdlReadToDesign(const Eigen::Isometry3d& F) {
  Eigen::Matrix3d M;
  M << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = M * F.linear();
  out.translation() = 1000.0 * (M * F.translation());
  return out;
}

struct KdlReadFile {
  fs::path path;
  std::string tip;  // empty: the reader's one leaf
};

// Both readings of one file at `samples` random encoder values inside each
// joint's range.
void compareWithKdl(const KdlReadFile& file, std::uint64_t seed, int samples) {
  INFO("file " << file.path.filename().string());
  rs::urdf::UrdfOptions options;
  options.tip = file.tip;
  const rs::urdf::UrdfRead read = rs::urdf::readUrdfFile(file.path, options);
  for (const auto& d : read.diagnostics) INFO(d.message);
  REQUIRE(read.robot);
  const rs::workcell::Robot& robot = *read.robot;
  REQUIRE(robot.urdf);
  const std::string xml = readKdlReadText(file.path);
  const rs::kdltest::KdlChain kdl = rs::kdltest::kdlChain(xml, robot.urdf->rootLink, robot.urdf->tipLink);
  const std::vector<rs::kdltest::Mimic> mimics = rs::kdltest::mimicsOf(xml);
  // robotsim's joints are the chain's moving joints in order, KDL's too
  // (a mimic joint is one of each: COUPLING in robotsim, its own in KDL).
  REQUIRE(robot.joints.size() == kdl.joints.size());
  REQUIRE(!robot.joints.empty());
  const rs::kinematics::ChainModel& chain = *robot.chain;
  rs::kinematics::ChainData data(chain);
  double reach = 0;
  for (const auto& f : robot.frames) reach += f.translation().norm();
  reach = std::max(reach, 1.0);
  std::mt19937_64 random(seed);
  for (int s = 0; s < samples; ++s) {
    INFO("sample " << s);
    std::vector<std::int32_t> counts;
    std::map<std::string, double> values;
    for (std::size_t i = 0; i < robot.joints.size(); ++i) {
      const rs::workcell::JointSpec& j = robot.joints[i];
      const std::int32_t c = std::uniform_int_distribution<std::int32_t>(j.min, j.max)(random);
      counts.push_back(c);
      const double v = c * j.precision;  // degrees or millimetres from the zero pose
      values[kdl.joints[i]] = j.type == rs::kinematics::JointType::Revolute ? v * std::numbers::pi / 180.0 : v / 1000.0;
    }
    std::vector<double> q(counts.size());
    REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, counts, q));
    rs::kinematics::forwardKinematics(chain, data, q);
    const Eigen::Isometry3d got = rs::kinematics::toolPose(chain, data);
    const Eigen::Isometry3d want = kdlReadToDesign(rs::kdltest::kdlTip(kdl, rs::kdltest::withMimics(mimics, values)));
    const rs::kdltest::PoseError e = rs::kdltest::poseError(got, want);
    REQUIRE(e.position <= 1e-9 * reach);
    REQUIRE(e.rotation <= 1e-9);
  }
}

}  // namespace

TEST_CASE("kdl: URDF arms read by robotsim and by kdl_parser give the same tool poses", "[urdf][kdl]") {
  const fs::path written = fs::path(ROBOTSIM_SOURCE_DIR) / "tests" / "urdf" / "data";
  const fs::path readData = fs::path(ROBOTSIM_SOURCE_DIR) / "tests" / "urdf" / "data_read";
  // The export tests' hand-written files (tool0 is their tip; mimic.urdf's
  // multiplier -0.5 is no COUPLING, below) and the reader's arms: parallel,
  // skew, intersecting axes, a continuous and a prismatic joint, fixed
  // joints between moving ones, a mimic that is COUPLING, the UR5.
  const std::vector<KdlReadFile> files{
      {written / "continuous.urdf", "tool0"},    {written / "fixed_between.urdf", "tool0"},
      {written / "parallel_axes.urdf", "tool0"}, {written / "prismatic.urdf", "tool0"},
      {written / "skew_axes.urdf", "tool0"},     {readData / "ur5_dh.urdf", ""},
      {readData / "mixed_arm.urdf", ""},         {readData / "scara.urdf", ""},
      {readData / "mimic_arm.urdf", ""},
  };
  std::uint64_t seed = 37;
  for (const KdlReadFile& f : files) compareWithKdl(f, seed++, 1000);
}

TEST_CASE("kdl: a mimic that COUPLING cannot say is an error naming the joint, not another robot", "[urdf][kdl]") {
  const fs::path file = fs::path(ROBOTSIM_SOURCE_DIR) / "tests" / "urdf" / "data" / "mimic.urdf";
  rs::urdf::UrdfOptions options;
  options.tip = "tool0";
  const rs::urdf::UrdfRead read = rs::urdf::readUrdfFile(file, options);
  REQUIRE_FALSE(read.robot);
  bool named = false;
  for (const auto& d : read.diagnostics)
    named = named || (d.severity == rs::diag::Severity::Error && d.message.find("j3") != std::string::npos);
  CHECK(named);
}
