// The URDF files written by hand for the tests (tests/urdf/data, whose
// README says what each one tests): Orocos KDL's forward kinematics of the
// chain root -> tool0 against one computed here from the file's origins and
// axes as written (tinyxml2 and Eigen, no URDF library), at 1,000 seeded
// random joint values per file, to 1e-9 of the arm's reach for the tool's
// position and orientation. robotsim's reading of the same files joins
// this comparison with the URDF reader.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <set>

#include "tests/kdl/kdl_support.h"

namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The joints that move on their own, each with the range it is drawn from:
// its limits, or two turns each way for a continuous joint.
std::map<std::string, std::pair<double, double>> drivenJoints(const std::vector<rs::kdltest::XmlJoint>& path) {
  std::map<std::string, std::pair<double, double>> ranges;
  for (const rs::kdltest::XmlJoint& j : path) {
    if (j.type == "fixed" || !j.mimic.empty()) continue;
    if (j.type == "continuous") ranges[j.name] = {-4 * std::numbers::pi, 4 * std::numbers::pi};
    else ranges[j.name] = {j.lower, j.upper};
  }
  return ranges;
}

}  // namespace

TEST_CASE("kdl: the hand-written URDF files agree with an independent forward kinematics", "[urdf][kdl]") {
  const fs::path dir = fs::path(ROBOTSIM_SOURCE_DIR) / "tests" / "urdf" / "data";
  const std::set<std::string> expected{"continuous.urdf",    "fixed_between.urdf", "mimic.urdf",
                                       "parallel_axes.urdf", "prismatic.urdf",     "skew_axes.urdf"};
  std::set<std::string> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".urdf") found.insert(e.path().filename().string());
  REQUIRE(found == expected);
  std::uint64_t seed = 1;
  for (const std::string& name : found) {
    INFO("file " << name);
    const std::string xml = readText(dir / name);
    const std::vector<rs::kdltest::XmlJoint> path = rs::kdltest::pathTo(rs::kdltest::xmlJoints(xml), "tool0");
    REQUIRE(!path.empty());
    const rs::kdltest::KdlChain kdl = rs::kdltest::kdlChain(xml, path.front().parent, "tool0");
    const auto ranges = drivenJoints(path);
    const std::vector<rs::kdltest::Mimic> mimics = rs::kdltest::mimicsOf(xml);
    // What each file is for is in its chain: a mimic, a prismatic, a
    // continuous and a fixed joint between moving ones are where the README
    // says they are.
    const auto count = [&](const std::string& type) {
      return std::count_if(path.begin(), path.end(), [&](const auto& j) { return j.type == type; });
    };
    if (name == "prismatic.urdf") CHECK(count("prismatic") == 2);
    if (name == "continuous.urdf") CHECK(count("continuous") == 2);
    if (name == "fixed_between.urdf") CHECK(count("fixed") == 4);
    if (name == "mimic.urdf")
      CHECK(std::count_if(path.begin(), path.end(), [](const auto& j) { return !j.mimic.empty(); }) == 1);
    std::mt19937_64 rng(seed++);
    double reach = 0, worstPosition = 0, worstRotation = 0;
    std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>> poses;
    for (int s = 0; s < 1000; ++s) {
      std::map<std::string, double> values;
      for (const auto& [joint, range] : ranges)
        values[joint] = std::uniform_real_distribution<double>(range.first, range.second)(rng);
      const Eigen::Isometry3d eigen = rs::kdltest::eigenTip(path, values);
      poses.emplace_back(eigen, rs::kdltest::kdlTip(kdl, rs::kdltest::withMimics(mimics, values)));
      reach = std::max(reach, eigen.translation().norm());
    }
    REQUIRE(reach > 0.1);
    for (const auto& [eigen, kdlPose] : poses) {
      const rs::kdltest::PoseError err = rs::kdltest::poseError(eigen, kdlPose);
      worstPosition = std::max(worstPosition, err.position);
      worstRotation = std::max(worstRotation, err.rotation);
    }
    INFO("reach " << reach << " m, worst position error " << worstPosition << " m, worst rotation entry " << worstRotation);
    CHECK(worstPosition <= 1e-9 * reach);
    CHECK(worstRotation <= 1e-9);
  }
}
