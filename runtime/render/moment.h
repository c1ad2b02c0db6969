// A moment of a program's run, for a still: run the program until its
// clock passes the moment, then read each motor's position at that time
// from its last segment (SimMachine is analytic). The same answer as
// stateAt on a full recording, without keeping one.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "runtime/sim_machine.h"
#include "runtime/stimuli.h"
#include "model/workcell/model.h"
#include "vm/image.h"
#include "vm/interpreter.h"

namespace rs::render {

struct Moment {
  vm::Micros at = 0;                   ///< the moment asked for
  std::vector<std::int32_t> encoders;  ///< every motor at `at`
  runtime::CameraTriple view, window;  ///< VIEW and WINDOW executed up to `at`
  vm::RunOutcome outcome;              ///< how the run stopped
  vm::Micros clock = 0;                ///< the clock when it stopped
  /// False when the run failed (runtime error, deadlock, step limit) at or
  /// before `at`; reaching `at` (the time limit) or END is success.
  bool reached = false;
  /// With a workcell: each object's placement (F_world_design) at `at`,
  /// carried by the gripper or resting (model/workcell/grasp.h).
  std::vector<Eigen::Isometry3d> objects;
};

/// Runs `image` (verified) with `stimuli` until the clock passes `at`; on
/// `cell` (its first robot runs the program) the objects follow the gripper.
Moment runToMoment(const vm::Image& image, runtime::Stimuli stimuli, vm::Micros at,
                   std::uint64_t maxSteps = vm::RunLimits{}.maxSteps, const workcell::Workcell* cell = nullptr);

}  // namespace rs::render
