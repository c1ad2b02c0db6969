// What a debugger can ask of a cell's devices (issue 35, docs/debugging.md):
// the places to stop at what they do (a sensor's edge, either one or only
// ON or OFF; a part a feeder puts in the cell; a part a sink takes), and
// their state as rows of a name and a value (every sensor, conveyor,
// feeder and sink, then every part in the cell and where it is), which the
// terminal's `print devices` and the debug adapter's Devices scope show.
//
//   auto point = parseDevicePoint(run, {"sensor", "eye", "on"});
//   if (point && point->matches(event)) ...
//   for (const DeviceRow& row : deviceRows(run, session.view())) ...
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/result.h"
#include "runtime/run/run.h"

namespace rs::debug {

struct DevicePoint {
  enum class Kind : std::uint8_t { Sensor, Feeder, Sink };
  /// Sensor: which of its edges stops the run.
  enum class Edge : std::uint8_t { Any, On, Off };
  Kind kind = Kind::Sensor;
  Edge edge = Edge::Any;
  std::size_t device = 0;  ///< in its kind's list of the cell's devices
  std::string name = {};   ///< as the cell spells it

  /// "sensor eye", "sensor eye ON", "feeder parts", "sink done".
  std::string text() const;
  /// A sensor's edge (of the edge asked for), a feed (not a part that
  /// waits for its place) or a take by this device.
  bool matches(const runtime::DeviceEvent& event) const;
};

/// `KIND NAME [on|off]` (KIND: sensor, feeder or sink, any case; on or off
/// only after a sensor) on the cell of `run`; a message naming the cell's
/// devices of that kind when NAME is none of them.
diag::Result<DevicePoint> parseDevicePoint(const runtime::Run& run, std::span<const std::string_view> words);

/// Whether `word` starts a device point (sensor, feeder, sink).
bool isDeviceWord(std::string_view word);

/// What the step just run did that `point` stops at, each said as the
/// trace says it, with its time: "sensor eye ON at 1.100 s".
std::vector<std::string> deviceHits(const runtime::Run& run, const DevicePoint& point);

struct DeviceRow {
  std::string name;   ///< "sensor eye", "conveyor infeed", "block (object 5)"
  std::string value;  ///< "ON, turned ON 1 time", "at (-740.000, 500.000, 620.000), riding infeed"
};

/// The devices' state as `run` stands, in the cell's order (sensors,
/// conveyors, feeders, sinks), then every part in the cell (fed parts by
/// the number they were given) and where it is, as `view` shows it. Empty
/// when the run has no devices.
std::vector<DeviceRow> deviceRows(const runtime::Run& run, const runtime::RunView& view);

}  // namespace rs::debug
