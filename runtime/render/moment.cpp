#include "runtime/render/moment.h"

#include <algorithm>

#include "runtime/run/device_history.h"

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
  // The run went on past `at` to the end of the step in progress: the
  // devices' parts are where the log says they were at `at`.
  const workcell::Workcell* cell = run.rig().cell();
  if (const runtime::CellDevices* devices = run.rig().devices(); devices && cell) {
    if (const runtime::RunLog* log = run.log()) {
      const runtime::DeviceHistory history(*log, *cell);
      const vm::Micros t = std::min(at, m.clock);
      for (std::size_t o = 0; o < m.objects.size(); ++o)
        if (m.held != o)
          if (const std::optional<Eigen::Isometry3d> p = history.restingPose(o, t)) m.objects[o] = *p;
      for (std::size_t s = 0; s < cell->devices.sensors.size(); ++s) m.sensorsOn.push_back(history.sensorOn(s, t));
    } else {
      for (std::size_t s = 0; s < cell->devices.sensors.size(); ++s) m.sensorsOn.push_back(devices->sensorOn(s));
    }
  }
  if (const runtime::SimMachine* sim = run.rig().sim()) {
    m.view = sim->viewRotation();
    m.window = sim->windowShift();
  }
  return m;
}

}  // namespace rs::render
