// `robotsim check --cell CELL` and `robotsim compile --cell CELL -o DIR`
// without a program file: every program the cell's ROBOT lines name
// (`PROGRAM FILE`), each compiled for its own robot and reported in its
// own file, as if `check FILE --cell CELL --robot LABEL` had been run for
// each. A cell's robots do not yet run together (docs/models.md): check
// runs each program with the other robots standing at home.
#pragma once

#include <ostream>

#include "tools/cli/lib/program_commands.h"
#include "tools/cli/lib/run_command.h"

namespace rs::cli {

/// check of every PROGRAM of --cell; the worst exit code of them.
int checkCellPrograms(const RunCommandOptions& o, std::ostream& out, std::ostream& err);

/// compile of every PROGRAM of --cell into the folder -o names (made if
/// missing), each as its file's stem + .rsb; the worst exit code.
int compileCellPrograms(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err);

}  // namespace rs::cli
