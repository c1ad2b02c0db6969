// Issue 36, the cell run itself (runtime/run/cell_run.h), through launch's
// loading of a cell's programs: zero-time ping-pong between two robots
// ends with an error naming the wires, and a rule between two robots'
// lines is refused with the WIRE to write instead.
#include <catch2/catch.hpp>

#include <string>

#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "runtime/run/cell_run.h"
#include "tests/cli/cli_support.h"

namespace cell_run_api_test {

const char* const kCell =
    "WORKCELL two\n"
    "  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM left.rsp\n"
    "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM right.rsp\n"
    "  WIRE left.OUT 1 TO right.IN 2\n"
    "  WIRE right.OUT 1 TO left.IN 1\n"
    "END\n";

std::optional<rs::runtime::CellRunSpec> specOf(const rs::testing::TempDir& dir, rs::launch::RunRequest run,
                                               std::vector<rs::diag::Diagnostic>& diags) {
  rs::launch::ProgramRequest request;
  request.cell = dir.file("c.rsd");
  rs::launch::CellPrograms programs;
  REQUIRE(rs::launch::assignCellPrograms(request, {}, programs));
  rs::launch::compileAssignedPrograms(request, programs);
  REQUIRE(programs.ok());
  return rs::launch::prepareCellRun(programs, run, diags);
}

}  // namespace cell_run_api_test

using namespace cell_run_api_test;

TEST_CASE("cell run api: zero-time ping-pong between two robots ends naming the wires", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  // Each answers the other at once: the clock never moves.
  dir.write("left.rsp", "loop:   OUTSIG 1 ON\n        WAITFOR 1 ON\n        OUTSIG 1 OFF\n        WAITFOR 1 OFF\n"
                        "        SET X 0\n        JMPVAR X = 0 loop\n        END\n");
  dir.write("right.rsp", "loop:   WAITFOR 2 ON\n        OUTSIG 1 ON\n        WAITFOR 2 OFF\n        OUTSIG 1 OFF\n"
                         "        SET X 0\n        JMPVAR X = 0 loop\n        END\n");
  std::vector<rs::diag::Diagnostic> diags;
  std::optional<rs::runtime::CellRunSpec> spec = specOf(dir, {}, diags);
  REQUIRE(spec);
  spec->limits.maxStepsPerInstant = 20'000;
  rs::runtime::CellRun cell(*spec);
  const rs::vm::RunOutcome outcome = cell.runToEnd();
  CHECK(outcome.reason == rs::vm::StopReason::InstantLimit);
  REQUIRE(cell.failed());
  INFO(outcome.message);
  CHECK(outcome.message.find("without the simulated clock moving") != std::string::npos);
  CHECK((outcome.message.find("left.OUT 1 TO right.IN 2 (line 4)") != std::string::npos ||
         outcome.message.find("right.OUT 1 TO left.IN 1 (line 5)") != std::string::npos));
  CHECK(cell.clock() == 0);
  // The other robot was stopped with the cell.
  CHECK(cell.end(1 - *cell.failed()) == rs::runtime::RobotEnd::Stopped);
}

TEST_CASE("cell run api: a stimuli rule between two robots is refused with the WIRE to write", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("left.rsp", "        END\n");
  dir.write("right.rsp", "        END\n");
  dir.write("s.stim", "when output left.3 on then input right.4 on\nat 1 input right.5 on\n");
  rs::launch::RunRequest run;
  run.stimuliFile = dir.file("s.stim");
  std::vector<rs::diag::Diagnostic> diags;
  CHECK_FALSE(specOf(dir, run, diags));
  REQUIRE_FALSE(diags.empty());
  CHECK(diags.back().message.find("line 1: a rule from one robot's output to another's input is not run yet: write a "
                                  "WIRE left.OUT 3 TO right.IN 4 in the cell instead") != std::string::npos);
}

TEST_CASE("cell run api: each robot gets its own labelled stimuli", "[cell-run][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("left.rsp", "        WAITFOR 3 ON\n        END\n");
  dir.write("right.rsp", "        WAITFOR 5 ON\n        END\n");
  dir.write("s.stim", "at 1.5 input left.3 on\nat 2.5 input right.5 on\n");
  rs::launch::RunRequest run;
  run.stimuliFile = dir.file("s.stim");
  std::vector<rs::diag::Diagnostic> diags;
  const std::optional<rs::runtime::CellRunSpec> spec = specOf(dir, run, diags);
  REQUIRE(spec);
  rs::runtime::CellRun cell(*spec);
  CHECK(cell.runToEnd().ok());
  CHECK(cell.endTime(0) == 1'500'000);  // left, at its stimulus
  CHECK(cell.endTime(1) == 2'500'000);  // right, at its own
}
