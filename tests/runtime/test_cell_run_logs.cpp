// Issue 36: in a cell run that keeps logs (CellRunSpec::log) every robot's
// log is its own: its steps and moves, and only its own gripper's takes and
// let-gos, although the world is shared. The relay example: the giver takes
// the bar, the taker takes it over from the giver, the giver opens (the
// taker has it), the taker puts it down (examples/two_robots/relay.rsd,
// its trace in docs/models.md). And render's moment of the cell
// (runtime/render/cell_moment.h) puts the bar where the world has it.
#include <catch2/catch.hpp>

#include <string>

#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "runtime/render/cell_moment.h"
#include "runtime/run/cell_run.h"
#include "tests/render/render_test_util.h"

namespace cell_run_logs_test {

rs::runtime::CellRunSpec relaySpec() {
  rs::launch::ProgramRequest request;
  request.cell = rendertest::kSourceDir + "/examples/two_robots/relay.rsd";
  rs::launch::CellPrograms programs;
  REQUIRE(rs::launch::assignCellPrograms(request, {}, programs));
  rs::launch::compileAssignedPrograms(request, programs);
  REQUIRE(programs.ok());
  std::vector<rs::diag::Diagnostic> diags;
  std::optional<rs::runtime::CellRunSpec> spec = rs::launch::prepareCellRun(programs, {}, diags);
  REQUIRE(spec);
  spec->log = true;
  return *spec;
}

}  // namespace cell_run_logs_test

using namespace cell_run_logs_test;

TEST_CASE("cell run logs: each robot's log keeps its own steps, moves and grasps only", "[cell-run][robots]") {
  rs::runtime::CellRun cell(relaySpec());
  REQUIRE(cell.runToEnd().ok());
  REQUIRE(cell.size() == 2);
  REQUIRE(cell.label(0) == "giver");
  REQUIRE(cell.label(1) == "taker");
  const rs::runtime::RunLog& giver = *cell.robot(0).log();
  const rs::runtime::RunLog& taker = *cell.robot(1).log();
  CHECK(giver.steps.size() == cell.robot(0).interpreter().steps());
  CHECK(taker.steps.size() == cell.robot(1).interpreter().steps());
  // The giver: it takes the bar, then lets go of it to the taker.
  REQUIRE(giver.grasps.size() == 2);
  for (const auto& g : giver.grasps) CHECK(g.event.hand == 0);
  CHECK(giver.grasps[0].event.held);
  CHECK_FALSE(giver.grasps[0].event.other);
  CHECK_FALSE(giver.grasps[1].event.held);
  CHECK(giver.grasps[1].event.other == std::optional<std::size_t>(1));
  // The taker: it takes the bar from the giver, later lets go onto the pallet.
  REQUIRE(taker.grasps.size() == 2);
  for (const auto& g : taker.grasps) CHECK(g.event.hand == 1);
  CHECK(taker.grasps[0].event.held);
  CHECK(taker.grasps[0].event.other == std::optional<std::size_t>(0));
  CHECK(taker.grasps[1].event.settled());
  // Each log ends when its robot ended.
  CHECK(giver.end == cell.endTime(0));
  CHECK(taker.end == cell.endTime(1));
}

TEST_CASE("cell moment: at the end every part is where the world has it", "[cell-run][robots][render]") {
  rs::runtime::CellRun cell(relaySpec());
  REQUIRE(cell.runToEnd().ok());
  const rs::render::CellMoment m = rs::render::cellMomentOf(cell, cell.clock());
  const auto world = cell.robot(0).rig().objects();
  REQUIRE(m.objects.size() == world.size());
  for (std::size_t o = 0; o < world.size(); ++o) {
    INFO("object " << o + 1);
    CHECK((m.objects[o].matrix() - world[o].pose.matrix()).cwiseAbs().maxCoeff() < 1e-9);
  }
  // Each robot's motors at the end are its machine's.
  for (std::size_t p = 0; p < cell.size(); ++p) {
    const auto motors = cell.robot(p).rig().motors();
    CHECK(m.encoders[cell.robot(p).rig().robotIndex()] == std::vector<std::int32_t>(motors.begin(), motors.end()));
  }
}
