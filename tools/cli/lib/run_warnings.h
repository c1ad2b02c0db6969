// How the commands print a run's warnings (the list itself is
// launch::runWarnings, shared with the language server): within
// --max-errors, and under `check --strict` as errors. `run`, `check`,
// `animate` and `render --program` use them, so that no command forgets
// one kind.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "launch/program.h"
#include "runtime/run/run.h"

namespace rs::cli {

/// Prints `warnings` (at most --max-errors of them, then how many more):
/// what the compile left unprinted was said with the compile's.
void printRunWarnings(std::ostream& err, const std::vector<diag::Diagnostic>& warnings,
                      const launch::LoadedProgram& program);

/// --strict: each warning of `diags` becomes an error marked "[--strict]";
/// true when there was one.
bool promoteWarnings(std::vector<diag::Diagnostic>& diags);

}  // namespace rs::cli
