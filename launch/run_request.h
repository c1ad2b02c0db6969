// The options of a run that are not the program: its input stimuli
// (`--stimuli FILE`, `--input N=ON@T`), its limits (`--max-steps`,
// `--max-time`, `--max-knots`), whether it keeps a log. `prepareRun` turns them and a
// loaded program into a runtime::RunSpec, every problem a diagnostic.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "launch/cell_programs.h"
#include "launch/program.h"
#include "runtime/run/run.h"
#include "compiler/stimuli/stimuli.h"

namespace rs::launch {

struct RunRequest {
  std::string stimuliFile;             ///< --stimuli
  std::vector<std::string> inputs;     ///< --input N=ON@T, in order
  std::optional<std::uint64_t> maxSteps;  ///< --max-steps; unset: the command's default
  std::optional<std::uint64_t> maxKnots;  ///< --max-knots; unset: vm::RunLimits's
  std::string maxTime;                 ///< --max-time in seconds; empty: not given (3600)
  std::string collisions;              ///< --collisions error|warn|off; empty: not given (error)
  /// The option names, in the order given, that belong to a run (for
  /// commands that run only with --program): the first set one, or "".
  std::string_view firstGiven() const;
};

/// Stimuli from the stimuli file (when named) and the --input changes, in
/// that order; every error becomes a diagnostic. False on any error.
bool loadStimuli(const RunRequest& request, stimuli::Stimuli& stimuli, std::vector<diag::Diagnostic>& diags);

/// --collisions' mode (error when not given), or a diagnostic.
std::optional<runtime::CollisionMode> collisionsOf(const RunRequest& request, std::vector<diag::Diagnostic>& diags);

/// --max-time's microseconds (3600 s when not given), or a diagnostic.
std::optional<vm::Micros> maxTimeOf(const RunRequest& request, std::vector<diag::Diagnostic>& diags);

/// The run of `program` (which must be ok()) with the request's stimuli and
/// limits; nullopt, with the diagnostics, when any of them is bad.
/// `defaultMaxSteps` applies when --max-steps is not given.
std::optional<runtime::RunSpec> prepareRun(const LoadedProgram& program, const RunRequest& request,
                                           std::vector<diag::Diagnostic>& diags,
                                           std::uint64_t defaultMaxSteps = vm::RunLimits{}.maxSteps);

/// The same for a cell of several robots running together
/// (cell_programs.h): one set of stimuli (labels name the robots), limits
/// per robot, the cell's time limit.
std::optional<runtime::CellRunSpec> prepareCellRun(const CellPrograms& programs, const RunRequest& request,
                                                   std::vector<diag::Diagnostic>& diags,
                                                   std::uint64_t defaultMaxSteps = vm::RunLimits{}.maxSteps);

}  // namespace rs::launch
