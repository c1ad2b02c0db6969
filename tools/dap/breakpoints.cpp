// The breakpoints that are not at a line: labels and the cell's devices as
// function breakpoints (setFunctionBreakpoints: a label's name, or
// `sensor NAME [on|off]`, `feeder NAME`, `sink NAME` as the terminal's
// break takes them), and watches as data breakpoints
// (dataBreakpointInfo, setDataBreakpoints: a value that changes, as the
// terminal's `watch`). Each set replaces the previous one of its kind, and
// its answer has one entry per breakpoint asked for, in order.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "base/ascii.h"
#include "base/text.h"
#include "tools/dap/adapter.h"
#include "tools/dap/scopes.h"

namespace rs::dap {

namespace {

Json unverified(std::string message) { return {{"verified", false}, {"message", std::move(message)}}; }


std::string fieldText(const Json& j, const char* name) {
  if (!j.contains(name) || j[name].is_null()) return {};
  return j.at(name).get<std::string>();  // a wrong type throws: a bad request (Adapter::handle)
}

}  // namespace

Adapter::Reply Adapter::setFunctionBreakpoints(const Json& args) {
  for (int id : functionBreakpoints_) session_->remove(id);
  functionBreakpoints_.clear();
  Json out = Json::array();
  const Json source = {{"name", std::filesystem::path(sourcePath_).filename().string()}, {"path", sourcePath_}};
  for (const Json& b : args.at("breakpoints")) {
    const std::string name = b.at("name").get<std::string>();
    const std::vector<std::string_view> words = base::splitWords(name);
    const bool device = words.size() > 1 && debug::isDeviceWord(words[0]);
    diag::Result<int> made = diag::refusal("no breakpoint");  // set below
    if (device) {
      auto point = debug::parseDevicePoint(session_->run(), words);
      if (point) made = session_->breakOnDevice(*point);
      else made = point.failure();
    } else {
      made = session_->breakAtLabel(debug::trimmed(name));
    }
    if (!made) {
      out.push_back(unverified(made.failure().message));
      continue;
    }
    if (const std::string problem = qualify(*made, b); !problem.empty()) {
      session_->remove(*made);
      out.push_back(unverified(problem));
      continue;
    }
    functionBreakpoints_.push_back(*made);
    if (device) {  // no place in the source: a moment of the cell
      out.push_back({{"id", *made}, {"verified", true}, {"message", fmt::format("stops after the instruction during which "
                                                                               "the {} acts", base::safeText(words[0]))}});
      continue;
    }
    const auto& all = session_->breakpoints();
    const auto at = std::find_if(all.begin(), all.end(), [&](const debug::Breakpoint& x) { return x.id == *made; });
    out.push_back({{"id", *made}, {"verified", true}, {"source", source}, {"line", clientLine(at->line)}});
  }
  return Json{{"breakpoints", out}};
}

// What can be watched: a variable, a motor, an input or output (as the
// terminal's watch takes them), named in a scope or as an expression.
Adapter::Reply Adapter::dataBreakpointInfo(const Json& args) {
  const std::string name = args.at("name").get<std::string>();
  const std::int64_t scope = args.value("variablesReference", std::int64_t{0});
  const auto none = [](std::string why) { return Json{{"dataId", nullptr}, {"description", std::move(why)}}; };
  if (scope == kObjects || scope == kClock || (scope == kMotors && base::sameName(name, "TCP")))
    return none(fmt::format("{} cannot be watched: watch a variable, a motor, an input or an output",
                            base::safeText(name.substr(0, 60))));
  if (scope != 0 && scope != kVariables && scope != kMotors && scope != kIo)
    return Error{fmt::format("no variables with reference {}", scope)};
  auto e = debug::parseExpression(*session_->run().spec().image, debug::ioWords(name));
  if (!e) return none(e.failure().message);
  return Json{{"dataId", e->name},
              {"description", fmt::format("{} (stops when it changes)", base::safeText(e->name))},
              {"accessTypes", Json::array({"write"})},
              {"canPersist", false}};
}

Adapter::Reply Adapter::setDataBreakpoints(const Json& args) {
  for (int id : dataBreakpoints_) session_->remove(id);
  dataBreakpoints_.clear();
  Json out = Json::array();
  for (const Json& b : args.at("breakpoints")) {
    const std::string dataId = b.at("dataId").get<std::string>();
    if (const std::string access = fieldText(b, "accessType"); !access.empty() && access != "write") {
      out.push_back(unverified(fmt::format("a watch stops when a value changes: accessType write, not {}",
                                           base::safeText(access.substr(0, 20)))));
      continue;
    }
    if (!fieldText(b, "condition").empty() || !fieldText(b, "hitCondition").empty()) {
      out.push_back(unverified("a watch takes no condition or hit count: use a conditional line breakpoint"));
      continue;
    }
    auto e = debug::parseExpression(*session_->run().spec().image, dataId);
    if (!e) {
      out.push_back(unverified(e.failure().message));
      continue;
    }
    const int id = session_->watch(*e);
    dataBreakpoints_.push_back(id);
    out.push_back({{"id", id}, {"verified", true}, {"message", fmt::format("watch {}", base::safeText(e->name))}});
  }
  return Json{{"breakpoints", out}};
}

}  // namespace rs::dap
