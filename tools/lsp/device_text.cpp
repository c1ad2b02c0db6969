#include "tools/lsp/device_text.h"

#include <fmt/format.h>

#include "base/number_text.h"

namespace rs::lsp {

using base::formatNumber;

namespace {

std::string pointText(const Eigen::Vector3d& p) {
  return fmt::format("({}, {}, {})", formatNumber(p.x()), formatNumber(p.y()), formatNumber(p.z()));
}

std::string pointWords(const Eigen::Vector3d& p) {
  return fmt::format("{} {} {}", formatNumber(p.x()), formatNumber(p.y()), formatNumber(p.z()));
}

// "of robot `left`" after a line of a labelled robot; nothing for the cell's one.
std::string robotOfLine(const std::string& robot) { return robot.empty() ? std::string() : fmt::format(" of robot `{}`", robot); }

std::string secondsText(std::int64_t us) { return formatNumber(static_cast<double>(us) / 1e6); }

}  // namespace

std::string signalWords(const workcell::Signal& s) {
  using K = workcell::Signal::Kind;
  switch (s.kind) {
    case K::On: return "always on";
    case K::Off: return "always off";
    case K::Output: return fmt::format("output {}{}", s.number, robotOfLine(s.robot));
    case K::Input: return fmt::format("input {}{}", s.number, robotOfLine(s.robot));
    case K::Sensor: return fmt::format("sensor `{}`", s.name);
  }
  return {};
}

std::string sensorShape(const workcell::Sensor& s) {
  if (s.shape == workcell::Sensor::Shape::Beam) return fmt::format("BEAM {} {}", pointWords(s.a), pointWords(s.b));
  const Eigen::AlignedBox3d& z = s.zone;
  return fmt::format("ZONE {} {} {} {} {} {}", formatNumber(z.min().x()), formatNumber(z.max().x()),
                     formatNumber(z.max().y()), formatNumber(z.min().y()), formatNumber(z.max().z()),
                     formatNumber(z.min().z()));
}

std::string sensorSentence(const workcell::Sensor& s) {
  using Sees = workcell::Sensor::Sees;
  const char* sees = s.sees == Sees::Parts ? "parts" : s.sees == Sees::Robots ? "robots" : "parts and robots";
  if (s.shape == workcell::Sensor::Shape::Beam)
    return fmt::format("sensor `{}`: a beam from {} to {}; on while it sees {} across it", s.name, pointText(s.a),
                       pointText(s.b), sees);
  return fmt::format("sensor `{}`: a zone from {} to {}; on while it sees {} in it", s.name, pointText(s.zone.min()),
                     pointText(s.zone.max()), sees);
}

std::string conveyorSentence(const workcell::Conveyor& v) {
  using K = workcell::Signal::Kind;
  const std::string when = v.run.kind == K::On    ? std::string("always")
                           : v.run.kind == K::Off ? std::string("never")
                                                  : fmt::format("while {} is on", signalWords(v.run));
  return fmt::format("conveyor `{}`: runs its belt at {} length units per second {}", v.name, formatNumber(v.speed),
                     when);
}

std::string feederSentence(const workcell::Feeder& f) {
  const std::string when = f.everyUs ? fmt::format("at the start and then every {} s", secondsText(*f.everyUs))
                           : f.when  ? fmt::format("on each rising edge of {}", signalWords(*f.when))
                                     : std::string("never");
  return fmt::format("feeder `{}`: puts a `{}` at {} {}{}", f.name, f.objectName, pointText(f.at), when,
                     f.count ? fmt::format(", at most {}", *f.count) : std::string());
}

std::string sinkSentence(const workcell::Sink& k) {
  return fmt::format("sink `{}`: a part whose centre enters the zone from {} to {} leaves the cell, counted", k.name,
                     pointText(k.zone.min()), pointText(k.zone.max()));
}

std::string wireSentence(const workcell::Wire& w) {
  return fmt::format("wire: input {}{} follows {}{}{}", w.input, robotOfLine(w.robot), signalWords(w.source),
                     w.afterUs ? fmt::format(", {} s later", secondsText(w.afterUs)) : std::string(),
                     w.inverted ? ", inverted" : "");
}

}  // namespace rs::lsp
