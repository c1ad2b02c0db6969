// A straight-line move on a Rhino: the line planned by the cell's machine
// in front of the controller, sent as a stream of small moves, one after
// the other (each waited for), ending where the simulation ends. In
// process on the emulator with a manual clock, both dialects.
#include <catch2/catch.hpp>

#include <algorithm>

#include "compiler/description/library.h"
#include "launch/program.h"
#include "model/workcell/line_path.h"
#include "runtime/sim/sim_machine.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using namespace rs::rhino::testing;

// Over the XR-4's front block, then 30 straight up.
const char* const kSerialLineProgram =
    "        MOVEP ABOVE\n"
    "        DEPART 30\n"
    "        END\n"
    "POINTS\n"
    "ABOVE AT 240 870 -40 APPROACH 0 -1 0\n";

rs::workcell::Workcell lineCell() {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  auto cell = library.workcell("xr4-cell");
  REQUIRE(cell);
  return *cell;
}

RunResult runLineOn(const rs::vm::Image& image, const rs::workcell::Workcell& cell, rs::vm::Machine& machine) {
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  rs::runtime::Run run(std::move(spec), machine);
  RunResult r;
  r.outcome = run.runToEnd();
  r.positions.assign(machine.positions().begin(), machine.positions().end());
  return r;
}

}  // namespace

TEST_CASE("DEPART on a Rhino is a stream of small moves that ends where the simulation does", "[serial][straight]") {
  const rs::workcell::Workcell cell = lineCell();
  const rs::diag::SourceFile source("line.rsp", kSerialLineProgram);
  const rs::compiler::CompileResult compiled = rs::compiler::compile(source, rs::launch::cellTarget(cell));
  for (const auto& d : compiled.diagnostics) INFO(d.message);
  REQUIRE(compiled.ok());
  const rs::vm::Image& image = *compiled.image;

  // The knots, as the planner makes them from ABOVE.
  const rs::workcell::LinePlanner planner(cell.robots.front());
  rs::workcell::LinePath path(planner);
  REQUIRE_FALSE(planner.planAlongTool(image.points[0].values, -30, path, "DEPART"));
  REQUIRE(path.size() >= 2);

  rs::runtime::SimMachine sim(image.motors, {});
  const RunResult simulated = runLineOn(image, cell, sim);
  INFO(simulated.outcome.message);
  REQUIRE(simulated.outcome.ok());
  const auto last = path.knot(path.size() - 1);
  CHECK(simulated.positions == std::vector<std::int32_t>(last.begin(), last.end()));

  for (const Dialect d : {Dialect::Mark3, Dialect::Mark4}) {
    INFO((d == Dialect::Mark3 ? "Mark III" : "Mark IV"));
    LoopbackRig rig(testSettings(d), image.motors, emulatorFor(testSettings(d), image.motors));
    REQUIRE(rig.machine.open());
    const RunResult real = runLineOn(image, cell, rig.machine);
    INFO(real.outcome.message);
    REQUIRE(real.outcome.ok());
    CHECK(real.positions == simulated.positions);
    // One move for MOVEP and one per knot: on Mark IV each move is started
    // by one MI; on Mark III each knot's steps are their own commands,
    // polled until done before the next knot is sent.
    const std::vector<std::string> sent = sentCommands(rig.logText.str());
    if (d == Dialect::Mark4) {
      CHECK(static_cast<std::size_t>(std::count(sent.begin(), sent.end(), "MI")) == 1 + path.size());
    } else {
      std::size_t moves = 0;
      for (const std::string& c : sent) moves += (c.size() >= 3 && (c[1] == '+' || c[1] == '-')) ? 1 : 0;
      CHECK(moves >= path.size());
    }
  }
}
