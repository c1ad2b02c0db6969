// Points written as tool poses ("NAME AT x y z ..."): resolved by the
// compiler with the cell's robot. Expectations are worked out by hand from
// the cells' layouts (stdlib/workcells/*.rsd) and checked with forward
// kinematics (ToolTracker), which does not use the inverse kinematics.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "model/workcell/tool_tracker.h"
#include "vm/disasm.h"

namespace {

struct Cell {
  rs::workcell::Workcell cell;
  rs::compiler::Target target;
};

Cell loadCell(const std::string& name) {
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  auto cell = lib.workcell(name);
  REQUIRE(cell);
  Cell c{*cell, rs::launch::cellTarget(*cell)};
  REQUIRE(c.target.robot);
  return c;
}

rs::compiler::CompileResult compileFor(const Cell& c, const std::string& text) {
  const rs::diag::SourceFile source("p.rsp", text);
  return rs::compiler::compile(source, c.target);
}

std::string firstError(const rs::compiler::CompileResult& r) {
  REQUIRE_FALSE(r.diagnostics.empty());
  const auto& d = r.diagnostics.front();
  return fmt::format("{}:{}: {} [{}] hint: {}", d.pos.line, d.pos.col, d.message, d.code, d.hint);
}

Eigen::Vector3d tcpOf(const Cell& c, const std::vector<std::int32_t>& values) {
  rs::workcell::ToolTracker tracker(c.cell.robots.front());
  const auto p = tracker.tcp(values);
  return {p[0], p[1], p[2]};
}

}  // namespace

TEST_CASE("a pose point puts the tool where it says, in world and robot coordinates", "[compiler][pose]") {
  const Cell scara = loadCell("scara-pick");
  const auto r = compileFor(scara, "MOVEP A\nMOVEP B\nEND\nPOINTS\nA AT -130 800 0 GRIP 120\nB AT ROBOT -90 -75 -45\n");
  REQUIRE(r.ok());
  const auto& points = r.image->points;
  REQUIRE(points.size() == 2);
  // Whole encoder counts: 0.1175 deg on a 105 link and 0.2233 deg on a 120
  // one move the tool at most ~0.35 units, and joint C 0.06.
  CHECK((tcpOf(scara, points[0].values) - Eigen::Vector3d(-130, 800, 0)).norm() < 0.5);
  CHECK(points[0].values.back() == 120);  // GRIP
  CHECK(points[1].values.back() == 120);  // kept from A
  // The cell puts frame 0 (design (90, -125, 0)) AT 0 750 0: design coordinates are
  // world - (-90, 875, 0), as the home tool centre point shows: design (-135, -35, 0)
  // (robotsim where), world (-225, 840, 0) (the cell's comment).
  CHECK((tcpOf(scara, points[1].values) - Eigen::Vector3d(-180, 800, -45)).norm() < 0.5);
  CHECK(points[0].origin == "AT -130 800 0 GRIP 120");
  const std::string listing = rs::vm::disassemble(*r.image);
  CHECK(listing.find("A = ") != std::string::npos);
  CHECK(listing.find("(from AT ROBOT -90 -75 -45)") != std::string::npos);
}

TEST_CASE("a pose point's orientation is met on a six-axis arm", "[compiler][pose]") {
  const Cell puma = loadCell("puma-cell");
  // Above the table's first block (x 600..640, z -20..20, top y = 790), tool pointing down, fingers closing along z.
  const auto r = compileFor(puma, "MOVEP A\nEND\nPOINTS\nA AT 620 850 0 APPROACH 0 -1 0 NORMAL 0 0 1\n");
  REQUIRE(r.ok());
  rs::workcell::ToolTracker tracker(puma.cell.robots.front());
  const Eigen::Isometry3d F = tracker.frame(r.image->points[0].values);
  CHECK((F.translation() - Eigen::Vector3d(620, 850, 0)).norm() < 2.0);  // 0.1 degree counts on 430 mm links
  CHECK(F.linear().col(2).dot(Eigen::Vector3d(0, -1, 0)) > std::cos(0.5 * M_PI / 180));
  CHECK(F.linear().col(0).dot(Eigen::Vector3d(0, 0, 1)) > std::cos(0.5 * M_PI / 180));
}

TEST_CASE("of several solutions a pose point takes the quickest move from the previous point", "[compiler][pose]") {
  const Cell scara = loadCell("scara-pick");
  // The same pose after a point with joint D bent one way, then the other:
  // the elbow stays on the side it was.
  const auto plus = compileFor(scara, "END\nPOINTS\nP 0 300 0 0 0\nQ AT -130 800 0\n");
  const auto minus = compileFor(scara, "END\nPOINTS\nP 0 -300 0 0 0\nQ AT -130 800 0\n");
  REQUIRE(plus.ok());
  REQUIRE(minus.ok());
  CHECK(plus.image->points[1].values[1] > 0);
  CHECK(minus.image->points[1].values[1] < 0);
  // Both reach the same place.
  CHECK((tcpOf(scara, plus.image->points[1].values) - tcpOf(scara, minus.image->points[1].values)).norm() < 1.0);
}

