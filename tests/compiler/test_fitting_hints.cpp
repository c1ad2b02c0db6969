// Hints that fit the program they are given to (issue 34): a library cell
// offered only where its robot has the program's motors; APPRO and DEPART,
// one segment along the tool's axis, not told to go through a via point;
// no rounding noise printed as a reach.
#include <catch2/catch.hpp>

#include <string>

#include "../render/render_test_util.h"
#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "stdlib/default_robot.h"
#include "tests/cli/cli_support.h"

namespace {

const rs::diag::Diagnostic& diagnosticCoded(const rs::compiler::CompileResult& r, std::string_view code) {
  for (const rs::diag::Diagnostic& d : r.diagnostics)
    if (d.code == code) return d;
  FAIL("no diagnostic " << code);
  return r.diagnostics.front();
}

}  // namespace

TEST_CASE("the hint of a straight line or a pose on motors alone names a cell only where its robot has those motors",
          "[compiler][hints]") {
  const std::string program = "        MOVES P\n        END\nPOINTS\nP 0 0 0 0 0\nQ AT 1 2 3\n";
  SECTION("the default robot: scara-pick, whose robot it is, never xr4-cell (six motors)") {
    const auto r = rs::compiler::compile(rs::diag::SourceFile("p.rsp", program), rs::launch::defaultTarget());
    for (const std::string_view code : {"needs-kinematics", "pose-no-model"}) {
      const rs::diag::Diagnostic& d = diagnosticCoded(r, code);
      INFO(d.hint);
      CHECK(d.hint.find("--cell scara-pick (its robot has these 5 motors)") != std::string::npos);
      CHECK(d.hint.find("xr4-cell") == std::string::npos);
    }
    // What the hint claims: scara-pick's robot has the default robot's motors, with a kinematic model.
    const rs::compiler::Target cell = rs::launch::cellTarget(rendertest::cell(std::string(rs::stdlib::rhinoScaraCellName())));
    CHECK(cell.motors == rs::stdlib::rhinoScaraMotors());
    CHECK(cell.robot != nullptr);
  }
  SECTION("motors no library cell is known to have: no cell named, the motor count said") {
    rs::compiler::Target three{"slides", {}, rs::vm::kDefaultCallDepth};
    for (const char letter : {'X', 'Y', 'Z'}) three.motors.push_back({letter, rs::vm::JointKind::Prismatic, 1, -10, 10, 5});
    const auto r = rs::compiler::compile(
        rs::diag::SourceFile("p.rsp", "        MOVES P\n        END\nPOINTS\nP 0 0 0\n"), three);
    const rs::diag::Diagnostic& d = diagnosticCoded(r, "needs-kinematics");
    INFO(d.hint);
    CHECK(d.hint.find("--cell NAME, a cell whose robot has these 3 motors") != std::string::npos);
    CHECK(d.hint.find("scara-pick") == std::string::npos);
    CHECK(d.hint.find("xr4-cell") == std::string::npos);
  }
}

TEST_CASE("APPRO and DEPART that meet a limit are not told to go through a via point, MOVES still is",
          "[compiler][hints][straight]") {
  // xr4-cell: the tool pointing straight out along the world's x from (250, 1100, 0): APPRO 400 stretches the
  // elbow straight about 92% of the way (joints 2 and 3 reach at most 457.2), a singular pose on the one segment
  // APPRO can take. A MOVES from there down to (300, 600, 0), the tool pointing down, takes motor C (the wrist's
  // pitch) out of its range on the way: a via point can take it round.
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const rs::compiler::Target target = rs::launch::cellTarget(cell);
  const auto appro = rs::compiler::compile(
      rs::diag::SourceFile("p.rsp", "        MOVEP OUT\n        APPRO 400\n        END\nPOINTS\n"
                                    "OUT     AT 250 1100 0 APPROACH 1 0 0\n"),
      target);
  REQUIRE_FALSE(appro.ok());
  const rs::diag::Diagnostic& a = appro.diagnostics.front();
  INFO(a.message << " / " << a.hint);
  CHECK(a.code == "line-singular");
  CHECK(a.message.rfind("APPRO ", 0) == 0);
  CHECK(a.hint.find("go through a via point") == std::string::npos);
  CHECK(a.hint == "APPRO is one straight segment along the tool's approach axis, which no via point changes: start "
                  "it from another pose, or make this move a joint move (MOVEP)");
  const auto moves = rs::compiler::compile(
      rs::diag::SourceFile("p.rsp", "        MOVEP OUT\n        MOVES FAR\n        END\nPOINTS\n"
                                    "OUT     AT 250 1100 0 APPROACH 1 0 0\nFAR     AT 300 600 0 APPROACH 0 -1 0\n"),
      target);
  REQUIRE_FALSE(moves.ok());
  const rs::diag::Diagnostic& m = moves.diagnostics.front();
  INFO(m.message << " / " << m.hint);
  CHECK(m.message.rfind("MOVES takes motor C to ", 0) == 0);
  CHECK(m.hint.find("go through a via point") != std::string::npos);
}

TEST_CASE("an arm whose two links are equal reaches from 0, not from rounding noise", "[compiler][hints][ik]") {
  // The XR-4's upper arm and forearm are both 228.6: |228.6 - 228.6| computed in floating point was 2.842e-14.
  const auto r = rs::testing::runCli({"ik", "xr4-cell", "--", "2000", "800", "0"});
  INFO(r.err);
  CHECK(r.code != 0);
  CHECK(r.err.find("(joints 2 and 3 reach 0 to 457.2 from joint 2)") != std::string::npos);
  CHECK(r.err.find("e-14") == std::string::npos);
}
