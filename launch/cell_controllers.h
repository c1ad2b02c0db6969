// Real controllers for a cell run of several robots (run --cell CELL
// --device LABEL=DEV ...): each robot named gets its own serial link and
// its own controller session, which follows its simulated machine in
// lock-step (runtime/run/followed_machine.h); the robots not named are
// simulated only. One --dialect, --serial-set and --serial-config serve
// every controller; --log-serial takes LABEL=FILE, one log per device.
// docs/serial.md, "Several robots on their controllers".
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "launch/cell_programs.h"
#include "launch/rhino.h"
#include "runtime/rhino/rhino_machine.h"

namespace rs::launch {

/// Per program of `programs`: the serial request of its robot's controller
/// (an empty device: simulated). Nullopt, with every mistake in `diags`
/// (each with a hint), when a --device or --log-serial is not LABEL=PATH,
/// names no robot of the cell or one without a program, names a robot
/// twice, gives one device to two robots, or a robot's motors are not a
/// Rhino controller's. Nothing is opened.
std::optional<std::vector<SerialRequest>> cellDevices(const SerialRequest& request, const CellPrograms& programs,
                                                      std::vector<diag::Diagnostic>& diags);

/// Opens each controller `requests` names (openRhino), for the program
/// with the same index; null where the robot is simulated. Nullopt, with
/// the problems in `diags`, when one does not open (those opened close).
std::optional<std::vector<std::unique_ptr<rhino::RhinoMachine>>> openCellControllers(
    const std::vector<SerialRequest>& requests, const CellPrograms& programs, vm::Micros maxTime,
    std::vector<diag::Diagnostic>& diags);

}  // namespace rs::launch
