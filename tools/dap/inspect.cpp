// The requests that look at a stopped run: stackTrace (the GOSUB stack),
// scopes and variables (Variables, Motors, Inputs/Outputs, Objects,
// Clock, and Devices on a cell that has them), evaluate (what the terminal's print takes), and setVariable
// (a variable, or an input as the terminal's `set input`).
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <filesystem>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "tools/dap/adapter.h"
#include "tools/dap/scopes.h"
#include "tools/debug/input_causes.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::dap {

namespace {

Json variable(std::string name, std::string value) {
  return {{"name", std::move(name)}, {"value", std::move(value)}, {"variablesReference", 0}};
}

std::string point(const std::array<double, 3>& p) { return fmt::format("({:.3f}, {:.3f}, {:.3f})", p[0], p[1], p[2]); }

}  // namespace

// A frame's name: its source line without the comment ("serve:  GOSUB
// pick"), or the instruction when there is no source.
std::string Adapter::frameName(std::uint32_t line, std::uint32_t instruction) const {
  if (source_ && line >= 1 && line <= source_->lineCount()) {
    std::string_view text = source_->line(line);
    text = debug::trimmed(text.substr(0, text.find(';')));
    if (!text.empty()) return base::safeText(text);
  }
  return base::safeText(vm::instructionText(*session_->run().spec().image, instruction));
}

Adapter::Reply Adapter::stackTrace(const Json& args) {
  const runtime::RunView v = session_->view();
  const vm::Image& image = *session_->run().spec().image;
  Json source = {{"name", std::filesystem::path(sourcePath_).filename().string()}, {"path", sourcePath_}};
  Json frames = Json::array();
  const auto column = [&](std::uint32_t instruction) {
    return clientColumn(image.columns.empty() ? 1 : image.columns[instruction]);
  };
  frames.push_back({{"id", 0},
                    {"name", frameName(v.line, v.instruction)},
                    {"source", source},
                    {"line", clientLine(v.line)},
                    {"column", column(v.instruction)}});
  int id = 1;
  for (auto f = v.callStack.rbegin(); f != v.callStack.rend(); ++f, ++id)
    frames.push_back({{"id", id},
                      {"name", frameName(f->line, f->gosub)},
                      {"source", source},
                      {"line", clientLine(f->line)},
                      {"column", column(f->gosub)}});
  const std::size_t total = frames.size();
  const std::size_t start = std::min<std::size_t>(args.value("startFrame", std::size_t{0}), total);
  const std::size_t levels = args.value("levels", std::size_t{0});
  Json page = Json::array();
  for (std::size_t i = start; i < total && (levels == 0 || i < start + levels); ++i) page.push_back(frames[i]);
  return Json{{"stackFrames", page}, {"totalFrames", total}};
}

Adapter::Reply Adapter::scopes(const Json& args) {
  args.at("frameId").get<std::int64_t>();  // required by the protocol; every frame sees the same globals
  const runtime::RunView v = session_->view();
  // How many each holds, for a client that pages them (variables' start and count).
  const auto scope = [](std::string_view name, int ref, std::size_t count) {
    return Json{{"name", name}, {"variablesReference", ref}, {"namedVariables", count}, {"expensive", false}};
  };
  const auto presentObjects = static_cast<std::size_t>(
      std::count_if(v.objects.begin(), v.objects.end(), [](const runtime::ObjectView& o) { return o.present; }));
  Json all = Json::array({scope("Variables", kVariables, v.variables.size()),
                          scope("Motors", kMotors, v.motors.size() + (v.tcp ? 1 : 0)),
                          scope("Inputs/Outputs", kIo, 2 * vm::kIoCount), scope("Objects", kObjects, presentObjects),
                          scope("Clock", kClock, 2)});
  // The cell's devices and its parts (debug/device_points.h), on a cell that has devices.
  if (const std::size_t rows = debug::deviceRows(session_->run(), v).size(); rows > 0)
    all.push_back(scope("Devices", kDevices, rows));
  return Json{{"scopes", all}};
}

