// What drives a program's inputs, for the hover on an input number and the
// warning on a WAITFOR nothing can end (issue 35): the cell's wires (a
// sensor, a robot's output, ON or OFF), the stimuli file beside the
// program (its timed changes and its reactive rules), or nothing.
#include <fmt/format.h>

#include "base/number_text.h"
#include "tools/lsp/device_text.h"
#include "tools/lsp/features/features.h"

namespace rs::lsp {

using base::formatNumber;

namespace {

std::string sensorText(const workcell::Sensor& s) { return fmt::format("sensor {} ({})", s.name, sensorShape(s)); }

std::string signalText(const workcell::Signal& s, const workcell::Workcell& cell) {
  using K = workcell::Signal::Kind;
  const std::string robot = s.robot.empty() ? std::string() : s.robot + ".";
  switch (s.kind) {
    case K::On: return "ON (always on)";
    case K::Off: return "OFF (always off)";
    case K::Output: return fmt::format("{}OUT {}", robot, s.number);
    case K::Input: return fmt::format("{}IN {}", robot, s.number);
    case K::Sensor:
      if (s.sensor < cell.devices.sensors.size()) return sensorText(cell.devices.sensors[s.sensor]);
      return fmt::format("sensor {}", s.name);
  }
  return {};
}

// The cell as the program names it: its directive's name, else the setting's.
std::string cellName(const ProgramAnalysis& a) {
  if (a.directive()) return a.directive()->name;
  return a.cell().name;
}

std::string lines(const std::vector<std::uint32_t>& list) {
  std::string out;
  for (const std::uint32_t l : list) out += fmt::format("{}{}", out.empty() ? "" : ", ", l);
  return out;
}

}  // namespace

bool wiresDrivenRobot(const workcell::Workcell& cell, const std::string& robot) {
  return robot.empty() || cell.robotLabeled(robot) == cell.drivenRobotIndex();
}

std::vector<std::string> inputDrivers(const ProgramAnalysis& a, std::int64_t input) {
  std::vector<std::string> out;
  if (const workcell::Workcell* cell = a.cell().cell.get())
    for (const workcell::Wire& w : cell->devices.wires)
      if (w.input == input && wiresDrivenRobot(*cell, w.robot)) {
        std::string text = signalText(w.source, *cell);
        if (w.afterUs > 0) text += fmt::format(", {} later", formatSeconds(w.afterUs));
        if (w.inverted) text += ", inverted";
        out.push_back(fmt::format("{}, wired on line {} of {}", text, w.pos.line, cellName(a)));
      }
  if (const std::optional<stimuli::Stimuli>& s = a.stimuli().parsed) {
    std::vector<std::uint32_t> changes;
    for (const stimuli::InputChange& c : s->changes)
      if (c.input == input) changes.push_back(c.line);
    if (!changes.empty())
      out.push_back(fmt::format("the stimuli file {} (line{} {})", a.stimuli().file, changes.size() > 1 ? "s" : "",
                                lines(changes)));
    for (const stimuli::ReactiveRule& r : s->rules)
      if (r.input == input)
        out.push_back(fmt::format("a reactive rule in {} (line {}: when output {} turns {}, it turns {}{})",
                                  a.stimuli().file, r.line, r.output, r.outputOn ? "ON" : "OFF", r.inputOn ? "ON" : "OFF",
                                  r.delay > 0 ? fmt::format(" {} later", formatSeconds(r.delay)) : std::string()));
  }
  return out;
}

bool inputCanTurnOn(const ProgramAnalysis& a, std::int64_t input) {
  if (const workcell::Workcell* cell = a.cell().cell.get())
    for (const workcell::Wire& w : cell->devices.wires)
      if (w.input == input && wiresDrivenRobot(*cell, w.robot)) {
        // OFF never turns it on; OFF INVERTED always does.
        const bool off = w.source.kind == workcell::Signal::Kind::Off;
        if (!off || w.inverted) return true;
      }
  if (const std::optional<stimuli::Stimuli>& s = a.stimuli().parsed) {
    for (const stimuli::InputChange& c : s->changes)
      if (c.input == input && c.on) return true;
    for (const stimuli::ReactiveRule& r : s->rules)
      if (r.input == input && r.inputOn) return true;
  } else if (!a.stimuli().file.empty()) {
    return true;  // a stimuli file with errors: what it would do is unknown
  }
  return false;
}

std::string inputHover(const ProgramAnalysis& a, std::int64_t input) {
  const std::vector<std::string> drivers = inputDrivers(a, input);
  if (drivers.empty()) {
    const std::string stim = a.stimuli().file.empty() ? std::string("no stimuli file beside the program")
                                                      : fmt::format("nothing in {}", a.stimuli().file);
    return fmt::format("input {}: nothing drives it (no wire in the cell, {}): it stays OFF", input, stim);
  }
  if (drivers.size() == 1) return fmt::format("input {}: {}", input, drivers.front());
  std::string out = fmt::format("input {}: driven by", input);
  for (const std::string& d : drivers) out += "\n- " + d;
  return out;
}

std::vector<diag::Diagnostic> unendingWaits(const ProgramAnalysis& a) {
  std::vector<diag::Diagnostic> out;
  for (const IndexedInstruction& in : a.index().instructions()) {
    if (!in.known || !vm::has(in.op, vm::kWaits) || vm::info(in.op).format != vm::Format::Input || !in.inputOn || in.inputPos.line == 0) continue;
    if (inputCanTurnOn(a, in.input)) continue;
    const std::string stim = a.stimuli().file.empty() ? std::string("no stimuli file beside the program")
                                                      : fmt::format("{} never turns it on", a.stimuli().file);
    out.push_back({a.source().name(), in.inputPos, diag::Severity::Warning,
                   fmt::format("WAITFOR {} ON can never end: nothing turns input {} on (no wire in the cell, {})",
                               in.input, in.input, stim),
                   "input-never-on",
                   fmt::format("wire a source to it in the cell (WIRE eye TO IN {0}), or give it a stimulus "
                               "(\"at 1 input {0} on\" in the program's .stim file)",
                               in.input)});
  }
  return out;
}

}  // namespace rs::lsp
