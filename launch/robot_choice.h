// Which robot of a cell a program runs on. A run drives one robot, the
// cell's first (Workcell::drivenRobot); in a cell of several robots the
// program names its own: `--robot LABEL`, else its `; robot: LABEL` line,
// else the robot whose PROGRAM is this very file, else the first. The cell
// is given back with that robot first, so that everything downstream
// (compiling for its motors, the image's cell, the run, the pictures) sees
// it as the driven one. Labels name robots, never places in the list, so
// the order change moves nothing else.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "launch/cell_directive.h"
#include "launch/program.h"

namespace rs::launch {

/// The cell's robot labels for a hint: "`left`, `right`".
std::string robotLabelsOf(const workcell::Workcell& cell);

/// `cell` with the program's robot first, or null with an error in `into`
/// (a label the cell does not have: at the directive, or on --robot). A
/// label given for a cell without robots of that label is an error even in
/// a cell of one robot, so a typo never runs quietly on another robot.
std::shared_ptr<const workcell::Workcell> driveProgramsRobot(std::shared_ptr<const workcell::Workcell> cell,
                                                             const ProgramRequest& request,
                                                             const std::optional<CellDirective>& directive,
                                                             LoadedProgram& into);

}  // namespace rs::launch