Adapter::Reply Adapter::variables(const Json& args) {
  const std::int64_t ref = args.at("variablesReference").get<std::int64_t>();
  const runtime::RunView v = session_->view();
  const vm::Image& image = *session_->run().spec().image;
  Json out = Json::array();
  switch (ref) {
    case kVariables:
      for (const auto& [name, value] : v.variables) out.push_back(variable(base::safeText(name), std::to_string(value)));
      break;
    case kMotors:
      for (std::size_t m = 0; m < v.motors.size(); ++m)
        out.push_back(variable(std::string(1, image.motors[m].letter), std::to_string(v.motors[m])));
      if (v.tcp) out.push_back(variable("TCP", point(*v.tcp)));
      break;
    case kIo:
      for (int i = 1; i <= vm::kIoCount; ++i)
        out.push_back(variable(fmt::format("in {}", i), inputShown(session_->run(), i, vm::lineIsOn(v.inputs, i))));
      for (int i = 1; i <= vm::kIoCount; ++i)
        out.push_back(variable(fmt::format("out {}", i), vm::lineIsOn(v.outputs, i) ? "on" : "off"));
      break;
    case kObjects:
      for (const runtime::ObjectView& o : v.objects) {
        if (!o.present) continue;  // a feeder's empty slot, a part a sink took
        out.push_back(variable(fmt::format("{}: {}", o.number, base::safeText(o.name)), point({o.at.x(), o.at.y(), o.at.z()}) + ", centre " +
                                                           point({o.centre.x(), o.centre.y(), o.centre.z()}) + (o.held ? ", held" : "") +
                                                           (o.moved ? ", moved" : "")));
      }
      break;
    case kClock:
      out.push_back(variable("time", fmt::format("{} s", base::formatSeconds(v.clock))));
      out.push_back(variable("steps", std::to_string(v.steps)));
      break;
    case kDevices:
      for (debug::DeviceRow& row : debug::deviceRows(session_->run(), v))
        out.push_back(variable(std::move(row.name), std::move(row.value)));
      break;
    default:
      return Error{fmt::format("no variables with reference {}", ref)};
  }
  // Every variable here is a named one: a client asking for indexed ones gets none.
  if (args.value("filter", std::string()) == "indexed") out = Json::array();
  const std::size_t start = std::min<std::size_t>(args.value("start", std::size_t{0}), out.size());
  const std::size_t count = args.value("count", std::size_t{0});  // 0: all
  Json page = Json::array();
  for (std::size_t i = start; i < out.size() && (count == 0 || i < start + count); ++i) page.push_back(out[i]);
  return Json{{"variables", page}};
}

// What the terminal's print takes: variables (all of them), motors, tcp,
// io, objects, devices, clock, or one value (a variable, a motor letter, in N, out
// N, input N, output N). A whole scope answers with its reference, for the
// client to open.
Adapter::Reply Adapter::evaluate(const Json& args) {
  const std::string asked = args.at("expression").get<std::string>();
  return evaluateIn(session_->run(), session_->view(), debug::trimmed(asked), {kVariables, kMotors, kIo, kObjects, kDevices});
}

Adapter::Reply Adapter::evaluateIn(const runtime::Run& run, const runtime::RunView& v, std::string_view text,
                                   const ScopeRefs& refs) {
  const vm::Image& image = *run.spec().image;
  const auto listed = [](const std::vector<std::pair<std::string, std::string>>& items, int ref) {
    std::string shown;
    for (const auto& [name, value] : items) shown += fmt::format("{}{} = {}", shown.empty() ? "" : ", ", name, value);
    return Json{{"result", shown}, {"variablesReference", ref}};
  };
  if (text.empty() || text == "variables") {
    if (v.variables.empty()) return Error{"the program has no variables"};
    std::vector<std::pair<std::string, std::string>> items;
    for (const auto& [name, value] : v.variables) items.emplace_back(base::safeText(name), std::to_string(value));
    return listed(items, refs.variables);
  }
  if (text == "motors") {
    std::vector<std::pair<std::string, std::string>> items;
    for (std::size_t m = 0; m < v.motors.size(); ++m)
      items.emplace_back(std::string(1, image.motors[m].letter), std::to_string(v.motors[m]));
    return listed(items, refs.motors);
  }
  if (text == "tcp") {
    if (!v.tcp) return Error{"no tool centre point: the program runs without a workcell (cell)"};
    return Json{{"result", point(*v.tcp)}, {"variablesReference", 0}};
  }
  if (text == "io") {
    const auto bits = [](vm::IoMask mask) {
      std::string s;
      for (int i = 1; i <= vm::kIoCount; ++i) s += vm::lineIsOn(mask, i) ? " 1" : " 0";
      return s;
    };
    return Json{{"result", fmt::format("inputs 1-{0}:{1}, outputs 1-{0}:{2}", vm::kIoCount, bits(v.inputs), bits(v.outputs))},
                {"variablesReference", refs.io}};
  }
  if (text == "objects") {
    if (v.objects.empty()) return Error{"no objects: the program runs without a workcell (cell), or it has none"};
    std::string names;
    for (const runtime::ObjectView& o : v.objects)
      if (o.present)
        names += fmt::format("{}{} {}{}", names.empty() ? "" : ", ", o.number, base::safeText(o.name), o.held ? " (held)" : "");
    return Json{{"result", names}, {"variablesReference", refs.objects}};
  }
  if (text == "devices") {
    std::vector<std::pair<std::string, std::string>> items;
    for (debug::DeviceRow& row : debug::deviceRows(run, v)) items.emplace_back(std::move(row.name), std::move(row.value));
    if (items.empty()) return Error{"no devices: the cell has no sensors, conveyors, feeders or sinks (or no workcell: cell)"};
    return listed(items, refs.devices);
  }
  auto e = debug::parseExpression(image, debug::ioWords(text));
  if (!e) return Error{e.failure().message};
  const debug::Expression& x = *e;
  const std::int64_t value = debug::valueIn(v, x);  // at the session's moment
  std::string shown = std::to_string(value);
  if (x.kind == debug::Expression::Kind::Output) shown = value ? "on" : "off";
  if (x.kind == debug::Expression::Kind::Input) shown = inputShown(run, static_cast<int>(x.index), value != 0);
  if (x.kind == debug::Expression::Kind::Clock) shown = fmt::format("{} s", base::formatSeconds(value));
  return Json{{"result", shown}, {"variablesReference", 0}};
}

