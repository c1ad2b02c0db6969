// The URDF reader: the chain, units and axes, motors, and the D-H table
// derived from the joint axes (docs/models.md, "Reading URDF").
#include <catch2/catch.hpp>

#include <cmath>

#include "model/kinematics/dh.h"
#include "model/urdf/urdf_mesh.h"
#include "tests/urdf/urdf_read_test_util.h"

namespace {

using rs::kinematics::DhRow;
using rs::kinematics::JointType;
using urdftest::readData;

double wrapDegrees(double d) {
  d = std::remainder(d, 360.0);
  return d <= -180.0 ? d + 360.0 : d;
}

// Forward kinematics of the robot read from `file` against the URDF's own,
// at `samples` random joint values inside every joint's limits: the tool
// centre point's position within 1e-9 of the arm's reach, its axes within
// 1e-9.
void checkFk(const std::string& file, const rs::urdf::UrdfOptions& options = {}, int samples = 1000) {
  const rs::urdf::UrdfRead read = readData(file, options);
  for (const auto& d : read.diagnostics) INFO(d.message);
  REQUIRE(read.robot);
  const rs::workcell::Robot& robot = *read.robot;
  const urdftest::UrdfFk fk(urdftest::dataRead(file), robot.urdf->tipLink);
  const rs::kinematics::ChainModel& chain = *robot.chain;
  REQUIRE(static_cast<std::size_t>(chain.size()) == fk.moving.size());
  rs::kinematics::ChainData data(chain);
  std::mt19937_64 random(37);
  double reach = 0;
  for (const auto& f : robot.frames) reach = std::max(reach, f.translation().norm());
  reach = std::max(reach, 1.0) * 2;
  for (int s = 0; s < samples; ++s) {
    std::vector<double> counts, urdfQ;
    for (const rs::workcell::JointSpec& j : robot.joints) {
      std::uniform_int_distribution<std::int32_t> pick(j.min, j.max);
      const std::int32_t c = pick(random);
      counts.push_back(c);
      const double v = c * j.precision;  // degrees or millimetres from the zero pose
      urdfQ.push_back(j.type == JointType::Revolute ? v * M_PI / 180.0 : v / 1000.0);
    }
    std::vector<double> q(counts.size());
    REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, counts, q));
    rs::kinematics::forwardKinematics(chain, data, q);
    const Eigen::Isometry3d got = rs::kinematics::toolPose(chain, data);
    const Eigen::Isometry3d want = urdftest::toDesign(fk.pose(urdfQ));
    INFO(file << " sample " << s);
    REQUIRE((got.translation() - want.translation()).norm() <= 1e-9 * reach);
    REQUIRE((got.linear() - want.linear()).norm() <= 1e-9);
  }
}

}  // namespace

TEST_CASE("urdf read: the UR5's derived D-H rows are the published ones, up to the written choices", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("ur5_dh.urdf");
  for (const auto& d : read.diagnostics) INFO(d.message);
  REQUIRE(read.robot);
  const std::vector<DhRow> rows = read.robot->chain->table();
  REQUIRE(rows.size() == 6);
  // Universal Robots' published UR5 table (metres, degrees): theta, alpha, a, d.
  struct Published {
    double theta, alpha, a, d;
  };
  const Published published[6] = {{0, 90, 0, 0.089159}, {0, 0, -0.425, 0},  {0, 0, -0.39225, 0},
                                  {0, 90, 0, 0.10915},   {0, -90, 0, 0.09465}, {0, 0, 0, 0.0823}};
  // The choices of model/urdf/urdf_dh.h decide the sense of each x_i: a_i
  // > 0 where the axes are parallel or skew, 0 < alpha_i < 180 where they
  // intersect; frame n is the tip (this file's tool0, the published frame
  // 6) as it is. Where the published x_i points the other way, flipping it
  // negates a_i and alpha_i and adds 180 degrees to theta_i and theta_{i+1}.
  bool flip[7] = {false};
  for (int i = 1; i <= 5; ++i) {
    const Published& p = published[i - 1];
    flip[i] = p.a < 0 || (p.a == 0 && p.alpha < 0);
  }
  for (int i = 1; i <= 6; ++i) {
    const Published& p = published[i - 1];
    INFO("row " << i);
    CHECK(wrapDegrees(rows[i - 1].theta - (p.theta + 180.0 * (flip[i - 1] + flip[i]))) == Approx(0).margin(1e-9));
    CHECK(wrapDegrees(rows[i - 1].alpha - (flip[i] ? -p.alpha : p.alpha)) == Approx(0).margin(1e-9));
    CHECK(rows[i - 1].a == Approx(1000.0 * (flip[i] ? -p.a : p.a)).margin(1e-9));
    CHECK(rows[i - 1].d == Approx(1000.0 * p.d).margin(1e-9));
  }
  // tool0 obeys the D-H rules: it is frame 6, no tool frame.
  CHECK(!read.robot->tool.has_value());
}

