// What a run says about a gripper that closed on nothing: the one place
// that words it and decides when it is worth a warning. The trace
// (`run --trace`, `debug`), the run's diagnostics (`run`, `check`,
// `animate`, `render --program`) and the test runner all read it here.
//
// The rule (docs/models.md, "Objects in the gripper"): on a workcell with
// objects, a closing move that takes nothing is noted by the World; a run
// that closed the gripper at least once and never took an object gets a
// warning at the first such close. A cell without objects has nothing to
// take and gets neither.
#pragma once

#include <optional>
#include <string>

#include "diag/diagnostic.h"
#include "runtime/run/run.h"

namespace rs::runtime {

/// "nearest: block (object 2), its centre 40 below the tool centre point,
/// which is 20 outside its box": the nearest object and which way it lies
/// from where the close left the tool centre point ("" when no object has
/// a box). Lengths in the cell's unit, at most 2 decimals; the world's y is
/// up, so y is "above"/"below" and x, z are "towards +x" and so on.
std::string emptyCloseText(const EmptyClose& e, const workcell::Workcell& cell);

/// The same offset (centre − tool centre point) as a move to make:
/// "40 down", "40 down and 5 towards -x"; "" when it rounds to nothing.
std::string moveText(const Eigen::Vector3d& offset);

/// The warning a finished (or paused) run gets when its gripper closed at
/// least once and never took an object: at the first close that took
/// nothing, code `gripper-took-nothing`, with a hint saying which way to
/// move. `file` is the program's name as diagnostics show it.
std::optional<diag::Diagnostic> gripperWarning(const Run& run, const std::string& file);

}  // namespace rs::runtime