std::string Adapter::inputShown(const runtime::Run& run, int input, bool on) {
  const std::string note = debug::inputCauseNote(run, input, on);
  return fmt::format("{}{}", on ? "on" : "off", note.empty() ? note : " (" + note + ")");
}

namespace {

std::optional<bool> onOrOff(std::string_view text) {
  for (std::string_view on : {"on", "1", "true"})
    if (base::sameName(text, on)) return true;
  for (std::string_view off : {"off", "0", "false"})
    if (base::sameName(text, off)) return false;
  return std::nullopt;
}

}  // namespace

// A variable of the program, or an input (as the terminal's `set input N
// on|off`): from this moment on, replayed going back and forth.
std::optional<Adapter::Error> Adapter::inputSetting(const vm::Image& image, const std::string& name, std::string_view typed,
                                                    int& input, bool& on) {
  auto e = debug::parseExpression(image, name);
  if (!e || e->kind != debug::Expression::Kind::Input)
    return Error{fmt::format("only inputs can be set ('in 1'..'in {}'): outputs are the program's", vm::kIoCount)};
  const std::optional<bool> value = onOrOff(typed);
  if (!value) return Error{fmt::format("'{}': an input is on or off", base::safeText(typed.substr(0, 60)))};
  input = static_cast<int>(e->index), on = *value;
  return std::nullopt;
}

Adapter::Reply Adapter::setVariable(const Json& args) {
  const std::int64_t ref = args.at("variablesReference").get<std::int64_t>();
  const std::string name = args.at("name").get<std::string>();
  const std::string value = args.at("value").get<std::string>();
  const std::string_view typed = debug::trimmed(value);
  if (ref == kVariables) {
    std::int64_t n = 0;
    const auto [end, ec] = std::from_chars(typed.data(), typed.data() + typed.size(), n);
    if (typed.empty() || ec != std::errc() || end != typed.data() + typed.size())
      return Error{fmt::format("'{}' is not a whole number", base::safeText(typed.substr(0, 60)))};
    if (auto problem = session_->setVariable(name, n)) return Error{*problem};
    return Json{{"value", std::to_string(n)}, {"variablesReference", 0}};
  }
  if (ref == kIo) {
    int input = 0;
    bool on = false;
    if (auto bad = inputSetting(*session_->run().spec().image, name, typed, input, on)) return *bad;
    if (auto problem = session_->setInput(input, on)) return Error{*problem};
    return Json{{"value", on ? "on" : "off"}, {"variablesReference", 0}};
  }
  if (ref >= kMotors && ref <= kDevices)
    return Error{"only variables and inputs can be set: the motors, objects, clock and devices are the run's"};
  return Error{fmt::format("no variables with reference {}", ref)};
}

}  // namespace rs::dap