TEST_CASE("pose points that cannot be reached are compile errors with the distance or the limit", "[compiler][pose]") {
  const Cell scara = loadCell("scara-pick");
  const auto error = [&](const std::string& point) { return firstError(compileFor(scara, "END\nPOINTS\n" + point + "\n")); };
  // Joint E's axis at x = z = 0; the links reach 120 - 105 = 15 to 225 from it.
  CHECK(error("P AT -600 800 0") ==
        "3:3: point P: the point is 375 out of the arm's reach (its links reach 15 to 225 from joint 1's axis) "
        "[pose-unreachable] hint: move the point within the ring the arm sweeps");
  CHECK(error("P AT 5 800 0").find("the point is 10 out of the arm's reach") != std::string::npos);
  // Straight out at 225: joint D straight.
  CHECK(error("P AT -225 820 0").find("near-singular pose: joint 2") != std::string::npos);
  // Joint C: d = 80 at home puts the tool at y = 840 - 80 + 80... each count 0.12 down; y = 100 needs far more than 350.
  CHECK(error("P AT -130 100 0").find("needs motor C at") != std::string::npos);
  CHECK(error("P AT -130 100 0").find("outside its range -350..350 [pose-out-of-range]") != std::string::npos);
  CHECK(error("P AT -130 800 0 APPROACH 1 0 0") ==
        "3:17: point P: the tool cannot take that orientation: its tool turns only about the axes of its joints (a "
        "SCARA) [pose-orientation] hint: here it reaches APPROACH 0 -1 0 NORMAL 1 0 0");
  CHECK(error("P AT -130 800 0 GRIP 500") ==
        "3:22: point P: GRIP 500 for motor A is outside its range 0..120 [pose-grip] hint: 0 is open, 120 closed");
  CHECK(error("P AT -130 800 0 APPROACH 0 -1 0 NORMAL 0 -1 0").find("NORMAL must be at right angles to APPROACH") !=
        std::string::npos);
  CHECK(error("P AT -130 800 0 APPROACH 0 0 0").find("APPROACH is a zero vector") != std::string::npos);
}

TEST_CASE("a pose point is read word by word with clear errors", "[compiler][pose]") {
  const Cell scara = loadCell("scara-pick");
  const auto error = [&](const std::string& point) { return firstError(compileFor(scara, "END\nPOINTS\n" + point + "\n")); };
  CHECK(error("P AT -130 800").find("AT expects three numbers (x y z), found 2") != std::string::npos);
  CHECK(error("P AT -130 800 0 GRIP 1 GRIP 2").find("point P: GRIP is written twice") != std::string::npos);
  CHECK(error("P AT -130 800 0 ELBOW UP").find("unexpected 'ELBOW' in a tool pose") != std::string::npos);
  CHECK(error("P AT -130 800 0 GRIP 1.5").find("a whole number") != std::string::npos);
  CHECK(error("P AT -130 800 0 APPROACH 0 -1").find("APPROACH expects three numbers") != std::string::npos);
  // Keywords are case-insensitive, like the rest of the language.
  CHECK(compileFor(scara, "END\npoints\np at world -130 800 0 grip 5\n").ok());
}

TEST_CASE("a pose point without a kinematic robot is refused with a hint", "[compiler][pose]") {
  const rs::diag::SourceFile source("p.rsp", "END\nPOINTS\nP AT 1 2 3\n");
  const auto r = rs::compiler::compile(source, rs::launch::defaultTarget());
  REQUIRE_FALSE(r.ok());
  CHECK(r.diagnostics.front().code == "pose-no-model");
  CHECK(r.diagnostics.front().hint.find("--cell") != std::string::npos);
}

TEST_CASE("a gantry pose point gives the counts its axes' formula gives", "[compiler][pose]") {
  // The gantry (stdlib/robots/gantry.rsd, motors X Z Y A, 0.1 per count):
  // tool centre point (500 + X/10, 200 - Y/10, 400 + Z/10) in the cell, so
  // AT 220 50 680 is X = -2800, Z = 2800, Y = 1500, exactly.
  const Cell gantry = loadCell("gantry-cell");
  const auto r = compileFor(gantry, "END\nPOINTS\nP AT 220 50 680 GRIP 100\nQ AT 220 50 680 APPROACH 0 -1 0\n");
  REQUIRE(r.ok());
  CHECK(r.image->points[0].values == std::vector<std::int32_t>{-2800, 2800, 1500, 100});
  CHECK(r.image->points[1].values == std::vector<std::int32_t>{-2800, 2800, 1500, 100});
  // A gantry never turns its tool: another approach is refused, with the one it has.
  CHECK(firstError(compileFor(gantry, "END\nPOINTS\nP AT 220 50 680 APPROACH 1 0 0\n")) ==
        "3:17: point P: the tool cannot take that orientation: its tool never turns: the orientation is fixed "
        "[pose-orientation] hint: here it reaches APPROACH 0 -1 0 NORMAL 1 0 0");
}
