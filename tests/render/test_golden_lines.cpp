// Golden tests: the projected 2-D endpoints of every library robot at fixed
// poses, against tests/render/golden/ROBOT.POSE.lines to 1e-6 pixels. One
// reference (SCOROBOT at pose B) is re-derived independently below from the
// paper's D-H table (Fig. 6) and the camera formula, with plain arrays.
//
// After an intended change (a robot redrawn, the camera changed), rewrite
// the references with ROBOTSIM_UPDATE_GOLDEN=1 and review the diff.
// The references of abb-irb120, adept-one, mitsubishi-rv-m1 and rhino-xr4
// were written that way when they joined the library (they are regression
// references); what they rest on is checked independently elsewhere: each
// robot's D-H table and T_n^0 against its published table and its home
// frames against its maker's figures (tests/library/), the camera formula
// by the scorobot derivation below, and each picture was looked at
// (docs/images/robot-NAME.png).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "render_test_util.h"
#include "runtime/render/picture.h"

namespace {

const std::string kGoldenDir = rendertest::kSourceDir + "/tests/render/golden/";

// Pose "b": motor i at the fraction 0.3 + 0.23 i (mod 1) of its range.
std::vector<std::int32_t> poseB(const rs::workcell::Robot& robot) {
  std::vector<std::int32_t> e;
  const auto at = [&](std::int32_t lo, std::int32_t hi) {
    const double f = std::fmod(0.3 + 0.23 * static_cast<double>(e.size()), 1.0);
    return static_cast<std::int32_t>(std::lround(lo + (hi - lo) * f));
  };
  for (const auto& j : robot.joints) e.push_back(at(j.min, j.max));
  if (robot.hasGripper) e.push_back(at(robot.gripper.min, robot.gripper.max));
  return e;
}

std::string dump(const std::string& robot, bool poseb) {
  const rs::workcell::Workcell cell = rendertest::cell(robot);
  rs::render::CellPoser poser(cell);
  rs::render::Camera camera;  // the default view, 1024x768
  camera.axes = poseb;
  const rs::render::Fit fit = rs::render::fitView(poser.homePoints(), camera);
  if (poseb) poser.setEncoders(0, poseB(cell.robots.front().robot));
  std::ostringstream out;
  rs::render::dumpText(out, rs::render::makePicture(poser, camera, fit, {}), cell);
  return out.str();
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string p; std::getline(in, p, sep);)
    if (sep != ' ' || !p.empty()) parts.push_back(p);
  return parts;
}

bool number(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size();
}

// Same rows, same words; numbers equal to 1e-6.
void compare(const std::string& actual, const std::string& expected) {
  const auto a = split(actual, '\n'), e = split(expected, '\n');
  REQUIRE(a.size() == e.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto wa = split(a[i], ' '), we = split(e[i], ' ');
    INFO("row " << i + 1 << ":\n  got      " << a[i] << "\n  expected " << e[i]);
    REQUIRE(wa.size() == we.size());
    for (std::size_t k = 0; k < wa.size(); ++k) {
      double x = 0, y = 0;
      if (number(wa[k], x) && number(we[k], y))
        REQUIRE(std::abs(x - y) <= 1e-6);
      else
        REQUIRE(wa[k] == we[k]);
    }
  }
}

using rs::testing::readBytes;

}  // namespace

TEST_CASE("Every library robot projects to its reference lines", "[render][golden]") {
  for (const std::string& robot : rendertest::libraryRobots())
    for (const bool poseb : {false, true}) {
      const std::string path = kGoldenDir + robot + (poseb ? ".b.lines" : ".home.lines");
      INFO(path);
      const std::string actual = dump(robot, poseb);
      if (rs::testing::rewriteGolden(path, actual)) continue;
      REQUIRE(std::filesystem::exists(path));
      compare(actual, readBytes(path));
    }
}

// ---- an independent derivation of scorobot.b.lines's link rows --------------

namespace {

using M4 = std::array<double, 16>;  // row-major 4x4

M4 mul(const M4& a, const M4& b) {
  M4 c{};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j) c[4 * r + j] += a[4 * r + k] * b[4 * k + j];
  return c;
}

// The inverse of a rigid motion [R t]: [R' -R't].
M4 rigidInverse(const M4& m) {
  M4 i{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) i[4 * r + c] = m[4 * c + r];
    i[4 * r + 3] = -(m[r] * m[3] + m[4 + r] * m[7] + m[8 + r] * m[11]);
  }
  i[15] = 1;
  return i;
}

