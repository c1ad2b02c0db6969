// What drives a program's inputs, for the hover on an input number and the
// warning on a WAITFOR nothing can end (issue 35): the cell's wires (a
// sensor, a robot's output, ON or OFF), the stimuli file beside the
// program (its timed changes and its reactive rules), or nothing.
#include <fmt/format.h>

#include <algorithm>
#include <optional>

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

// The level a wire holds its input at whatever happens (ON or OFF, inverted
// or not), or nothing for a source that changes (a sensor, an output).
std::optional<bool> heldLevel(const workcell::Wire& w) {
  if (w.source.kind == workcell::Signal::Kind::On) return !w.inverted;
  if (w.source.kind == workcell::Signal::Kind::Off) return w.inverted;
  return std::nullopt;
}

// "OFF", "ON INVERTED": a held wire's source as its line writes it.
std::string heldSource(const workcell::Wire& w) {
  return fmt::format("{}{}", w.source.kind == workcell::Signal::Kind::On ? "ON" : "OFF", w.inverted ? " INVERTED" : "");
}

// The hover's words for a wire that holds its input at one level.
std::optional<std::string> heldText(const workcell::Wire& w, const std::string& cell) {
  const std::optional<bool> level = heldLevel(w);
  if (!level) return std::nullopt;
  // Inputs start OFF: a wire that holds one ON with AFTER turns it on then.
  const std::string held = !*level ? "always OFF" : w.afterUs > 0 ? fmt::format("ON from {} s", formatSeconds(w.afterUs)) : "always ON";
  return fmt::format("{}, wired on line {} of {}: {}", heldSource(w), w.pos.line, cell, held);
}

// The wire of the program's robot to `input`, or null (one input takes one wire).
const workcell::Wire* wireTo(const workcell::Workcell& cell, std::int64_t input) {
  for (const workcell::Wire& w : cell.devices.wires)
    if (w.input == input && wiresDrivenRobot(cell, w.robot)) return &w;
  return nullptr;
}

