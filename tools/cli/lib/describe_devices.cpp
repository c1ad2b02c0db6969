#include "tools/cli/lib/describe_devices.h"

#include <fmt/format.h>

#include "base/text.h"
#include "tools/lsp/device_text.h"

namespace rs::cli {

namespace {

using Json = nlohmann::ordered_json;

Json deviceVec(const Eigen::Vector3d& v) { return Json::array({v.x() + 0.0, v.y() + 0.0, v.z() + 0.0}); }

double deviceSeconds(std::int64_t us) { return static_cast<double>(us) / 1e6; }

// A signal by its line's words: {"kind": "output", "number": 1}, {"kind":
// "sensor", "sensor": "eye"}, {"kind": "on"}; "robot" for LABEL.OUT n.
Json signalJson(const workcell::Signal& s) {
  using K = workcell::Signal::Kind;
  Json j;
  switch (s.kind) {
    case K::On: j = {{"kind", "on"}}; break;
    case K::Off: j = {{"kind", "off"}}; break;
    case K::Output: j = {{"kind", "output"}, {"number", s.number}}; break;
    case K::Input: j = {{"kind", "input"}, {"number", s.number}}; break;
    case K::Sensor: j = {{"kind", "sensor"}, {"sensor", s.name}}; break;
  }
  if (!s.robot.empty()) j["robot"] = s.robot;
  return j;
}

const char* seesName(workcell::Sensor::Sees s) {
  switch (s) {
    case workcell::Sensor::Sees::Parts: return "parts";
    case workcell::Sensor::Sees::Robots: return "robots";
    case workcell::Sensor::Sees::All: return "all";
  }
  return "";
}

}  // namespace

void describeDevicesText(const workcell::Workcell& cell, std::ostream& out) {
  const workcell::Devices& d = cell.devices;
  if (d.empty()) return;
  out << "\ndevices\n";
  const auto line = [&out](const std::string& text) { out << "  " << base::safeText(text) << '\n'; };
  for (const workcell::Sensor& s : d.sensors) line(lsp::sensorSentence(s));
  for (const workcell::Conveyor& v : d.conveyors)
    line(lsp::conveyorSentence(v) + fmt::format(" (the belt of object {})", v.object + 1));
  for (const workcell::Feeder& f : d.feeders) line(lsp::feederSentence(f));
  for (const workcell::Sink& k : d.sinks) line(lsp::sinkSentence(k));
  for (const workcell::Wire& w : d.wires) line(lsp::wireSentence(w));
}

Json describeDevicesJson(const workcell::Workcell& cell) {
  const workcell::Devices& d = cell.devices;
  Json sensors = Json::array(), conveyors = Json::array(), feeders = Json::array(), sinks = Json::array();
  for (const workcell::Sensor& s : d.sensors) {
    const bool beam = s.shape == workcell::Sensor::Shape::Beam;
    sensors.push_back({{"name", s.name},
                       {"kind", beam ? "beam" : "zone"},
                       {beam ? "from" : "min", deviceVec(beam ? s.a : Eigen::Vector3d(s.zone.min()))},
                       {beam ? "to" : "max", deviceVec(beam ? s.b : Eigen::Vector3d(s.zone.max()))},
                       {"sees", seesName(s.sees)}});
  }
  for (const workcell::Conveyor& v : d.conveyors)
    conveyors.push_back({{"name", v.name}, {"object", v.object + 1}, {"speed", v.speed}, {"run", signalJson(v.run)}});
  for (const workcell::Feeder& f : d.feeders)
    feeders.push_back({{"name", f.name},
                       {"object", f.objectName},
                       {"at", deviceVec(f.at)},
                       {"every", f.everyUs ? Json(deviceSeconds(*f.everyUs)) : Json(nullptr)},
                       {"when", f.when ? signalJson(*f.when) : Json(nullptr)},
                       {"count", f.count ? Json(*f.count) : Json(nullptr)}});
  for (const workcell::Sink& k : d.sinks)
    sinks.push_back({{"name", k.name}, {"min", deviceVec(k.zone.min())}, {"max", deviceVec(k.zone.max())}});
  return {{"sensors", sensors}, {"conveyors", conveyors}, {"feeders", feeders}, {"sinks", sinks}};
}

Json describeWiresJson(const workcell::Workcell& cell) {
  Json wires = Json::array();
  for (const workcell::Wire& w : cell.devices.wires)
    wires.push_back({{"input", w.input},
                     {"robot", w.robot.empty() ? Json(nullptr) : Json(w.robot)},
                     {"source", signalJson(w.source)},
                     {"after", deviceSeconds(w.afterUs)},
                     {"inverted", w.inverted}});
  return wires;
}

}  // namespace rs::cli
