// Which robots of a cell run which programs (issue 36): the cell's
// `PROGRAM FILE` lines, then the program named on the command line on the
// robot it names (robot_choice.h), then each `LABEL=FILE` given. Each
// program is compiled for its own robot, exactly as for a run of one.
// prepareCellRun (run_request.h) turns the result into a cell run.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "launch/program.h"
#include "runtime/run/cell_run.h"

namespace rs::launch {

struct CellPrograms {
  std::shared_ptr<const workcell::Workcell> cell;  ///< as its file gives it: robots in the cell's order
  LoadedProgram cellLoad;                          ///< the cell's own diagnostics and description texts
  std::vector<std::string> labels;                 ///< per program: its robot's label
  std::vector<std::string> files;                  ///< per program: its file
  std::vector<LoadedProgram> loaded;               ///< per program, in the cell's robot order
  std::vector<runtime::CellProgram> programs;      ///< per program: its robot and image (once compiled)
  /// Every problem so far is in cellLoad or a program's own diagnostics.
  bool ok() const;
  /// Every diagnostic so far: the cell's, then each program's.
  std::vector<diag::Diagnostic> allDiagnostics() const;
  /// The same, each said once: every program's load read the cell again,
  /// so the cell's warnings would come once a program.
  std::vector<diag::Diagnostic> diagnosticsOnce() const;
  /// The diagnostic's file's text, from whichever load read it.
  const diag::SourceFile* sourceOf(const std::string& file) const;
};

/// Whether `arg` is a `LABEL=FILE` assignment rather than a program file.
bool isProgramAssignment(std::string_view arg);

/// The programs of `request.cell`: its PROGRAMs, `request.file` (if any)
/// on its robot, then `assignments` (`LABEL=FILE`). False (and nothing
/// compiled) when the cell does not load, an assignment is malformed or
/// names no robot of the cell (an error with the cell's labels as hint).
/// True with no programs: `request.file` alone on a cell where no other
/// robot has a PROGRAM (a run of one robot, as always).
bool assignCellPrograms(const ProgramRequest& request, std::span<const std::string> assignments, CellPrograms& into);

/// Compiles every assigned program for its robot (into.loaded, into.programs).
void compileAssignedPrograms(const ProgramRequest& request, CellPrograms& into);

}  // namespace rs::launch
