// The editor's checked run of a program in a cell where other robots have
// programs (issue 36): the whole cell run together, as `robotsim check
// PROG --cell CELL` runs it (launch::prepareCellRun, runtime::CellRun), on
// the run worker's thread, bounded and abandoned as the run of one program
// is (checked_run.h). What it finds goes to the program it belongs to: a
// runtime error or a collision to the program of the robot that made it
// (the moving one), the deadlock to every waiting robot's program at its
// line, the time limit likewise. What belongs to another robot's program
// whose document does not show it (not open, or checked as another robot)
// is said in the program the run is made for, naming that robot, its file
// and line.
#pragma once

#include <chrono>
#include <vector>

#include "tools/lsp/cell_run_plan.h"
#include "tools/lsp/checked_run.h"

namespace rs::lsp {

/// The cell run of `analysis` (which compiled) with the plan's other
/// programs: one CheckedRun per program, the program's own first, then
/// each partner's in the plan's order.
std::vector<CheckedRun> checkCellRun(const ProgramAnalysis& analysis, const CellRunPlan& plan,
                                     const RunOptions& options, RunControl& control,
                                     std::chrono::milliseconds budget = kRunBudget);

}  // namespace rs::lsp
