// One robot's log of a cell run of several robots, with what the cell's
// devices did in every robot's steps: the pictures' and the chart's view
// of the cell's devices.
//
// Why: the devices are the cell's, but a device's event or a part's motion
// is logged in the log of the robot whose step it happened in (each
// Rig takes them at the end of its step), so one robot's log alone misses
// the belt's parts and the sensor edges that came while it waited.
#pragma once

#include <cstddef>

#include "runtime/run/cell_run.h"
#include "runtime/run/run_log.h"

namespace rs::runtime {

/// Program p's log (CellRunSpec::log) with every robot's device events and
/// part motions, in time order; another robot's each keyed to p's step in
/// force at its time (the first whose end is at or after it; after p's
/// last step, its last). An empty log when p kept none.
RunLog cellLogOf(const CellRun& run, std::size_t p);

}  // namespace rs::runtime
