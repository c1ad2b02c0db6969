// `render --at`, `animate` and `plot` of a cell whose robots run programs
// together (issue 36, docs/models.md "Several robots on one clock"): the
// programs are chosen as `run --cell` chooses them (the cell's PROGRAMs,
// the program file on its robot, LABEL=FILE), and the cell runs with every
// robot keeping its own log, so that each is drawn where its motors are.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "launch/cell_programs.h"
#include "launch/program.h"
#include "launch/run_request.h"
#include "runtime/render/cell_chart.h"
#include "runtime/run/cell_run.h"

namespace rs::cli {

/// A cell run of several robots, ready to run, its diagnostics so far printed.
struct CellDraw {
  launch::CellPrograms programs;
  runtime::CellRunSpec spec;              ///< every robot keeps its log
  std::unique_ptr<runtime::CellRun> run;  ///< made of spec by runCellDraw
};

/// What a drawing command runs for `request` and `assignments` (LABEL=FILE;
/// a program file that does not exist but reads as one counts too).
struct CellDrawChoice {
  std::optional<int> exit;                    ///< bad input (printed): the exit code
  std::optional<launch::ProgramRequest> one;  ///< one robot has a program: run this, as a run of one
  std::unique_ptr<CellDraw> several;          ///< the cell run
};

/// nullopt when `request` is a run of one robot as always (no cell, or no
/// other robot of it has a program). `lines` is how the logs keep straight
/// lines' knots (a page or a chart thins them).
std::optional<CellDrawChoice> chooseCellDraw(const launch::ProgramRequest& request,
                                             std::vector<std::string> assignments, const launch::RunRequest& run,
                                             std::uint64_t defaultMaxSteps, runtime::LineThinning lines,
                                             std::ostream& err);

/// Runs the cell to its end (or the cell's stop), then prints what the
/// run said (its errors and warnings); the cell's outcome. With `until`
/// (a still's --at) the cell's time limit is then, and stopping there is
/// no failure: nothing is printed of it.
vm::RunOutcome runCellDraw(CellDraw& draw, std::ostream& err, std::optional<vm::Micros> until = std::nullopt);

/// The cell's chart (runtime/render/cell_chart.h) of a finished cell run:
/// each robot's lanes with its marks (collisions, warnings, its stop).
render::Chart cellChart(const CellDraw& draw, const vm::RunOutcome& outcome, vm::Micros every);

/// "left.rsp, right.rsp on interlock": what a cell's picture, page or chart is of.
std::string cellDrawTitle(const CellDraw& draw);

}  // namespace rs::cli