TEST_CASE("urdf read: the UR5's tool centre point at home, turned to y up in millimetres", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("ur5_dh.urdf");
  REQUIRE(read.robot);
  rs::kinematics::ChainData data(*read.robot->chain);
  std::vector<double> q;
  for (const auto& j : read.robot->chain->joints()) q.push_back(j.home);
  rs::kinematics::forwardKinematics(*read.robot->chain, data, q);
  const Eigen::Vector3d tcp = rs::kinematics::toolPose(*read.robot->chain, data).translation();
  // By hand from the published table: the flange at x = a2 + a3, y = -(d4 + d6),
  // z = d1 - d5 (metres, z up); in design coordinates (x, z, -y) in mm.
  CHECK(tcp.x() == Approx(-817.25).margin(1e-9));
  CHECK(tcp.y() == Approx(89.159 - 94.65).margin(1e-9));
  CHECK(tcp.z() == Approx(109.15 + 82.3).margin(1e-9));
  CHECK(read.robot->urdf->rootLink == "base_link");
  CHECK(read.robot->urdf->tipLink == "tool0");
}

TEST_CASE("urdf read: the derived rows reproduce the URDF's forward kinematics at 1,000 joint values", "[urdf]") {
  checkFk("ur5_dh.urdf");
}

TEST_CASE("urdf read: continuous, skew, fixed-between and prismatic joints - a tip that is a tool frame", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("mixed_arm.urdf");
  REQUIRE(read.robot);
  const auto& joints = read.robot->joints;
  REQUIRE(joints.size() == 3);
  // A continuous joint: one turn either way at 0.01 degrees a count.
  CHECK(joints[0].min == -36000);
  CHECK(joints[0].max == 36000);
  // Limits -2..2 rad in counts of 0.01 degrees, rounded inwards; velocity
  // 1.5 rad/s as counts per second.
  CHECK(joints[1].min == static_cast<std::int32_t>(std::ceil(-2 * 180 / M_PI / 0.01)));
  CHECK(joints[1].max == static_cast<std::int32_t>(std::floor(2 * 180 / M_PI / 0.01)));
  CHECK(joints[1].speed == static_cast<std::int32_t>(std::lround(1.5 * 180 / M_PI / 0.01)));
  // The prismatic joint: -0.1..0.2 m in counts of 0.01 mm, 0.25 m/s.
  CHECK(joints[2].type == JointType::Prismatic);
  CHECK(joints[2].min == -10000);
  CHECK(joints[2].max == 20000);
  CHECK(joints[2].speed == 25000);
  CHECK(read.robot->tool.has_value());
  checkFk("mixed_arm.urdf");
}

TEST_CASE("urdf read: a mimic joint with multiplier -1 becomes COUPLING", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("mimic_arm.urdf");
  REQUIRE(read.robot);
  CHECK(read.robot->joints[1].coupling);
  CHECK(read.robot->joints[2].min == 0);
  CHECK(read.robot->joints[2].max == 0);
  checkFk("mimic_arm.urdf");
}

TEST_CASE("urdf read: limits that leave out the zero pose are widened with a warning naming the joint", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("scara.urdf");
  REQUIRE(read.robot);
  CHECK(read.robot->joints[1].min == 0);
  CHECK(read.robot->joints[1].max == static_cast<std::int32_t>(std::floor(1.5 * 180 / M_PI / 0.01)));
  REQUIRE(read.diagnostics.size() == 1);
  CHECK(read.diagnostics[0].severity == rs::diag::Severity::Warning);
  CHECK(read.diagnostics[0].message.find("'j2'") != std::string::npos);
  CHECK(read.diagnostics[0].pos.line == 11);
  checkFk("scara.urdf");
}

TEST_CASE("urdf read: --precision sets the counts of the ranges", "[urdf]") {
  rs::urdf::UrdfOptions options;
  options.precision = 0.1;
  const rs::urdf::UrdfRead read = readData("mixed_arm.urdf", options);
  REQUIRE(read.robot);
  CHECK(read.robot->joints[0].max == 3600);
  CHECK(read.robot->joints[2].max == 2000);
  checkFk("mixed_arm.urdf", options, 100);
}

TEST_CASE("urdf read: a branching tree needs --tip, which names the chain's end", "[urdf]") {
  const rs::urdf::UrdfRead branched = readData("branch.urdf");
  CHECK_FALSE(branched.robot);
  REQUIRE(branched.diagnostics.size() == 1);
  CHECK(branched.diagnostics[0].message.find("'to_left'") != std::string::npos);
  CHECK(branched.diagnostics[0].hint.find("--tip") != std::string::npos);
  rs::urdf::UrdfOptions options;
  options.tip = "right";
  const rs::urdf::UrdfRead read = readData("branch.urdf", options);
  REQUIRE(read.robot);
  CHECK(read.robot->urdf->tipLink == "right");
  CHECK(read.robot->joints.size() == 2);
  // The other finger's joint is off the chain: held at zero, with a warning.
  REQUIRE(read.diagnostics.size() == 1);
  CHECK(read.diagnostics[0].message.find("'to_left'") != std::string::npos);
}

