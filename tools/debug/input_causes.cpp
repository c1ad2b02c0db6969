#include "tools/debug/input_causes.h"

#include <fmt/format.h>

#include "base/seconds.h"
#include "base/text.h"
#include "runtime/cell/devices.h"
#include "runtime/cell/input_cause.h"

namespace rs::debug {

namespace {

// What turns a wired input, and so what to change instead of the input.
std::string whatTurnsIt(const workcell::Signal& s) {
  using K = workcell::Signal::Kind;
  const std::string whose = s.robot.empty() ? std::string("the program's") : base::safeText(s.robot) + "'s";
  switch (s.kind) {
    case K::Sensor: return "the sensor turns it as what it sees comes and goes";
    case K::Output: return fmt::format("{} OUTSIG {} turns it", whose, s.number);
    case K::Input: return "it follows that input: set that one instead";
    case K::On:
    case K::Off: return "it never changes";
  }
  return {};
}

}  // namespace

std::optional<std::string> wiredInputRefusal(const workcell::Workcell& cell, std::size_t robot, int input,
                                             std::string_view label) {
  for (const workcell::Wire& w : cell.devices.wires) {
    const std::size_t driven = w.robot.empty() ? cell.drivenRobotIndex() : cell.robotLabeled(w.robot);
    if (w.input != input || driven != robot) continue;
    std::string source = base::safeText(runtime::signalText(w.source));
    if (w.afterUs > 0) source += fmt::format(", {} s later", base::formatSeconds(w.afterUs));
    if (w.inverted) source += ", inverted";
    return fmt::format("input {}{} is wired from {} (line {} of {}): {}; to set it by hand, remove the WIRE", input,
                       label.empty() ? std::string() : " of " + base::safeText(label), source, w.pos.line,
                       cell.name.empty() ? std::string("the cell") : base::safeText(cell.name), whatTurnsIt(w.source));
  }
  return std::nullopt;
}

std::optional<std::string> wiredInputRefusal(const runtime::Run& run, int input, std::string_view label) {
  const workcell::Workcell* cell = run.rig().cell();
  if (!cell) return std::nullopt;
  return wiredInputRefusal(*cell, run.rig().robotIndex(), input, label);
}

std::string inputCauseNote(const runtime::Run& run, int input, bool on) {
  const runtime::InputChangeRecord* last = run.rig().lastInputChange(input);
  if (!last || last->cause.on != on) return {};
  return base::safeText(runtime::inputSinceText(base::formatSeconds(last->at), last->cause));
}

std::string causeAside(const runtime::Run& run, const Expression& e, std::int64_t value) {
  if (e.kind != Expression::Kind::Input) return {};
  const std::string note = inputCauseNote(run, static_cast<int>(e.index), value != 0);
  return note.empty() ? note : " (" + note + ")";
}

std::string conditionCause(const runtime::Run& run, const Condition& condition) {
  if (condition.left.kind != Expression::Kind::Input) return {};
  const int input = static_cast<int>(condition.left.index);
  const bool on = valueOf(run, condition.left) != 0;
  const std::string note = inputCauseNote(run, input, on);
  return note.empty() ? note : fmt::format("input {} {} {}", input, on ? "ON" : "OFF", note);
}

}  // namespace rs::debug
