// The compile-time check of straight-line moves (MOVES, APPRO, DEPART):
// wherever the compiler knows where the arm stands before one (the code
// before it runs straight from a move to known encoder counts, and nothing
// jumps or returns in between), the whole line is planned as the run would
// plan it (model/workcell/line_path.h), and a line the arm cannot follow
// is an error at the instruction, in the run's words.
#pragma once

#include "diag/diagnostic.h"
#include "model/workcell/line_plan_cache.h"
#include "model/workcell/model.h"
#include "vm/image.h"

namespace rs::compiler {

/// `robot` must have a chain; `image` is a complete, error-free image.
/// Lines planned before are taken from `cache` (may be null: a cache for
/// this check alone, so that each line is planned once).
void checkLinePaths(const vm::Image& image, const workcell::PlacedRobot& robot, diag::Diagnostics& diagnostics,
                    workcell::LinePlanCache* cache = nullptr);

}  // namespace rs::compiler
