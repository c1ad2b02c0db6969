// A moment of a program's run, for a still: run the program until its
// clock passes the moment, then read each motor's position at that time
// from its last segment (SimMachine is analytic). The same answer as
// stateAt on a full recording, without keeping one.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/sim_machine.h"
#include "runtime/stimuli.h"
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
};

/// Runs `image` (verified) with `stimuli` until the clock passes `at`.
Moment runToMoment(const vm::Image& image, runtime::Stimuli stimuli, vm::Micros at,
                   std::uint64_t maxSteps = vm::RunLimits{}.maxSteps);

}  // namespace rs::render
