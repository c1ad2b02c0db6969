// MOVES, APPRO and DEPART run on a workcell: the knots and their timing
// worked out by hand on the gantry (a Cartesian arm, whose straight line
// is straight in its joints too), the run log replaying the knots, the
// run-time path check in the compile-time check's words.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "../render/render_test_util.h"
#include "runtime/run/run.h"
#include "runtime/run/run_log.h"
#include "vm/image_file.h"
#include "vm/verify.h"

namespace {

// Pause once this many instructions have run.
rs::runtime::RunUntil lineStepsUntil(std::uint64_t steps) {
  rs::runtime::RunUntil until;
  until.steps = steps;
  return until;
}

using rs::vm::Micros;

constexpr Micros kLineSecond = 1'000'000;

struct LineRun {
  std::unique_ptr<rs::runtime::Run> run;
  rs::vm::RunOutcome outcome;
};

LineRun runLine(const std::string& cellName, const std::string& program) {
  const rs::workcell::Workcell cell = rendertest::cell(cellName);
  LineRun r;
  r.run = rendertest::runOf(rendertest::compileText(program, cell), &cell, {}, true);
  r.outcome = r.run->runToEnd();
  return r;
}

std::string compileMessage(const std::string& cellName, const std::string& program) {
  const rs::workcell::Workcell cell = rendertest::cell(cellName);
  const rs::diag::SourceFile source("line.rsp", program);
  const rs::compiler::CompileResult p = rs::compiler::compile(source, rs::launch::cellTarget(cell));
  REQUIRE_FALSE(p.ok());
  REQUIRE(!p.diagnostics.empty());
  return p.diagnostics.front().message;
}

}  // namespace

TEST_CASE("MOVES on the gantry: four knots in lock-step, timed by hand", "[runtime][straight]") {
  // Motors X Z Y A, 0.1 length units a count, X and Z at 1000 counts/s.
  // X 0 -> 40 and Z 0 -> 16: a straight line in the joints too, so the
  // first step the planner tries, a quarter of the line, passes its chord
  // check, and its knot moves the tool 1 + 0.4 = 1.4 with each motor on
  // its own (at most kKnotTravel, 2): knots (10, 4), (20, 8), (30, 12),
  // (40, 16). Each takes its slowest motor at full speed, 10 counts at
  // 1000/s = 10 ms, and the other motor keeps pace: 5 ms in, X is at
  // 10 * 5 / 10 = 5 and Z at 4 * 5 / 10 = 2 (a MOVETO would have Z at 5
  // by then, off the line). Both motors carry the tool forward along the
  // line, so in the first half of the line both lead (each takes a count as
  // soon as it is begun), in the second half neither does (each takes it
  // when it is done). 27 ms in: the third knot, 7 ms of 10: X 20 + 7 = 27,
  // Z 8 + floor(4 * 7 / 10) = 10. 3 ms in, Z is at ceil(4 * 3 / 10) = 2.
  // The whole line 40 ms.
  const LineRun r = runLine("gantry-cell", "        MOVES DIAG\n        END\nPOINTS\nDIAG 40 16 0 0\n");
  INFO(r.outcome.message);
  REQUIRE(r.outcome.ok());
  const rs::runtime::RunLog& log = *r.run->log();
  REQUIRE(log.steps.size() >= 1);
  constexpr Micros kMs = 1000;
  CHECK(log.steps[0].start == 0);
  CHECK(log.steps[0].end == 40 * kMs);
  REQUIRE(log.moves[0].size() == 4);
  REQUIRE(log.moves[1].size() == 4);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto x = static_cast<std::int32_t>(10 * (k + 1)), z = static_cast<std::int32_t>(4 * (k + 1));
    CHECK(log.moves[0][k].to == x);
    CHECK(log.moves[1][k].to == z);
    CHECK(log.moves[0][k].start == static_cast<Micros>(k) * 10 * kMs);
    CHECK(log.moves[0][k].end == static_cast<Micros>(k + 1) * 10 * kMs);
    CHECK(log.moves[0][k].lockStep);
  }
  CHECK(rs::runtime::stateAt(log, 5 * kMs).encoders == std::vector<std::int32_t>{5, 2, 0, 0});
  CHECK(rs::runtime::stateAt(log, 27 * kMs).encoders == std::vector<std::int32_t>{27, 10, 0, 0});
  CHECK(rs::runtime::stateAt(log, 3 * kMs).encoders == std::vector<std::int32_t>{3, 2, 0, 0});
  CHECK(log.moves[1][0].lead);
  CHECK_FALSE(log.moves[1][2].lead);
  CHECK(r.run->rig().motors()[0] == 40);
}

