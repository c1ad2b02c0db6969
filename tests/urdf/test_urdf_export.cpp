// The URDF export (model/urdf/urdf_export.h) and `robotsim export`: the XML
// writer's escaping and numbers, roll-pitch-yaw, the BOXes a description
// keeps, what the document holds (checked against values worked out by
// hand from the robots' descriptions), deterministic bytes, the atomic
// write, - for standard output and the errors. KDL's reading of the
// exports is tests/kdl/; check_urdf's is tests/urdf/test_check_urdf.sh.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <regex>
#include <string>

#include "compiler/description/library.h"
#include "model/urdf/urdf_export.h"
#include "model/urdf/urdf_export_pose.h"
#include "model/urdf/urdf_xml.h"
#include "tests/cli/cli_support.h"

namespace {

using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

std::optional<rs::workcell::Robot> libraryRobot(const std::string& name) {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  return library.robot(name);
}

const std::string kCoupledArm = std::string(ROBOTSIM_SOURCE_DIR) + "/tests/kdl/data/coupled-arm.rsd";

// The element `<TAG name="NAME" ...>...</TAG>` (or `<TAG name="NAME" .../>`) of `xml`.
std::string elementNamed(const std::string& xml, const std::string& tag, const std::string& name) {
  const std::size_t start = xml.find("<" + tag + " name=\"" + name + "\"");
  if (start == std::string::npos) return {};
  const std::size_t selfClose = xml.find("/>", start), open = xml.find('>', start);
  if (selfClose != std::string::npos && selfClose + 1 == open) return xml.substr(start, open + 1 - start);
  const std::size_t end = xml.find("</" + tag + ">", start);
  return xml.substr(start, end - start);
}

double attribute(const std::string& element, const std::string& name) {
  const std::size_t at = element.find(" " + name + "=\"");
  REQUIRE(at != std::string::npos);
  return std::stod(element.substr(at + name.size() + 3));
}

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("urdf xml: text is escaped, comments hold no --, numbers read back exactly", "[urdf]") {
  CHECK(rs::urdf::xmlEscape("a<b>&\"c'") == "a&lt;b&gt;&amp;&quot;c&apos;");
  CHECK(rs::urdf::xmlEscape(std::string("x\x01y\tz", 5)) == "x?y\tz");
  rs::urdf::XmlWriter w;
  w.open("robot", {{"name", "r&d"}});
  w.comment("made by --urdf -");
  w.element("link", {{"name", "a\"b"}});
  w.close();
  CHECK(w.take() ==
        "<robot name=\"r&amp;d\">\n  <!-- made by - -urdf -  -->\n  <link name=\"a&quot;b\"/>\n</robot>\n");
  CHECK(rs::urdf::xmlNumber(0.1) == "0.1");
  CHECK(rs::urdf::xmlNumber(-0.0) == "0");
  CHECK(rs::urdf::xmlNumber(std::cos(std::numbers::pi / 2)) == "0");  // 6e-17: a rounding residue
  CHECK(rs::urdf::xmlNumber(1e-5) == "0.00001");                       // never an exponent
  CHECK(rs::urdf::xmlNumber(-1234.5) == "-1234.5");
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> any(-1e3, 1e3);
  for (int i = 0; i < 1000; ++i) {
    const double v = any(rng);
    CHECK(std::stod(rs::urdf::xmlNumber(v)) == v);
  }
}

TEST_CASE("urdf pose: roll, pitch, yaw give every rotation back, at pitch ±90° too", "[urdf]") {
  const auto fromRpy = [](const Eigen::Vector3d& a) {
    return (Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
  };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Matrix3d R = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    CHECK((fromRpy(rs::urdf::rpyFromRotation(R)) - R).cwiseAbs().maxCoeff() < 1e-14);
    // Gimbal lock: pitch exactly ±90°, any roll and yaw.
    const Eigen::Matrix3d G = fromRpy({angle(rng), i % 2 ? std::numbers::pi / 2 : -std::numbers::pi / 2, angle(rng)});
    CHECK((fromRpy(rs::urdf::rpyFromRotation(G)) - G).cwiseAbs().maxCoeff() < 1e-12);
  }
  // The turn that stands a y-up drawing on z: y becomes z, z becomes -y.
  const Eigen::Matrix3d turn = rs::urdf::upTurn(rs::urdf::UpAxis::Y);
  CHECK(turn * Eigen::Vector3d::UnitY() == Eigen::Vector3d::UnitZ());
  CHECK(turn * Eigen::Vector3d::UnitZ() == -Eigen::Vector3d::UnitY());
  CHECK(turn * Eigen::Vector3d::UnitX() == Eigen::Vector3d::UnitX());
  CHECK(rs::urdf::upTurn(rs::urdf::UpAxis::Z) == Eigen::Matrix3d::Identity());
}

TEST_CASE("urdf: a description keeps each BOX's frame and size, turned and moved with its lines", "[urdf]") {
  TempDir dir;
  const std::string file = dir.write("shapes.rsd",
                                     "LINK s\n"
                                     "  LINE 0 0 0  10 0 0\n"
                                     "  BOX 10 -10 40 0 5 -5 COLOR RED\n"
                                     "  ROTATE Z 30\n"
                                     "  MOVE 1 2 3\n"
                                     "  BOX 0 1 1 0 1 0\n"
                                     "END\n"
                                     "ROBOT r\n"
                                     "  LINK s FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1\n"
                                     "END\n");
  rs::compiler::Library library({dir.path()});
  const std::optional<rs::workcell::Robot> robot = library.robot(file);
  REQUIRE(robot);
  const rs::workcell::Shape& s = robot->links.at(0);
  REQUIRE(s.boxes.size() == 2);
  CHECK(s.boxes[0].firstSegment == 1);
  CHECK(s.boxes[1].firstSegment == 13);
  CHECK(s.boxes[0].color == rs::workcell::Color::Red);
  CHECK(s.boxes[0].size.isApprox(Eigen::Vector3d(20, 40, 10)));
  CHECK(s.boxes[1].size.isApprox(Eigen::Vector3d(1, 1, 1)));
  // Each box's 12 lines run between its frame's corners (±size/2 along its axes).
  for (const rs::workcell::DrawnBox& b : s.boxes)
    for (std::size_t i = b.firstSegment; i < b.firstSegment + 12; ++i)
      for (const Eigen::Vector3d& end : {s.segments[i].a, s.segments[i].b}) {
        const Eigen::Vector3d local = b.F_design_box.inverse() * end;
        CHECK((local.cwiseAbs() - b.size / 2).cwiseAbs().maxCoeff() < 1e-12);
      }
}

TEST_CASE("urdf export: scorobot's document, checked against its description by hand", "[urdf]") {
  const std::optional<rs::workcell::Robot> robot = libraryRobot("scorobot");
  REQUIRE(robot);
  rs::urdf::ExportOptions o;
  o.millimetresPerUnit = 2, o.up = rs::urdf::UpAxis::Z;
  const rs::diag::Result<std::string> xml = rs::urdf::exportUrdf(*robot, o);
  REQUIRE(xml);
  const std::string& x = *xml;
  CHECK(x.rfind("<?xml version=\"1.0\"?>\n<robot name=\"scorobot\">\n", 0) == 0);
  // Five arm joints (motors F..B), two fingers, tool0: one link each.
  for (int i = 1; i <= 5; ++i) CHECK(!elementNamed(x, "joint", "joint_" + std::to_string(i)).empty());
  CHECK(countOf(x, "<joint ") == 5 + 2 + 1);
  CHECK(countOf(x, "<link ") == 1 + 5 + 2 + 1);
  // Joint 1: 0.1175 degrees per count, -1000..1000 counts, 400 counts/s.
  const std::string j1 = elementNamed(x, "joint", "joint_1");
  const double radiansPerCount = 0.1175 * std::numbers::pi / 180;
  CHECK(attribute(j1, "lower") == Approx(-1000 * radiansPerCount).epsilon(1e-15));
  CHECK(attribute(j1, "upper") == Approx(1000 * radiansPerCount).epsilon(1e-15));
  CHECK(attribute(j1, "velocity") == Approx(400 * radiansPerCount).epsilon(1e-15));
  CHECK(attribute(j1, "effort") == 0);
  // d1 = 1220 units of 2 mm: joint 1's frame stands 2.44 m above base_link.
  CHECK(j1.find("<origin xyz=\"0 0 2.44\" rpy=\"0 0 0\"/>") != std::string::npos);
  CHECK(j1.find("<parent link=\"base_link\"/>") != std::string::npos);
  // Joint 5 (the wrist roll) turns about z4, which runs down from the
  // wrist: link_5's frame is on it where x5 meets it, d5 = 600 units down,
  // at the tool centre point (757, 0, 1397). From link_4's frame (D-H
  // frame 3 at (707, 0, 1997), θ4 = d4 = 0) that is a4 = 50 units (0.1 m)
  // along its x and, as α4 = 90 turns z4 to its -y, 1.2 m along -y.
  CHECK(elementNamed(x, "joint", "joint_5").find("<origin xyz=\"0.1 -1.2 0\"") != std::string::npos);
  // So tool0, fixed to link_5, is link_5's frame itself (a5 = 0, α5 = 0).
  const std::string tool = elementNamed(x, "joint", "tool0_joint");
  CHECK(tool.find("type=\"fixed\"") != std::string::npos);
  CHECK(tool.find("<parent link=\"link_5\"/>") != std::string::npos);
  CHECK(tool.find("<origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>") != std::string::npos);
  // The gripper: motor A, 0.5 degrees per count, 0..40; finger 3 mimics finger 2.
  const std::string f2 = elementNamed(x, "joint", "finger_2_joint"), f3 = elementNamed(x, "joint", "finger_3_joint");
  CHECK(attribute(f2, "upper") == Approx(40 * 0.5 * std::numbers::pi / 180).epsilon(1e-15));
  CHECK(f2.find("<mimic") == std::string::npos);
  CHECK(f3.find("<mimic joint=\"finger_2_joint\" multiplier=\"1\" offset=\"0\"/>") != std::string::npos);
  // The plinth BOX -150 150 150 0 150 -150 turned ROTATE X 90: 300 x 150 x
  // 300 units, its centre 75 up: a 0.6 x 0.3 x 0.6 m box 0.15 m up.
  const std::string base = elementNamed(x, "link", "base_link");
  CHECK(base.find("<origin xyz=\"0 0 0.15\" rpy=\"1.5707963267948966 0 0\"/>") != std::string::npos);
  CHECK(base.find("<box size=\"0.6 0.3 0.6\"/>") != std::string::npos);
  CHECK(base.find("<material name=\"DARKGRAY\"/>") != std::string::npos);
  // Materials: EGA DARKGRAY is 0x55 0x55 0x55.
  CHECK(x.find("<material name=\"DARKGRAY\">\n    <color rgba=\"0.3333 0.3333 0.3333 1\"/>") != std::string::npos);
  // The upper arm's LINE (0 0 1220 to 0 0 1997, 777 units) is a thin box 1.554 m long.
  CHECK(elementNamed(x, "link", "link_2").find("<box size=\"1.554 0.002 0.002\"/>") != std::string::npos);
}

TEST_CASE("urdf export: a y-up robot stands up, and COUPLING becomes mimic joints that cascade", "[urdf]") {
  const std::optional<rs::workcell::Robot> irb = libraryRobot("abb-irb120");
  REQUIRE(irb);
  const rs::diag::Result<std::string> x = rs::urdf::exportUrdf(*irb);
  REQUIRE(x);
  // Axis 2 is 290 mm above the base (d1): 0.29 m up z after the turn.
  CHECK(elementNamed(*x, "joint", "joint_1").find("<origin xyz=\"0 0 0.29\"") != std::string::npos);
  CHECK(x->find("_coupling_") == std::string::npos);

  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const std::optional<rs::workcell::Robot> arm = library.robot(kCoupledArm);
  REQUIRE(arm);
  const rs::diag::Result<std::string> c = rs::urdf::exportUrdf(*arm);
  REQUIRE(c);
  // COUPLING ON on joints 1, 2 and 4: joint 2 cancels joint 1, joint 3
  // cancels joint 2's whole motion (so follows joint 1 and cancels joint
  // 2's own), joint 5 cancels joint 4.
  const auto mimic = [&](const std::string& joint, const std::string& followed, int multiplier) {
    const std::string e = elementNamed(*c, "joint", joint);
    INFO(joint);
    CHECK(e.find("<mimic joint=\"" + followed + "\" multiplier=\"" + std::to_string(multiplier) + "\" offset=\"0\"/>") !=
          std::string::npos);
  };
  mimic("joint_2_coupling_1", "joint_1", -1);
  mimic("joint_3_coupling_1", "joint_1", 1);
  mimic("joint_3_coupling_2", "joint_2", -1);
  mimic("joint_5_coupling_4", "joint_4", -1);
  CHECK(countOf(*c, "<mimic ") == 4);
  CHECK(elementNamed(*c, "joint", "joint_5_coupling_4").find("type=\"prismatic\"") != std::string::npos);
  // Joint 4 slides 0.5 mm per count over -40..100 counts.
  const std::string j4 = elementNamed(*c, "joint", "joint_4");
  CHECK(attribute(j4, "lower") == Approx(-0.02).epsilon(1e-15));
  CHECK(attribute(j4, "upper") == Approx(0.05).epsilon(1e-15));
}

TEST_CASE("robotsim export: deterministic bytes, atomic file, - for standard output", "[urdf][cli]") {
  TempDir dir;
  const std::string file = dir.file("irb.urdf");
  const rs::testing::CliResult written = runCli({"export", "abb-irb120", "--urdf", "-o", file});
  REQUIRE(written.code == 0);
  CHECK(written.err.empty());
  CHECK(std::regex_match(written.out, std::regex("abb-irb120 -> .*irb\\.urdf \\(URDF: 6 joints and a gripper, [0-9]+ bytes\\)\n")));
  const rs::testing::CliResult stdoutRun = runCli({"export", "abb-irb120", "--urdf", "-o", "-"});
  REQUIRE(stdoutRun.code == 0);
  CHECK(stdoutRun.out == readBytes(file));
  CHECK(runCli({"export", "abb-irb120", "--urdf", "-o", "-"}).out == stdoutRun.out);
  // No temporary file is left beside it.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  CHECK(entries == 1);
  // --mm-per-unit scales every length: twice the unit, twice the lengths.
  const rs::testing::CliResult twice = runCli({"export", "abb-irb120", "--urdf", "-o", "-", "--mm-per-unit", "2"});
  REQUIRE(twice.code == 0);
  CHECK(elementNamed(twice.out, "joint", "joint_1").find("<origin xyz=\"0 0 0.58\"") != std::string::npos);
}

TEST_CASE("robotsim export: bad input is an error with exit 2, nothing written", "[urdf][cli]") {
  TempDir dir;
  const std::string out = dir.file("x.urdf");
  SECTION("an unknown robot") {
    const rs::testing::CliResult r = runCli({"export", "no-such-robot", "--urdf", "-o", out});
    CHECK(r.code == 2);
    CHECK(r.err.find("error:") != std::string::npos);
  }
  SECTION("no --urdf") {
    const rs::testing::CliResult r = runCli({"export", "scorobot", "-o", out});
    CHECK(r.code == 2);
    CHECK(r.err.find("--urdf") != std::string::npos);
  }
  SECTION("a unit that is not a positive number") {
    for (const char* bad : {"0", "-1", "nan", "1e400"}) {
      const rs::testing::CliResult r = runCli({"export", "scorobot", "--urdf", "-o", out, "--mm-per-unit", bad});
      INFO(bad);
      CHECK(r.code == 2);
      CHECK(r.err.find("--mm-per-unit") != std::string::npos);
    }
  }
  SECTION("an up axis that is not y or z") {
    const rs::testing::CliResult r = runCli({"export", "scorobot", "--urdf", "-o", out, "--up", "x"});
    CHECK(r.code == 2);
  }
  SECTION("a directory as output") {
    const rs::testing::CliResult r = runCli({"export", "scorobot", "--urdf", "-o", dir.path().string()});
    CHECK(r.code == 2);
    CHECK(r.err.find(": error: cannot write: ") != std::string::npos);
  }
  CHECK_FALSE(std::filesystem::exists(out));
}
