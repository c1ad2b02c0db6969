#include "tools/debug/device_points.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/ascii.h"
#include "base/near_names.h"
#include "base/seconds.h"
#include "base/text.h"
#include "runtime/run/trace.h"

namespace rs::debug {

namespace {

using Kind = DevicePoint::Kind;

std::string_view kindWord(Kind k) {
  switch (k) {
    case Kind::Sensor: return "sensor";
    case Kind::Feeder: return "feeder";
    case Kind::Sink: return "sink";
  }
  return "";
}

// The names of the cell's devices of kind `k`.
std::vector<std::string> deviceNamesOf(const workcell::Devices& d, Kind k) {
  std::vector<std::string> names;
  if (k == Kind::Sensor)
    for (const auto& s : d.sensors) names.push_back(s.name);
  if (k == Kind::Feeder)
    for (const auto& f : d.feeders) names.push_back(f.name);
  if (k == Kind::Sink)
    for (const auto& s : d.sinks) names.push_back(s.name);
  return names;
}

std::string deviceCountText(std::uint64_t n, std::string_view what) { return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s"); }

std::string devicePointText(const Eigen::Vector3d& p) { return fmt::format("({:.3f}, {:.3f}, {:.3f})", p.x(), p.y(), p.z()); }

}  // namespace

std::string DevicePoint::text() const {
  std::string t = fmt::format("{} {}", kindWord(kind), base::safeText(name));
  if (edge == Edge::On) t += " ON";
  if (edge == Edge::Off) t += " OFF";
  return t;
}

bool DevicePoint::matches(const runtime::DeviceEvent& e) const {
  using E = runtime::DeviceEvent::Kind;
  if (e.device != device) return false;
  switch (kind) {
    case Kind::Sensor:
      return (e.kind == E::SensorOn && edge != Edge::Off) || (e.kind == E::SensorOff && edge != Edge::On);
    case Kind::Feeder: return e.kind == E::Fed;
    case Kind::Sink: return e.kind == E::Taken;
  }
  return false;
}

bool isDeviceWord(std::string_view word) {
  return base::sameName(word, "sensor") || base::sameName(word, "feeder") || base::sameName(word, "sink");
}

diag::Result<DevicePoint> parseDevicePoint(const runtime::Run& run, std::span<const std::string_view> words) {
  if (words.empty() || !isDeviceWord(words[0]))
    return diag::refusal("a device point is sensor NAME [on|off], feeder NAME or sink NAME");
  DevicePoint p;
  p.kind = base::sameName(words[0], "sensor") ? Kind::Sensor : base::sameName(words[0], "feeder") ? Kind::Feeder : Kind::Sink;
  const std::string_view kind = kindWord(p.kind);
  const bool sensor = p.kind == Kind::Sensor;
  if (words.size() < 2 || words.size() > (sensor ? 3u : 2u))
    return diag::refusal(sensor ? "break sensor takes a sensor's name and maybe on or off: break sensor NAME [on|off]"
                                : fmt::format("break {0} takes a {0}'s name: break {0} NAME", kind));
  if (words.size() == 3) {
    if (base::sameName(words[2], "on")) p.edge = DevicePoint::Edge::On;
    else if (base::sameName(words[2], "off")) p.edge = DevicePoint::Edge::Off;
    else return diag::refusal(fmt::format("'{}': a sensor's edge is on or off", base::safeText(words[2].substr(0, 60))));
  }
  const workcell::Workcell* cell = run.rig().cell();
  if (!cell || !run.rig().devices())
    return diag::refusal("the cell has no devices (sensors, feeders, sinks): run the program on a workcell that has them (--cell)");
  const std::vector<std::string> names = deviceNamesOf(cell->devices, p.kind);
  const auto at = std::find_if(names.begin(), names.end(), [&](const std::string& n) { return base::sameName(n, words[1]); });
  if (at == names.end()) {
    std::string known;
    for (const std::string& n : names) known += (known.empty() ? "" : ", ") + base::safeText(n);
    const std::string_view near = base::nearestName(words[1], names);
    return diag::refusal(fmt::format("the cell has no {} '{}'{}: {}", kind, base::safeText(words[1].substr(0, 60)),
                                     near.empty() ? "" : fmt::format(" (did you mean '{}'?)", base::safeText(near)),
                                     names.empty() ? fmt::format("it has no {}", kind) : "its " + std::string(kind) + "s are " + known));
  }
  p.device = static_cast<std::size_t>(at - names.begin());
  p.name = *at;
  return p;
}

std::vector<std::string> deviceHits(const runtime::Run& run, const DevicePoint& point) {
  std::vector<std::string> hits;
  const workcell::Workcell* cell = run.rig().cell();
  if (!cell) return hits;
  for (const runtime::DeviceEvent& e : run.rig().devicesOfLastStep())
    if (point.matches(e))
      hits.push_back(fmt::format("{} at {} s", runtime::deviceEventText(e, *cell), base::formatSeconds(e.at)));
  return hits;
}

std::vector<DeviceRow> deviceRows(const runtime::Run& run, const runtime::RunView& view) {
  std::vector<DeviceRow> rows;
  const runtime::CellDevices* d = run.rig().devices();
  const workcell::Workcell* cell = run.rig().cell();
  if (!d || !cell) return rows;
  const workcell::Devices& devices = cell->devices;
  for (std::size_t s = 0; s < devices.sensors.size(); ++s)
    rows.push_back({"sensor " + base::safeText(devices.sensors[s].name),
                    fmt::format("{}, turned ON {}", d->sensorOn(s) ? "ON" : "OFF", deviceCountText(d->sensorCount(s), "time"))});
  for (std::size_t c = 0; c < devices.conveyors.size(); ++c)
    rows.push_back({"conveyor " + base::safeText(devices.conveyors[c].name),
                    fmt::format("{}, carried {}", d->running(c) ? "running" : "stopped", deviceCountText(d->carried(c), "part"))});
  for (std::size_t f = 0; f < devices.feeders.size(); ++f)
    rows.push_back({"feeder " + base::safeText(devices.feeders[f].name),
                    fmt::format("fed {}{}", deviceCountText(d->fed(f), "part"),
                                f < d->state().waiting.size() && d->state().waiting[f] ? ", one waits for its place" : "")});
  for (std::size_t s = 0; s < devices.sinks.size(); ++s)
    rows.push_back({"sink " + base::safeText(devices.sinks[s].name), fmt::format("took {}", deviceCountText(d->taken(s), "part"))});
  // The parts in the cell, by number (a fed part's slot comes after the
  // cell's own objects, whatever its number).
  std::vector<std::size_t> parts;
  for (std::size_t o = 0; o < view.objects.size() && o < cell->objects.size(); ++o)
    if (view.objects[o].present && cell->objects[o].kind == workcell::ObjectKind::Part) parts.push_back(o);
  std::sort(parts.begin(), parts.end(),
            [&](std::size_t a, std::size_t b) { return view.objects[a].number < view.objects[b].number; });
  const runtime::CellDevices::State& state = d->state();
  for (std::size_t o : parts) {
    const runtime::ObjectView& v = view.objects[o];
    std::string where = "at " + devicePointText(v.at);
    if (v.held) where += ", held";
    else if (o < state.velocity.size() && !state.velocity[o].isZero() && state.ridden[o] > 0 &&
             state.ridden[o] <= devices.conveyors.size() && d->running(state.ridden[o] - 1))
      where += ", riding " + base::safeText(devices.conveyors[state.ridden[o] - 1].name);
    rows.push_back({fmt::format("{} (object {})", base::safeText(v.name), v.number), where});
  }
  return rows;
}

}  // namespace rs::debug