TEST_CASE("APPRO and DEPART move the tool along its approach axis and back", "[runtime][straight]") {
  // The gantry's tool points down (approach (0, -1, 0) in the world): APPRO
  // 20 lowers the tool centre point by 20, 200 counts of its Y motor, and
  // DEPART 20 brings it back to where it was. Knots of at most 2 length
  // units (kKnotTravel): 16 of 12.5 counts, rounded to 13 or 12, summing
  // to 200.
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  auto run = rendertest::runOf(rendertest::compileText("APPRO 20\nDEPART 20\nEND\n", cell), &cell, {}, true);
  const auto home = run->rig().tcp();
  REQUIRE(home);
  REQUIRE(run->runUntil(lineStepsUntil(1)).paused());
  const auto low = run->rig().tcp();
  REQUIRE(low);
  CHECK(std::abs((*low)[0] - (*home)[0]) < 1e-9);
  CHECK(std::abs((*low)[1] - ((*home)[1] - 20)) < 1e-9);
  CHECK(std::abs((*low)[2] - (*home)[2]) < 1e-9);
  const rs::vm::RunOutcome end = run->runToEnd();
  INFO(end.message);
  REQUIRE(end.ok());
  const auto back = run->rig().tcp();
  for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs((*back)[i] - (*home)[i]) < 1e-9);
  // Each knot ceil(counts * 10^6 / 800) = counts * 1250 us: 200 counts, 0.25 s each way.
  CHECK(run->rig().clock() == kLineSecond / 2);
}

TEST_CASE("a line whose start only the run knows is checked when it starts, in the compiler's words",
          "[runtime][straight]") {
  // Across joint 1's axis of the XR-4 (its base at x 0, z 0): the line
  // from one side of the base to the other passes over the axis, where
  // the base would have to turn half a turn at once.
  const std::string points =
      "POINTS\n"
      "A AT 120 950 -120 APPROACH 0 -1 0\n"
      "B AT -120 950 120 APPROACH 0 -1 0\n";
  const std::string atCompile = compileMessage("xr4-cell", "        MOVEP A\n        MOVES B\n        END\n" + points);
  CHECK(atCompile.find("MOVES ") == 0);
  CHECK(atCompile.find("along the line") != std::string::npos);
  // A jump to MOVES: the compiler does not follow where the arm stands
  // across jumps, so it does not know where this line starts; the run
  // finds the same problem when the line starts.
  const LineRun r = runLine("xr4-cell", "        MOVEP A\n        GOTO across\nacross: MOVES B\n        END\n" + points);
  CHECK(r.outcome.reason == rs::vm::StopReason::RuntimeError);
  CHECK(r.outcome.index == 2);
  CHECK(r.outcome.message == atCompile);
}

TEST_CASE("an image with straight-line moves round-trips, and the verifier holds APPRO and DEPART to 1..100000",
          "[runtime][straight][vm]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  rs::vm::Image image = rendertest::compileText(
      "MOVEP A\nMOVES B\nAPPRO 5\nDEPART 7\nEND\nPOINTS\nA AT 240 870 -40 APPROACH 0 -1 0\n"
      "B AT 240 850 -40 APPROACH 0 -1 0\n",
      cell);
  CHECK(rs::vm::verify(image).message.empty());
  const std::vector<std::uint8_t> bytes = rs::vm::writeImage(image);
  const auto loaded = rs::vm::loadImage(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  REQUIRE(loaded.ok());
  CHECK(loaded.value().code == image.code);
  CHECK(image.code[2].c == 5);
  CHECK(image.code[3].c == 7);
  image.code[2].c = 0;
  CHECK(rs::vm::verify(image).message == "instruction 3 (APPRO): distance 0 outside 1..100000");
  image.code[2].c = 100001;
  CHECK(rs::vm::verify(image).message == "instruction 3 (APPRO): distance 100001 outside 1..100000");
  image.code[2].c = 5;
  image.code[3].a = 1;
  CHECK(rs::vm::verify(image).message == "instruction 4 (DEPART): unused operand fields are not zero");
}
