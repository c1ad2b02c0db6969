// The spec of a cell run of every PROGRAM a cell file names, compiled and
// prepared as `robotsim run --cell CELL` does: what the tests of cell runs
// start from.
#pragma once

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "runtime/run/cell_run.h"

namespace rs::testing {

inline runtime::CellRunSpec cellRunSpecOf(const std::string& cellFile) {
  launch::ProgramRequest request;
  request.cell = cellFile;
  launch::CellPrograms programs;
  REQUIRE(launch::assignCellPrograms(request, {}, programs));
  launch::compileAssignedPrograms(request, programs);
  REQUIRE(programs.ok());
  std::vector<diag::Diagnostic> diags;
  std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, {}, diags);
  REQUIRE(spec);
  return *spec;
}

}  // namespace rs::testing
