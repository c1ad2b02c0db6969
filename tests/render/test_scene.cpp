// CellPoser: the paper's drawing rule (each link drawn at home, moved by
// its frame), checked against the kinematics library on every stdlib robot
// and workcell.
#include <catch2/catch.hpp>
#include <random>

#include "render_test_util.h"
#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"
#include "runtime/render/picture.h"
#include "runtime/render/scene.h"
#include "model/workcell/tool_tracker.h"

using rs::render::CellPoser;
using rs::render::Line3;
using rs::render::PartKind;

namespace {

std::vector<std::string> allCells() {
  std::vector<std::string> names = rendertest::libraryRobots();
  for (const auto& entry : std::filesystem::directory_iterator(rendertest::kSourceDir + "/stdlib/workcells"))
    if (entry.path().extension() == ".rsd") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Encoders inside every motor's range, from a fixed seed.
std::vector<std::int32_t> randomEncoders(const rs::workcell::Robot& robot, std::mt19937& rng) {
  std::vector<std::int32_t> e;
  for (const auto& j : robot.joints) e.push_back(std::uniform_int_distribution<std::int32_t>(j.min, j.max)(rng));
  if (robot.hasGripper)
    e.push_back(std::uniform_int_distribution<std::int32_t>(robot.gripper.min, robot.gripper.max)(rng));
  return e;
}

double distance(const Line3& l, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::max((l.a - a).norm(), (l.b - b).norm());
}

}  // namespace

TEST_CASE("At home every line is where the workcell placed its drawing", "[render]") {
  for (const std::string& name : allCells()) {
    INFO(name);
    const rs::workcell::Workcell cell = rendertest::cell(name);
    const CellPoser poser(cell);
    std::vector<Line3> lines;
    poser.lines(lines);
    std::size_t k = 0;
    for (const auto& placed : cell.robots) {
      const auto& r = placed.robot;
      std::vector<const rs::workcell::Shape*> shapes;
      for (const auto& link : r.links) shapes.push_back(&link);
      if (r.hasGripper) shapes.insert(shapes.end(), {&r.gripper.base, &r.gripper.finger2, &r.gripper.finger3});
      for (const auto* shape : shapes)
        for (const auto& s : shape->segments) {
          REQUIRE(k < lines.size());
          CHECK(distance(lines[k], placed.F_world_design * s.a, placed.F_world_design * s.b) < 1e-9);
          CHECK(lines[k].color == s.color);
          ++k;
        }
    }
    for (const auto& object : cell.objects)
      for (const auto& s : object.shape.segments) {
        REQUIRE(k < lines.size());
        CHECK(distance(lines[k], object.F_world_design * s.a, object.F_world_design * s.b) < 1e-9);
        CHECK(lines[k].part.kind == PartKind::Object);
        ++k;
      }
    CHECK(k == lines.size());
    CHECK(poser.homePoints().size() == 2 * lines.size());
  }
}

TEST_CASE("Each link moves with its frame, the tool is the ToolTracker's", "[render]") {
  std::mt19937 rng(4);
  for (const std::string& name : allCells()) {
    INFO(name);
    const rs::workcell::Workcell cell = rendertest::cell(name);
    const auto& placed = cell.robots.front();
    const auto& robot = placed.robot;
    REQUIRE(robot.chain);
    CellPoser poser(cell);
    rs::workcell::ToolTracker tracker(placed);
    // An independent route: the placed chain, FK at home and at q.
    const auto chain = robot.chain->placedAt(placed.F_world_design * robot.frames.front());
    rs::kinematics::ChainData home(chain), now(chain);
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<std::int32_t> enc = randomEncoders(robot, rng);
      poser.setEncoders(0, enc);
      std::vector<double> q(static_cast<std::size_t>(chain.size()));
      REQUIRE(rs::kinematics::jointValuesFromEncoders(chain, std::span<const std::int32_t>(enc), q));
      REQUIRE(rs::kinematics::forwardKinematics(chain, now, q));
      const auto tcp = tracker.tcp(enc);
      CHECK((poser.tool(0) - Eigen::Vector3d(tcp[0], tcp[1], tcp[2])).norm() < 1e-9);
      std::vector<Line3> lines;
      poser.lines(lines);
      std::size_t k = 0;
      for (std::size_t i = 0; i < robot.links.size(); ++i) {
        const std::size_t f = std::min<std::size_t>(i, static_cast<std::size_t>(chain.size()));
        const Eigen::Isometry3d T = chain.F_world_0() * now.F_0_i[f] *
                                    (chain.F_world_0() * home.F_0_i[f]).inverse(Eigen::Isometry) *
                                    placed.F_world_design;
        for (const auto& s : robot.links[i].segments) {
          CHECK(distance(lines[k], T * s.a, T * s.b) < 1e-6);
          CHECK(lines[k].part.kind == PartKind::Link);
          CHECK(lines[k].part.index == static_cast<int>(i));
          ++k;
        }
      }
    }
  }
}

