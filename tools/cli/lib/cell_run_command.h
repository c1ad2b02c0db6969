// `robotsim run --cell CELL [LABEL=FILE ...]`, and `robotsim run PROG
// --cell CELL` on a cell where other robots have PROGRAMs too: every robot
// with a program runs it on the cell's one clock (runtime/run/cell_run.h).
// The summary has a section per robot and the cell's lines once; the JSON
// summary a `robots` list; the trace prefixes each line with the robot's
// label (text) or gives it as a `robot` field (JSON).
#pragma once

#include <optional>
#include <ostream>

#include "runtime/run/cell_run.h"
#include "tools/cli/lib/run_command.h"

namespace rs::cli {

/// The cell run `o` asks for, and its exit code; nullopt when `o` is a run
/// of one robot (a program file, and no other robot of the cell has a
/// program), which runOrCheck does as always.
/// With `check`, the same as `check` does it: one line per robot when all
/// is well, --strict's warnings failing it, and nullopt when a program does
/// not compile (each is then checked alone, in its own file).
/// `readCell`, when given, gets the cell read to decide a run of one, for
/// that run's load (launch::ProgramRequest::loadedCell): read once, not twice.
std::optional<int> runCellIfSeveral(const RunCommandOptions& o, bool check, std::ostream& out, std::ostream& err,
                                    std::shared_ptr<const launch::LoadedCell>* readCell = nullptr);

/// What the cell's stop says, as diagnostics: the failing robot's own words
/// at its line (launch/run_diagnostics.h), or the deadlock or limit at the
/// first waiting robot's line. Also what render, animate and plot of a
/// cell print (cell_draw.h).
std::vector<diag::Diagnostic> cellRunDiagnostics(const runtime::CellRun& cell, const vm::RunOutcome& outcome,
                                                 runtime::CollisionMode collisions);

}  // namespace rs::cli
