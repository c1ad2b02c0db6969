// Which programs a program's checked run runs with (issue 36): in a cell
// where other robots have a PROGRAM, the program is checked by running
// the whole cell, as `robotsim check PROG --cell CELL` does, the program
// on its robot (launch/robot_choice.h: its `; robot:` line, else the robot
// whose PROGRAM it is, else the first) and every other robot's PROGRAM
// beside it: the text of its open document first, else its file. The
// workspace makes the plan (workspace.h), the run worker runs it
// (cell_checked_run.h), and the server publishes what it found in each
// program to that program's own document when it can.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/workcell/model.h"
#include "tools/lsp/document.h"
#include "tools/lsp/json.h"
#include "vm/image.h"

namespace rs::lsp {

class ProgramAnalysis;

/// Another robot's program in the cell run.
struct CellPartner {
  std::size_t robot = 0;  ///< its robot's index in the cell as written
  std::string label;      ///< that robot's label
  std::string file;       ///< its program's file (the PROGRAM's path)
  /// Compiled for that robot: the open document's own analysis when the
  /// document is checked as that robot of this cell, else one made for the
  /// run; null for a compiled image (`image` alone).
  std::shared_ptr<const ProgramAnalysis> analysis;
  std::shared_ptr<const vm::Image> image;  ///< what runs
  /// The open document checked as this robot of this cell: it shows what
  /// the run finds in it itself (the run is its run when `claimed`, else it
  /// makes its own); otherwise the program the run is made for shows it.
  std::string uri;
  bool claimed = false;             ///< this run is that document's run (its analysis asked for it)
  std::int64_t version = 0;         ///< the claimed document's version
  Json compileDiagnostics;          ///< the claimed document's, as published for that version
};

struct CellRunPlan {
  std::shared_ptr<const workcell::Workcell> cell;  ///< as its file writes it (the robots' order)
  std::size_t robot = 0;                           ///< the program's own robot in it
  std::vector<CellPartner> partners;               ///< in the cell's order
  /// Why the cell cannot run ("" = it can): another robot's program has
  /// errors or cannot be read; a note on the program's first line says so.
  std::string problem;
  /// Whether the program is checked with others at all (else alone, as before).
  bool active() const { return !partners.empty() || !problem.empty(); }
};

}  // namespace rs::lsp
