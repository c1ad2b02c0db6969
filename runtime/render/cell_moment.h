// A moment of a cell run of several robots (runtime/run/cell_run.h), for a
// still: each robot's motors at that time from its own log, and each object
// where the robots' takes and let-gos had put it by then.
//
// Why from the logs: a cell run cannot pause at a time (its robots wait on
// one another), so it runs on past the moment and every robot's log says
// where its motors were at it, exactly as its machine would have.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/run/cell_run.h"

namespace rs::render {

struct CellMoment {
  vm::Micros at = 0;
  /// Per robot of the cell (Workcell::robots): its motors at `at`; empty
  /// for a robot without a program (it stands at home).
  std::vector<std::vector<std::int32_t>> encoders;
  /// Each object's placement (F_world_design) at `at`, of the run's cell
  /// (with its feeders' slots).
  std::vector<Eigen::Isometry3d> objects;
  /// Per robot: the object its gripper carries at `at`, if any.
  std::vector<std::optional<std::size_t>> held;
};

/// The moment `at` of `run`, which kept logs (CellRunSpec::log) and ran past
/// `at` (or ended before it: then everything is where the run left it). A
/// take counts from the end of its closing move, a let-go from the start of
/// its opening move; a hand-over's let-go leaves the part with the robot
/// that took it over. A part the cell's devices move (a belt, a feeder, a
/// sink) is where its last logged motion has it at `at`.
CellMoment cellMomentOf(const runtime::CellRun& run, vm::Micros at);

}  // namespace rs::render
