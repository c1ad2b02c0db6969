// A moment of a program's run, for a still: run until the clock passes the
// moment, then read each motor's position at that time from its last
// segment (the simulated machine is analytic). The same answer as stateAt
// on the run's log, without keeping one.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/run/run.h"

namespace rs::render {

struct Moment {
  vm::Micros at = 0;                   ///< the moment asked for
  std::vector<std::int32_t> encoders;  ///< every motor at `at`
  runtime::CameraTriple view, window;  ///< VIEW and WINDOW executed up to `at`
  vm::RunOutcome outcome;              ///< how the run stopped
  vm::Micros clock = 0;                ///< the clock when it stopped
  /// False when the run failed (runtime error, deadlock, step limit) at or
  /// before `at`; reaching `at` (a pause there, or the time limit past it)
  /// or END is success.
  bool reached = false;
  /// With a workcell: each object's placement (F_world_design) at `at`,
  /// carried by the gripper or resting (runtime/cell/world.h), of the run's
  /// cell (Rig::cell(): a feeder's slots are objects too, parked while
  /// empty). On a cell with devices, a run that keeps a log gives where a
  /// belt had carried each part at `at` exactly (runtime/run/device_history.h).
  std::vector<Eigen::Isometry3d> objects;
  /// Each sensor's state at `at` (the cell's devices.sensors), when the
  /// run keeps a log; else as the run left it.
  std::vector<bool> sensorsOn;
  /// The object the gripper carries at `at`, if any (its pose is in
  /// `objects`): a still checks it for collisions as the run did, with the
  /// gripper's frame.
  std::optional<std::size_t> held;
};

/// Runs `run` (on the simulated machine) until its clock passes `at`, and
/// reads everything at `at`. A closing move still under way at `at` has not
/// taken anything yet.
Moment momentOf(runtime::Run& run, vm::Micros at);

}  // namespace rs::render
