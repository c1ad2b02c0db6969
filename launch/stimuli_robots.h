// Stimuli on the robots of a cell: a stimulus may name the robot whose
// input it drives (`at 1.5 input right.3 on`, `--input right.3=ON@1.5`)
// and a rule the robot whose output it watches. Labels are checked against
// the cell here, once, for every front end that starts a run.
#pragma once

#include <string_view>
#include <vector>

#include "compiler/stimuli/stimuli.h"
#include "diag/diagnostic.h"
#include "model/workcell/model.h"

namespace rs::launch {

/// Checks every label the stimuli name against `cell` (null: no cell, where
/// no label may be named) and keeps what the run's robot, the cell's driven
/// one, reads: a stimulus without a label is its, as is one naming its
/// label. A stimulus for another robot is dropped with a warning (that robot
/// runs no program, so nothing reads it). An unknown label is an error at its
/// place in `stimuliFile` (or `--input`). False on any error. A run of
/// several robots (runtime/run/cell_run.h) keeps, labels and all, what
/// every robot `running` marks reads.
bool placeStimuliOnRobots(const workcell::Workcell* cell, std::string_view stimuliFile, stimuli::Stimuli& stimuli,
                          std::vector<diag::Diagnostic>& diags, const std::vector<bool>* running = nullptr);

}  // namespace rs::launch