TEST_CASE("urdf read: meshes by their feature edges - a missing mesh draws the link's frame, with a warning", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("meshes.urdf");
  REQUIRE(read.robot);
  // The cube: 12 triangles, but only its 12 edges fold by more than 30 degrees.
  CHECK(read.robot->links[0].segments.size() == 12);
  REQUIRE(read.robot->links[0].collision.size() == 1);
  // The hull of the cube's corners, 100 mm wide after scale 0.1.
  Eigen::AlignedBox3d box;
  for (const auto& p : read.robot->links[0].collision[0].points) box.extend(p);
  CHECK(box.sizes().x() == Approx(100));
  CHECK(read.robot->links[1].segments.size() == 3);
  REQUIRE(read.diagnostics.size() == 1);
  CHECK(read.diagnostics[0].severity == rs::diag::Severity::Warning);
  CHECK(read.diagnostics[0].message.find("gone.dae") != std::string::npos);
}

TEST_CASE("urdf read: an OBJ mesh too - its quadrilateral faces' 12 feature edges, its hull", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("mesh_obj.urdf");
  for (const auto& d : read.diagnostics) INFO(d.message);
  REQUIRE(read.robot);
  CHECK(read.diagnostics.empty());
  // A cube's 12 edges (a face's diagonal, if Assimp splits it, folds by 0).
  CHECK(read.robot->links[0].segments.size() == 12);
  REQUIRE(read.robot->links[0].collision.size() == 1);
  // 1 m scaled by 0.2 is 200 mm on each side, whatever the turn to y up.
  Eigen::AlignedBox3d box;
  for (const auto& p : read.robot->links[0].collision[0].points) box.extend(p);
  CHECK(box.sizes().x() == Approx(200));
  CHECK(box.sizes().y() == Approx(200));
  CHECK(box.sizes().z() == Approx(200));
}

// A COLLADA mesh, read by Debian's Assimp: box.dae, written by hand, is a
// box from (10, 20, 30) to (110, 220, 330) in its own millimetres
// (<unit meter="0.001">), saying Z_UP. Worked out by hand: in the URDF's
// metres the box is 0.01..0.11 by 0.02..0.22 by 0.03..0.33 (the unit
// applied, the up axis not, as RViz does); turned to y up (x stays, URDF z
// is y, URDF y is -z) and in millimetres, x 10..110, y 30..330, z
// -220..-20. Had Z_UP been applied, y would be -220..-20. To 1e-4 mm:
// Assimp keeps single-precision floats (7 digits of 330 is 3e-5).
TEST_CASE("urdf read: a COLLADA mesh - its unit applied, its up axis not, the box's 12 edges and its bounds", "[urdf]") {
  const rs::urdf::UrdfRead read = readData("mesh_dae.urdf");
  for (const auto& d : read.diagnostics) INFO(d.message);
  REQUIRE(read.robot);
  CHECK(read.diagnostics.empty());
  CHECK(read.robot->links[0].segments.size() == 12);
  REQUIRE(read.robot->links[0].collision.size() == 1);
  Eigen::AlignedBox3d hull, lines;
  for (const auto& p : read.robot->links[0].collision[0].points) hull.extend(p);
  for (const auto& s : read.robot->links[0].segments) lines.extend(s.a), lines.extend(s.b);
  for (const Eigen::AlignedBox3d* box : {&hull, &lines}) {
    CHECK(box->min().x() == Approx(10).margin(1e-4));
    CHECK(box->max().x() == Approx(110).margin(1e-4));
    CHECK(box->min().y() == Approx(30).margin(1e-4));
    CHECK(box->max().y() == Approx(330).margin(1e-4));
    CHECK(box->min().z() == Approx(-220).margin(1e-4));
    CHECK(box->max().z() == Approx(-20).margin(1e-4));
  }
}

TEST_CASE("urdf read: material colours become the nearest EGA colour", "[urdf]") {
  CHECK(rs::urdf::nearestEga(0.1, 0.1, 0.8) == rs::workcell::Color::Blue);
  CHECK(rs::urdf::nearestEga(1, 1, 1) == rs::workcell::Color::White);
  CHECK(rs::urdf::nearestEga(0.6, 0.6, 0.6) == rs::workcell::Color::LightGray);
  const rs::urdf::UrdfRead read = readData("mixed_arm.urdf");
  REQUIRE(read.robot);
  CHECK(read.robot->links[0].segments.front().color == rs::workcell::Color::Blue);
}
