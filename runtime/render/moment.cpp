#include "runtime/render/moment.h"

#include "runtime/grasp_observer.h"

namespace rs::render {

// With the time limit set to `at`, the run stops right after the first
// instruction that takes the clock past it; the instructions that take no
// time at `at` itself (a VIEW, an OUTSIG) have run. The motors' segments
// then describe the move in progress at `at`, if any.
Moment runToMoment(const vm::Image& image, runtime::Stimuli stimuli, vm::Micros at, std::uint64_t maxSteps,
                   const workcell::Workcell* cell) {
  runtime::SimMachine machine(image.motors, std::move(stimuli));
  vm::Interpreter interpreter(image, machine);
  runtime::ObjectsInGripper objects(cell, machine.positions());
  if (objects.observer()) objects.observer()->takeNothingEndingAfter(at);
  Moment m;
  m.at = at;
  m.outcome = interpreter.run({maxSteps, at}, objects.chain(nullptr));
  m.reached = m.outcome.ok() || (m.outcome.reason == vm::StopReason::TimeLimit && machine.now() > at);
  m.encoders.resize(image.motors.size());
  for (std::size_t i = 0; i < m.encoders.size(); ++i)
    m.encoders[i] = m.outcome.ok() ? machine.positions()[i] : machine.positionAt(i, at);
  m.clock = machine.now();
  if (workcell::Grasping* grasping = objects.grasping())
    for (std::size_t o = 0; o < cell->objects.size(); ++o) m.objects.push_back(grasping->objectPose(o, m.encoders));
  m.view = machine.viewRotation();
  m.window = machine.windowShift();
  return m;
}

}  // namespace rs::render
