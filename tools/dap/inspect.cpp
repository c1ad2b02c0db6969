// The requests that look at a stopped run: stackTrace (the GOSUB stack),
// scopes and variables (Variables, Motors, Inputs/Outputs, Objects,
// Clock), evaluate.
#include <fmt/format.h>

#include <filesystem>

#include "base/seconds.h"
#include "base/text.h"
#include "tools/dap/adapter.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::dap {

namespace {

// The scopes' variablesReference numbers: fixed, the run has one frame of
// globals whatever the call depth.
enum Scope : int { kVariables = 1, kMotors, kIo, kObjects, kClock };

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
  frames.push_back({{"id", 0},
                    {"name", frameName(v.line, v.instruction)},
                    {"source", source},
                    {"line", v.line},
                    {"column", image.columns.empty() ? 1 : image.columns[v.instruction]}});
  int id = 1;
  for (auto f = v.callStack.rbegin(); f != v.callStack.rend(); ++f, ++id)
    frames.push_back({{"id", id},
                      {"name", frameName(f->line, f->gosub)},
                      {"source", source},
                      {"line", f->line},
                      {"column", image.columns.empty() ? 1 : image.columns[f->gosub]}});
  const std::size_t total = frames.size();
  const std::size_t start = std::min<std::size_t>(args.value("startFrame", std::size_t{0}), total);
  const std::size_t levels = args.value("levels", std::size_t{0});
  Json page = Json::array();
  for (std::size_t i = start; i < total && (levels == 0 || i < start + levels); ++i) page.push_back(frames[i]);
  return Json{{"stackFrames", page}, {"totalFrames", total}};
}

Adapter::Reply Adapter::scopes(const Json& args) {
  args.at("frameId").get<std::int64_t>();  // required by the protocol; every frame sees the same globals
  const auto scope = [](std::string_view name, int ref, bool expensive) {
    return Json{{"name", name}, {"variablesReference", ref}, {"expensive", expensive}};
  };
  return Json{{"scopes", Json::array({scope("Variables", kVariables, false), scope("Motors", kMotors, false),
                                      scope("Inputs/Outputs", kIo, false), scope("Objects", kObjects, false),
                                      scope("Clock", kClock, false)})}};
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
      for (int i = 1; i <= vm::kIoCount; ++i) out.push_back(variable(fmt::format("in {}", i), vm::lineIsOn(v.inputs, i) ? "on" : "off"));
      for (int i = 1; i <= vm::kIoCount; ++i)
        out.push_back(variable(fmt::format("out {}", i), vm::lineIsOn(v.outputs, i) ? "on" : "off"));
      break;
    case kObjects:
      for (std::size_t n = 0; n < v.objects.size(); ++n) {
        const runtime::ObjectView& o = v.objects[n];
        out.push_back(variable(fmt::format("{}: {}", n + 1, base::safeText(o.name)), point({o.at.x(), o.at.y(), o.at.z()}) + ", centre " +
                                                           point({o.centre.x(), o.centre.y(), o.centre.z()}) + (o.held ? ", held" : "") +
                                                           (o.moved ? ", moved" : "")));
      }
      break;
    case kClock:
      out.push_back(variable("time", fmt::format("{} s", base::formatSeconds(v.clock))));
      out.push_back(variable("steps", std::to_string(v.steps)));
      break;
    default:
      return Error{fmt::format("no variables with reference {}", ref)};
  }
  return Json{{"variables", out}};
}

Adapter::Reply Adapter::evaluate(const Json& args) {
  const std::string text = args.at("expression").get<std::string>();
  auto e = debug::parseExpression(*session_->run().spec().image, debug::ioWords(text));
  if (!e) return Error{e.failure().message};
  const debug::Expression& x = *e;
  const std::int64_t value = debug::valueIn(session_->view(), x);  // at the session's moment
  std::string shown = std::to_string(value);
  if (x.kind == debug::Expression::Kind::Input || x.kind == debug::Expression::Kind::Output) shown = value ? "on" : "off";
  if (x.kind == debug::Expression::Kind::Clock) shown = fmt::format("{} s", base::formatSeconds(value));
  return Json{{"result", shown}, {"variablesReference", 0}};
}

}  // namespace rs::dap
