// What a finished run says as diagnostics: the one place where a run's end
// (a runtime error, a collision that stopped it, a deadlock, a step, time
// or clock limit) and its warnings (collisions under --collisions=warn, the
// empty gripper) become diag::Diagnostics. `robotsim
// run` and `check` print them, `render --program` and `animate` too, and
// the language server underlines them in the editor: what the editor shows
// is what `check` says, from this code.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/run.h"
#include "vm/image.h"
#include "vm/interpreter.h"

namespace rs::launch {

/// The hint of a deadlock across the robots of a cell (`run --cell`, the
/// language server's cell run).
inline constexpr const char* kCellDeadlockHint =
    "a robot waits for an input that only another waiting robot's output drives: change the order of an OUTSIG "
    "and a WAITFOR in one program";

/// A run that stopped early, as an error at the instruction's source
/// position: "collision: collision at 1.2 s: link 2 ... (instruction 7)",
/// with a hint where the command line can help (--max-steps, --input).
diag::Diagnostic stopDiagnostic(const vm::Image& image, const vm::RunOutcome& outcome, const std::string& file);

/// The run's warnings in the order of the run: with `mode` Warn, each
/// collision the run went on after (by time; with Error the one found
/// stopped the run and is its stop), then the gripper that never took an
/// object (runtime/run/empty_close.h), which concerns the whole run.
std::vector<diag::Diagnostic> runWarnings(const runtime::Run& run, runtime::CollisionMode mode,
                                          const std::string& file);

/// Everything a finished run reports, in the order `check` prints it: its
/// stop when it did not end well, then its warnings. `mode` is the run's
/// --collisions; `file` names the program.
std::vector<diag::Diagnostic> runDiagnostics(const runtime::Run& run, runtime::CollisionMode mode,
                                             const std::string& file);

}  // namespace rs::launch
