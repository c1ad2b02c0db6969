// Every warning a finished run gives, as diagnostics: the gripper that
// never took anything (runtime/run/empty_close.h) and, with
// --collisions=warn, each collision the run went on after. `run` and
// `check` print them (and `check --strict` fails on them), `animate` and
// `render --program` print them too; one list, so that no command forgets
// one kind.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "launch/program.h"
#include "runtime/run/run.h"

namespace rs::cli {

/// The run's warnings in the order of the run (collisions by time, then the
/// gripper's, which concerns the whole run). `mode` is the run's
/// --collisions: only Warn makes a collision a warning (with Error the one
/// found stopped the run and is its runtime error). `file`: the program's
/// name as diagnostics show it.
std::vector<diag::Diagnostic> runWarnings(const runtime::Run& run, runtime::CollisionMode mode,
                                          const std::string& file);

/// Prints `warnings` (at most --max-errors of them, then how many more):
/// what the compile left unprinted was said with the compile's.
void printRunWarnings(std::ostream& err, const std::vector<diag::Diagnostic>& warnings,
                      const launch::LoadedProgram& program);

/// --strict: each warning of `diags` becomes an error marked "[--strict]";
/// true when there was one.
bool promoteWarnings(std::vector<diag::Diagnostic>& diags);

}  // namespace rs::cli
