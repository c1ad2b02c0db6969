#include "runtime/render/moment.h"

namespace rs::render {

// The run pauses right after the first instruction that takes the clock
// past `at` (or stops there at its time limit); the instructions that take
// no time at `at` itself have run. The motors' segments then describe the
// move in progress at `at`, if any.
Moment momentOf(runtime::Run& run, vm::Micros at) {
  Moment m;
  m.at = at;
  m.outcome = run.runUntil({.time = at});
  m.clock = run.rig().clock();
  m.reached = m.outcome.ok() || (m.outcome.paused() && run.pauseCause() == vm::StopReason::Time) ||
              (m.outcome.reason == vm::StopReason::TimeLimit && m.clock > at);
  m.encoders = run.rig().motorsAt(at);
  for (const runtime::ObjectView& o : run.rig().objects(at)) {
    if (o.held) m.held = m.objects.size();
    m.objects.push_back(o.pose);
  }
  if (const runtime::SimMachine* sim = run.rig().sim()) {
    m.view = sim->viewRotation();
    m.window = sim->windowShift();
  }
  return m;
}

}  // namespace rs::render
