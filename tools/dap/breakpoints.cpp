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
#include "tools/debug/command_line.h"

namespace rs::dap {

namespace {

Json unverified(std::string message) { return {{"verified", false}, {"message", std::move(message)}}; }


std::string fieldText(const Json& j, const char* name) {
  if (!j.contains(name) || j[name].is_null()) return {};
  return j.at(name).get<std::string>();  // a wrong type throws: a bad request (Adapter::handle)
}

// What a data breakpoint asks that a watch does not do: an access type
// other than write, a condition, a hit count (empty: nothing).
std::string watchProblem(const Json& b) {
  if (const std::string access = fieldText(b, "accessType"); !access.empty() && access != "write")
    return fmt::format("a watch stops when a value changes: accessType write, not {}", base::safeText(access.substr(0, 20)));
  if (!fieldText(b, "condition").empty() || !fieldText(b, "hitCondition").empty())
    return "a watch takes no condition or hit count: use a conditional line breakpoint";
  return {};
}

// A device's breakpoint, verified: it stands at no place in the source, it is a moment of the cell.
Json deviceVerified(int id, std::string_view kind) {
  return {{"id", id}, {"verified", true},
          {"message", fmt::format("stops after the instruction during which the {} acts", base::safeText(kind))}};
}

Json watchable(const std::string& dataId, const std::string& name) {
  return Json{{"dataId", dataId},
              {"description", fmt::format("{} (stops when it changes)", base::safeText(name))},
              {"accessTypes", Json::array({"write"})},
              {"canPersist", false}};
}

Json notWatchable(std::string why) { return Json{{"dataId", nullptr}, {"description", std::move(why)}}; }

std::string notWatchableText(const std::string& name) {
  return fmt::format("{} cannot be watched: watch a variable, a motor, an input or an output", base::safeText(name.substr(0, 60)));
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
      out.push_back(deviceVerified(*made, words[0]));
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
  if (scope == kObjects || scope == kClock || (scope == kMotors && base::sameName(name, "TCP")))
    return notWatchable(notWatchableText(name));
  if (scope != 0 && scope != kVariables && scope != kMotors && scope != kIo)
    return Error{fmt::format("no variables with reference {}", scope)};
  auto e = debug::parseExpression(*session_->run().spec().image, debug::ioWords(name));
  if (!e) return notWatchable(e.failure().message);
  return watchable(e->name, e->name);
}

Adapter::Reply Adapter::setDataBreakpoints(const Json& args) {
  for (int id : dataBreakpoints_) session_->remove(id);
  dataBreakpoints_.clear();
  Json out = Json::array();
  for (const Json& b : args.at("breakpoints")) {
    const std::string dataId = b.at("dataId").get<std::string>();
    if (std::string problem = watchProblem(b); !problem.empty()) {
      out.push_back(unverified(std::move(problem)));
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

// --- a cell of several robots ------------------------------------------------------

// Function breakpoints are the cell's devices' and labels (LABEL, of the
// current thread's robot, or ROBOT:LABEL); a device's condition reads the
// current robot, a label's its robot.
Adapter::Reply Adapter::cellSetFunctionBreakpoints(const Json& args) {
  for (int id : functionBreakpoints_) cell_->remove(id);
  functionBreakpoints_.clear();
  Json out = Json::array();
  const std::size_t robot = cell_->current();
  for (const Json& b : args.at("breakpoints")) {
    const std::string name = b.at("name").get<std::string>();
    const std::vector<std::string_view> words = base::splitWords(name);
    if (words.size() < 2 || !debug::isDeviceWord(words[0])) {
      // A label: of the current thread's robot, or ROBOT:LABEL.
      std::size_t p = robot;
      std::string_view label = debug::trimmed(name);
      if (const std::size_t colon = label.find(':'); colon != std::string_view::npos) {
        const auto named = cell_->robotNamed(label.substr(0, colon));
        if (!named) {
          out.push_back(unverified(fmt::format("'{}' names no robot of the cell", base::safeText(label.substr(0, colon)))));
          continue;
        }
        p = *named, label = label.substr(colon + 1);
      }
      auto made = cell_->breakAtLabel(p, label);
      std::optional<debug::Condition> condition;
      std::optional<debug::HitCondition> hits;
      std::string problem = made ? qualifiers(b, *cell_->cell().robot(p).spec().image, condition, hits) : made.failure().message;
      if (!problem.empty()) {
        if (made) cell_->remove(*made);
        out.push_back(unverified(std::move(problem)));
        continue;
      }
      cell_->qualify(*made, condition, hits);
      functionBreakpoints_.push_back(*made);
      const auto& all = cell_->breakpoints();
      const auto at = std::find_if(all.begin(), all.end(), [&](const debug::CellBreakpoint& x) { return x.id == *made; });
      out.push_back({{"id", *made}, {"verified", true},
                     {"source", {{"name", std::filesystem::path(cellPaths_[p]).filename().string()}, {"path", cellPaths_[p]}}},
                     {"line", clientLine(at->line)}});
      continue;
    }
    auto point = debug::parseDevicePoint(cell_->cell().robot(robot), words);
    if (!point) {
      out.push_back(unverified(point.failure().message));
      continue;
    }
    std::optional<debug::Condition> condition;
    std::optional<debug::HitCondition> hits;
    if (std::string problem = qualifiers(b, *cell_->cell().robot(robot).spec().image, condition, hits); !problem.empty()) {
      out.push_back(unverified(std::move(problem)));
      continue;
    }
    const int id = cell_->breakOnDevice(*point);
    cell_->qualify(id, condition, hits);
    functionBreakpoints_.push_back(id);
    out.push_back(deviceVerified(id, words[0]));
  }
  return Json{{"breakpoints", out}};
}

// A data breakpoint is a watch of one robot's value: its dataId carries
// the thread ("2:PARTS"; without one, the current robot's).
Adapter::Reply Adapter::cellDataBreakpointInfo(const Json& args) {
  const std::string name = args.at("name").get<std::string>();
  const std::int64_t ref = args.value("variablesReference", std::int64_t{0});
  std::size_t robot = cell_->current();
  if (ref != 0) {
    const std::int64_t thread = ref / kCellPerThread, scope = ref % kCellPerThread;
    if (thread < 1 || thread > static_cast<std::int64_t>(cell_->size()) || scope < 1 || scope > kCellLastScope)
      return Error{fmt::format("no variables with reference {}", ref)};
    if (scope == kCellClockScope || scope == kCellDevicesScope || (scope == kCellMotorsScope && base::sameName(name, "TCP")))
      return notWatchable(notWatchableText(name));
    robot = static_cast<std::size_t>(thread - 1);
  }
  auto e = debug::parseExpression(*cell_->cell().robot(robot).spec().image, debug::ioWords(name));
  if (!e) return notWatchable(e.failure().message);
  return watchable(fmt::format("{}:{}", robot + 1, e->name), fmt::format("{} of {}", e->name, cell_->label(robot)));
}

Adapter::Reply Adapter::cellSetDataBreakpoints(const Json& args) {
  for (int id : dataBreakpoints_) cell_->remove(id);
  dataBreakpoints_.clear();
  Json out = Json::array();
  for (const Json& b : args.at("breakpoints")) {
    std::string dataId = b.at("dataId").get<std::string>();
    if (std::string problem = watchProblem(b); !problem.empty()) {
      out.push_back(unverified(std::move(problem)));
      continue;
    }
    std::size_t robot = cell_->current();
    if (const std::size_t colon = dataId.find(':'); colon != std::string::npos) {
      const auto thread = debug::wholeCount(std::string_view(dataId).substr(0, colon));
      if (!thread || *thread < 1 || *thread > cell_->size()) {
        out.push_back(unverified(fmt::format("'{}': no thread of the cell", base::safeText(dataId.substr(0, 60)))));
        continue;
      }
      robot = static_cast<std::size_t>(*thread - 1);
      dataId = dataId.substr(colon + 1);
    }
    auto e = debug::parseExpression(*cell_->cell().robot(robot).spec().image, dataId);
    if (!e) {
      out.push_back(unverified(e.failure().message));
      continue;
    }
    const int id = cell_->watch(robot, *e);
    dataBreakpoints_.push_back(id);
    out.push_back({{"id", id}, {"verified", true},
                   {"message", fmt::format("watch {} of {}", base::safeText(e->name), base::safeText(cell_->label(robot)))}});
  }
  return Json{{"breakpoints", out}};
}

}  // namespace rs::dap