// "input 1 does", "inputs 1 and 2 do", "inputs 1, 2 and 4 do": the program's
// robot's wired inputs; empty when it has none.
std::string wiredInputs(const workcell::Workcell& cell) {
  std::vector<int> inputs;
  for (const workcell::Wire& w : cell.devices.wires)
    if (wiresDrivenRobot(cell, w.robot)) inputs.push_back(w.input);
  std::sort(inputs.begin(), inputs.end());
  inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
  std::string out;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    out += fmt::format("{}{}", i == 0 ? "" : i + 1 == inputs.size() ? " and " : ", ", inputs[i]);
  if (inputs.empty()) return out;
  return fmt::format("{} {} {}", inputs.size() > 1 ? "inputs" : "input", out, inputs.size() > 1 ? "do" : "does");
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
        if (std::optional<std::string> held = heldText(w, cellName(a))) {
          out.push_back(std::move(*held));
          continue;
        }
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
    if (const workcell::Wire* w = wireTo(*cell, input)) {
      // OFF and ON INVERTED never turn it on (a stimulus still may).
      const std::optional<bool> level = heldLevel(*w);
      if (!level || *level) return true;
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

namespace {

// The warning on a wait for input n ON that nothing turns on (`ending`:
// "WAITFOR 1 ON can never end", or a polling loop's words): the wire that
// holds the input OFF, else that the cell wires other inputs but not this
// one, else that nothing drives it at all.
diag::Diagnostic unendingWait(const ProgramAnalysis& a, std::int64_t input, diag::Pos at, const std::string& ending) {
  const std::string& file = a.stimuli().file;
  const std::string stimulus = fmt::format("give it a stimulus (\"at 1 input {} on\" in the program's .stim file)", input);
  const auto warning = [&](std::string message, std::string hint) {
    return diag::Diagnostic{a.source().name(), at, diag::Severity::Warning, std::move(message), "input-never-on",
                            std::move(hint)};
  };
  const std::string wireHint = fmt::format("wire a source to it in the cell (WIRE eye TO IN {}), or {}", input, stimulus);
  const workcell::Workcell* cell = a.cell().cell.get();
  if (const workcell::Wire* w = cell ? wireTo(*cell, input) : nullptr)
    return warning(fmt::format("input {} is wired from {} (line {} of {}): it is never ON, so {}",
                               input, heldSource(*w), w->pos.line, cellName(a), ending),
                   fmt::format("{}, or {}",
                               w->inverted ? fmt::format("drop INVERTED from the WIRE on line {}", w->pos.line)
                                           : fmt::format("wire a sensor or an output to it on line {} instead of OFF", w->pos.line),
                               stimulus));
  if (const std::string others = cell ? wiredInputs(*cell) : std::string(); !others.empty())
    return warning(fmt::format("input {} has no wire in {} ({}), {}: it is never ON, so {}", input,
                               cellName(a), others,
                               file.empty() ? std::string("no stimulus and no rule") : fmt::format("and {} never turns it on", file),
                               ending),
                   wireHint);
  const std::string stim = file.empty() ? std::string("no stimuli file beside the program") : fmt::format("{} never turns it on", file);
  return warning(fmt::format("{}: nothing turns input {} on (no wire in the cell, {})", ending, input, stim),
                 wireHint);
}

// Whether an instruction only goes on to the next: no jump, call, return
// or end (a polling loop's body is made of these).
bool goesOn(const IndexedInstruction& in) {
  return in.known && vm::has(in.op, vm::kFallsThrough) && !vm::has(in.op, vm::kJumps) && !vm::has(in.op, vm::kCalls) &&
         !vm::has(in.op, vm::kReturns) && !vm::has(in.op, vm::kEnds);
}

// A polling loop whose one way out is `in` (an input jump that asks for
// ON): the instruction after it (`back`) jumps back, unconditionally, to it
// or to a line before it, and every instruction from there to it goes on
// to the next. `lastStop[n]`: the number of the last instruction at or
// before n that does not (0: none), so the check is one look whatever the
// loop's length. The loop's first instruction, or null.
const IndexedInstruction* pollingLoopStart(const ProgramIndex& index, const std::vector<std::uint32_t>& lastStop,
                                           const IndexedInstruction& in, const IndexedInstruction& back) {
  if (!back.known || !vm::has(back.op, vm::kJumps) || vm::has(back.op, vm::kFallsThrough) ||
      vm::has(back.op, vm::kBranches) || vm::has(back.op, vm::kCalls))
    return nullptr;
  const IndexedInstruction* start =
      !back.targetLabel.empty() ? index.labelled(back.targetLabel) : index.instructionNumbered(back.targetNumber);
  if (!start || start->number > in.number) return nullptr;
  return lastStop[in.number - 1] < start->number ? start : nullptr;
}

}  // namespace

std::vector<diag::Diagnostic> unendingWaits(const ProgramAnalysis& a) {
  std::vector<diag::Diagnostic> out;
  const std::vector<IndexedInstruction>& all = a.index().instructions();
  std::vector<std::uint32_t> lastStop(all.size() + 1, 0);  // built once: a loop's check is then one look
  for (std::uint32_t n = 1; n <= all.size(); ++n) lastStop[n] = goesOn(all[n - 1]) ? lastStop[n - 1] : n;  // all[n - 1] is number n
  for (const IndexedInstruction& in : all) {
    if (!in.known || !in.inputOn || in.inputPos.line == 0 || in.input == 0) continue;
    const vm::Format format = vm::info(in.op).format;
    if (vm::has(in.op, vm::kWaits) && format == vm::Format::Input) {
      if (!inputCanTurnOn(a, in.input))
        out.push_back(unendingWait(a, in.input, in.inputPos, fmt::format("WAITFOR {} ON can never end", in.input)));
    } else if (format == vm::Format::InputJump) {
      const IndexedInstruction* back = a.index().instructionNumbered(in.number + 1);
      const IndexedInstruction* start = back ? pollingLoopStart(a.index(), lastStop, in, *back) : nullptr;
      if (start && !inputCanTurnOn(a, in.input))
        out.push_back(unendingWait(a, in.input, in.inputPos,
                                   fmt::format("the loop of lines {}..{} can never end (its one way out is {} {} ON)",
                                               start->pos.line, back->pos.line, in.mnemonic, in.input)));
    }
  }
  return out;
}

}  // namespace rs::lsp