TEST_CASE("Closing the gripper turns only the fingers, about their axes", "[render]") {
  const rs::workcell::Workcell cell = rendertest::cell("scorobot");
  const auto& robot = cell.robots.front().robot;
  REQUIRE(robot.hasGripper);
  CellPoser poser(cell);
  std::vector<std::int32_t> enc(robot.joints.size() + 1, 0);
  std::vector<Line3> open, closed;
  poser.lines(open);
  enc.back() = robot.gripper.max;
  poser.setEncoders(0, enc);
  poser.lines(closed);
  REQUIRE(open.size() == closed.size());
  int fingerLines = 0, moved = 0;
  for (std::size_t k = 0; k < open.size(); ++k) {
    const bool finger = open[k].part.kind == PartKind::Finger2 || open[k].part.kind == PartKind::Finger3;
    const double d = distance(closed[k], open[k].a, open[k].b);
    if (!finger) {
      CHECK(d < 1e-9);
      continue;
    }
    ++fingerLines;
    moved += d > 1e-3;
    // At home the design and world coordinates agree (the robot stands where
    // it was drawn): each point keeps its distance to its finger's axis.
    const auto& axis = open[k].part.kind == PartKind::Finger2 ? robot.gripper.model.r2 : robot.gripper.model.r3;
    const auto toAxis = [&](const Eigen::Vector3d& p) { return (p - axis.point).cross(axis.direction).norm(); };
    CHECK(toAxis(closed[k].a) == Approx(toAxis(open[k].a)).margin(1e-9));
    CHECK(toAxis(closed[k].b) == Approx(toAxis(open[k].b)).margin(1e-9));
  }
  CHECK(fingerLines > 0);
  CHECK(moved > 0);
}

TEST_CASE("A robot with a joint or a gripper has a tool mark, a bare one has none", "[render]") {
  rs::workcell::Workcell cell = rendertest::cell("scorobot");
  CHECK(CellPoser(cell).hasToolMark(0));
  CHECK(rs::render::makePicture(CellPoser(cell), {}, {}, {}).tools.size() == 1);
  cell.robots[0].robot.chain.reset();
  cell.robots[0].robot.hasGripper = false;
  const CellPoser bare(cell);
  CHECK_FALSE(bare.hasToolMark(0));
  CHECK(rs::render::makePicture(bare, {}, {}, {}).tools.empty());
}

TEST_CASE("AXES ON adds three lines per frame, 0..n, in x/y/z colours", "[render]") {
  const rs::workcell::Workcell cell = rendertest::cell("scorobot");
  const CellPoser poser(cell);
  std::vector<Line3> plain, axes;
  poser.lines(plain);
  poser.lines(axes, 50.0);
  const std::size_t frames = poser.frameCount(0);
  REQUIRE(axes.size() == plain.size() + 3 * frames);
  for (std::size_t k = plain.size(); k < axes.size(); ++k) {
    const Line3& l = axes[k];
    CHECK(l.part.kind == PartKind::Axis);
    CHECK((l.b - l.a).norm() == Approx(50.0));
    CHECK(l.color == rs::render::kAxisColors[l.part.axis]);
    CHECK((l.a - poser.frame(0, static_cast<std::size_t>(l.part.index)).translation()).norm() < 1e-12);
  }
}