// The paper's A_i = Rot(z, θ) Trans(z, d) Trans(x, a) Rot(x, α), written out.
M4 dh(double theta, double alpha, double a, double d) {
  const double r = M_PI / 180, ct = std::cos(theta * r), st = std::sin(theta * r), ca = std::cos(alpha * r),
               sa = std::sin(alpha * r);
  return {ct, -ca * st, sa * st, a * ct, st, ca * ct, -sa * ct, a * st, 0, sa, ca, d, 0, 0, 0, 1};
}

std::array<double, 3> transformPoint(const M4& m, const Eigen::Vector3d& p) {
  std::array<double, 3> q{};
  for (int r = 0; r < 3; ++r) q[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
  return q;
}

}  // namespace

// Link i's points move by F_i(q)·F_i(home)⁻¹ (frame 0 is the design's own
// axes, and a robot alone stands where it was drawn); frames from Fig. 6's
// table, θ_i = home_i + 0.1175 × count. The camera: u = 512 + s·x', v = 384 −
// s·y' with (x', y') = Rx(25)·Ry(−35)·(p − centre), s = 0.45·768 / radius,
// centre and radius read from the reference's header.
TEST_CASE("scorobot.b.lines agrees with the paper's D-H table and the camera formula", "[render][golden]") {
  const double alpha[] = {90, 0, 0, 90, 0}, a[] = {0, 777, 707, 50, 0}, d[] = {1220, 0, 0, 0, 600},
               home[] = {0, 90, -90, 0, 90};
  const rs::workcell::Workcell cell = rendertest::cell("scorobot");
  const rs::workcell::Robot& robot = cell.robots.front().robot;
  const std::vector<std::int32_t> enc = poseB(robot);
  REQUIRE(enc.size() == 6);
  REQUIRE(robot.links.size() == 5);
  M4 T{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, H = T;
  std::array<M4, 6> move{T};  // F_i(q)·F_i(home)⁻¹
  for (std::size_t i = 0; i < 5; ++i) {
    T = mul(T, dh(home[i] + 0.1175 * enc[i], alpha[i], a[i], d[i]));
    H = mul(H, dh(home[i], alpha[i], a[i], d[i]));
    move[i + 1] = mul(T, rigidInverse(H));
  }

  const std::string golden = readBytes(kGoldenDir + "scorobot.b.lines");
  const auto rows = split(golden, '\n');
  const auto cam = split(rows.at(1), ' ');
  // "# camera: view 25 -35 0 window 0 0 0 zoom 1 axes on fit cx cy cz radius r"
  REQUIRE(cam.size() == 20);
  REQUIRE(cam.at(2) == "view");
  REQUIRE(cam.at(14) == "fit");
  REQUIRE(std::stod(cam.at(3)) == 25.0);
  REQUIRE(std::stod(cam.at(4)) == -35.0);
  REQUIRE(std::stod(cam.at(5)) == 0.0);
  const double cx = std::stod(cam.at(15)), cy = std::stod(cam.at(16)), cz = std::stod(cam.at(17)),
               radius = std::stod(cam.at(19));
  const double r = M_PI / 180, s = 0.45 * 768 / radius;
  const auto pixel = [&](std::array<double, 3> p) {
    const double x = p[0] - cx, y = p[1] - cy, z = p[2] - cz;
    const double x1 = std::cos(-35 * r) * x + std::sin(-35 * r) * z,
                 z1 = -std::sin(-35 * r) * x + std::cos(-35 * r) * z;
    const double y2 = std::cos(25 * r) * y - std::sin(25 * r) * z1;
    return std::array<double, 2>{512 + s * x1, 384 - s * y2};
  };

  std::size_t row = 2, checked = 0;
  for (std::size_t i = 0; i < 5; ++i)
    for (const rs::workcell::Segment& seg : robot.links[i].segments) {
      const auto w = split(rows.at(row++), ' ');
      REQUIRE(w.size() == 9);
      REQUIRE(w[3] == "link" + std::to_string(i));
      const auto pa = pixel(transformPoint(move[i], seg.a)), pb = pixel(transformPoint(move[i], seg.b));
      CHECK(std::stod(w[5]) == Approx(pa[0]).margin(1e-6));
      CHECK(std::stod(w[6]) == Approx(pa[1]).margin(1e-6));
      CHECK(std::stod(w[7]) == Approx(pb[0]).margin(1e-6));
      CHECK(std::stod(w[8]) == Approx(pb[1]).margin(1e-6));
      ++checked;
    }
  CHECK(checked > 50);
  // The tool centre point: the origin of frame 5.
  const auto tool = split(rows.back(), ' ');
  REQUIRE(tool.size() == 5);
  REQUIRE(tool[0] == "tool");
  const auto ut = pixel(transformPoint(T, Eigen::Vector3d::Zero()));
  CHECK(std::stod(tool[3]) == Approx(ut[0]).margin(1e-6));
  CHECK(std::stod(tool[4]) == Approx(ut[1]).margin(1e-6));
}
