// The debug adapter on a cell of several robots (a launch with `cell` and
// `programs`, or a cell alone: its PROGRAMs): one DAP thread per robot (id
// = its place among the programs + 1, named by its label), breakpoints
// per program file, every stop stops every thread (allThreadsStopped) and
// names the robot that stopped; stackTrace, scopes and variables per
// thread; stepIn and next step that thread's robot while the others go on
// in time; stepBack, reverseContinue and gotoTime put the whole cell back.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "base/seconds.h"
#include "base/text.h"
#include "launch/cell_programs.h"
#include "tools/dap/adapter.h"
#include "tools/dap/scopes.h"
#include "tools/debug/device_points.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::dap {

namespace {

std::string programPath(const std::string& file) {
  std::error_code ec;
  const std::string path = std::filesystem::absolute(file, ec).lexically_normal().string();
  return ec ? file : path;
}

Json cellVariable(std::string name, std::string value) {
  return {{"name", std::move(name)}, {"value", std::move(value)}, {"variablesReference", 0}};
}

}  // namespace

Adapter::Reply Adapter::launchCell(const launch::ProgramRequest& program, const launch::RunRequest& run,
                                   const Json& args) {
  if (program.cell.empty()) return Error{"programs name the programs of a cell's robots: give the cell too"};
  // programs: {"LABEL": "FILE", ...}, or ["LABEL=FILE", ...] as the command line takes them.
  std::vector<std::string> assignments;
  if (const Json& p = args.value("programs", Json()); p.is_object()) {
    for (const auto& [label, file] : p.items()) {
      if (!file.is_string()) return Error{fmt::format("programs.{} is a file name (a string)", base::safeText(label))};
      assignments.push_back(label + "=" + file.get<std::string>());
    }
  } else if (p.is_array()) {
    for (const Json& a : p) {
      if (!a.is_string() || !launch::isProgramAssignment(a.get<std::string>()))
        return Error{"programs is {\"LABEL\": \"FILE\", ...} or a list of \"LABEL=FILE\""};
      assignments.push_back(a.get<std::string>());
    }
  } else if (!p.is_null()) {
    return Error{"programs is {\"LABEL\": \"FILE\", ...} or a list of \"LABEL=FILE\""};
  }
  launch::CellPrograms programs;
  const auto sourceOf = [&programs](const std::string& file) { return programs.sourceOf(file); };
  std::vector<diag::Diagnostic> diags;
  std::optional<runtime::CellRunSpec> spec;
  if (launch::assignCellPrograms(program, assignments, programs)) {
    launch::compileAssignedPrograms(program, programs);
    spec = launch::prepareCellRun(programs, run, diags);
  }
  diags.insert(diags.begin(), programs.cellLoad.diagnostics.begin(), programs.cellLoad.diagnostics.end());
  for (const launch::LoadedProgram& l : programs.loaded) diags.insert(diags.end(), l.diagnostics.begin(), l.diagnostics.end());
  std::ostringstream text;
  launch::printDiagnostics(text, diags, sourceOf, program.maxErrors, {});
  if (!text.str().empty()) output("stderr", text.str());
  if (!spec) {
    const auto error = std::find_if(diags.begin(), diags.end(), [](const diag::Diagnostic& d) { return d.severity == diag::Severity::Error; });
    const std::string first = error == diags.end()    ? std::string("it could not be loaded")
                              : error->pos.line == 0 ? fmt::format("{}: {}", base::safeText(error->file), error->message)
                                                     : fmt::format("{}:{}: {}", base::safeText(error->file), error->pos.line, error->message);
    return Error{fmt::format("cannot debug cell {}: {}", base::safeText(program.cell), first)};
  }
  if (spec->programs.empty())
    return Error{fmt::format("cannot debug cell {}: no robot has a program (give programs: {{\"LABEL\": \"FILE\"}})",
                             base::safeText(program.cell))};
  cell_ = std::make_unique<debug::CellSession>(*spec);
  cell_->setInterrupt([this] { return poll_ && poll_(); });
  for (std::size_t p = 0; p < programs.loaded.size(); ++p) {
    const launch::LoadedProgram& l = programs.loaded[p];
    cellSources_.push_back(l.source ? *l.source : diag::SourceFile(programs.files[p], ""));
    cellPaths_.push_back(programPath(programs.files[p]));
  }
  cellBreakpoints_.assign(cell_->size(), {});
  state_ = State::Launched;
  pending_ = [this] { event("initialized"); };
  return Json(nullptr);
}

std::optional<std::size_t> Adapter::cellThread(const Json& args) const {
  if (!args.contains("threadId")) return cell_->current();
  const std::int64_t id = args.at("threadId").get<std::int64_t>();
  if (id < 1 || id > static_cast<std::int64_t>(cell_->size())) return std::nullopt;
  return static_cast<std::size_t>(id - 1);
}

Adapter::Reply Adapter::cellDispatch(const std::string& command, const Json& args) {
  if (command == "threads") {
    Json threads = Json::array();
    for (std::size_t p = 0; p < cell_->size(); ++p)
      threads.push_back({{"id", p + 1}, {"name", base::safeText(cell_->label(p))}});
    return Json{{"threads", threads}};
  }
  if (command == "setBreakpoints") return cellSetBreakpoints(args);
  if (command == "setFunctionBreakpoints") return cellSetFunctionBreakpoints(args);
  if (command == "dataBreakpointInfo") return cellDataBreakpointInfo(args);
  if (command == "setDataBreakpoints") return cellSetDataBreakpoints(args);
  if (command == "setExceptionBreakpoints") {
    stopOnDeadlock_ = stopOnRuntimeError_ = stopOnLimit_ = false;
    for (int id : exceptionBreakpoints_) cell_->remove(id);
    exceptionBreakpoints_.clear();
    Json out = Json::array();
    for (const Json& f : args.value("filters", Json::array())) {
      const std::string name = f.is_string() ? f.get<std::string>() : f.dump();
      if (name == "deadlock") stopOnDeadlock_ = true;
      else if (name == "runtimeError") stopOnRuntimeError_ = true;
      else if (name == "limit") stopOnLimit_ = true;
      else if (name == "collision") exceptionBreakpoints_.push_back(cell_->breakOnCollision());
      else if (name == "warning") exceptionBreakpoints_.push_back(cell_->breakOnWarning());
      else {
        out.push_back({{"verified", false}, {"message", "no such filter: deadlock, runtimeError, limit, collision, warning"}});
        continue;
      }
      out.push_back({{"verified", true}});
    }
    return Json{{"breakpoints", out}};
  }
  if (command == "configurationDone") {
    if (state_ != State::Launched) return Error{"configurationDone was already sent"};
    state_ = State::Running;
    pending_ = [this] { reportCellStop(stopOnEntry_ ? cell_->lastStop() : cell_->resume()); };
    return Json(nullptr);
  }
  if (command == "stackTrace") return cellStackTrace(args);
  if (command == "scopes") return cellScopes(args);
  if (command == "variables") return cellVariables(args);
  if (command == "evaluate") return cellEvaluate(args);
  if (command == "terminate") {
    if (state_ != State::Terminated) pending_ = [this] { event("terminated"); };
    state_ = State::Terminated;
    return Json(nullptr);
  }
  if (command == "pause") return Json(nullptr);  // a stopped cell stays stopped
  const bool moves = command == "continue" || command == "next" || command == "stepIn" || command == "stepOut" ||
                     command == "stepBack" || command == "reverseContinue" || command == "gotoTime";
  if (command == "setVariable") return cellSetVariable(args);
  if (!moves) return Error{fmt::format("unknown request '{}'", base::safeText(command.substr(0, 60)))};
  if (state_ == State::Launched) return Error{fmt::format("{} before configurationDone", command)};
  if (state_ == State::Terminated) return Error{fmt::format("{}: the debug session has been terminated", command)};
  const std::optional<std::size_t> thread = cellThread(args);
  if (!thread) return Error{fmt::format("no thread {}: the cell's threads are 1 to {}", args.at("threadId").dump(), cell_->size())};
  if (command == "gotoTime") {
    vm::Micros at = 0;
    if (std::optional<Error> bad = gotoTimeArgument(args, at)) return *bad;
    pending_ = [this, micros = at] {
      const debug::CellStop stop = cell_->gotoTime(micros);
      // Past the end: the cell stands at its end and can still go back, as the terminal's does.
      if (stop.reason == debug::StopReason::End)
        event("stopped", {{"reason", "goto"}, {"threadId", stop.robot + 1}, {"allThreadsStopped", true}, {"description", stop.message}});
      else reportCellStop(stop);
    };
    return Json(nullptr);
  }
  if (command == "next" || command == "stepIn" || command == "stepOut") {
    cell_->select(*thread);
    auto r = command == "next" ? cell_->next() : command == "stepOut" ? cell_->finish() : cell_->step();
    if (!r) return Error{r.failure().message};
    pending_ = [this, stop = *r] { reportCellStop(stop); };  // the step has run: its response still goes first
    return Json(nullptr);
  }
  cell_->select(*thread);
  pending_ = [this, command] {
    if (command == "continue") reportCellStop(cell_->resume());
    else if (command == "stepBack") reportCellStop(cell_->reverseNext());  // over a GOSUB, as the one robot's
    else reportCellStop(cell_->reverseContinue());
  };
  if (command == "continue") return Json{{"allThreadsContinued", true}};
  return Json(nullptr);
}

Adapter::Reply Adapter::cellSetBreakpoints(const Json& args) {
  const std::string path = programPath(args.value("source", Json::object()).value("path", std::string()));
  const auto robot = std::find(cellPaths_.begin(), cellPaths_.end(), path);
  Json out = Json::array();
  if (robot == cellPaths_.end()) {
    for (const Json& b : args.value("breakpoints", Json::array()))
      out.push_back({{"verified", false}, {"line", b.at("line").get<std::int64_t>()}, {"message", "no robot of the cell runs this file"}});
    return Json{{"breakpoints", out}};
  }
  const auto p = static_cast<std::size_t>(robot - cellPaths_.begin());
  for (int id : cellBreakpoints_[p]) cell_->remove(id);
  cellBreakpoints_[p].clear();
  for (const Json& b : args.value("breakpoints", Json::array())) {
    const std::int64_t asked = b.at("line").get<std::int64_t>();
    const std::int64_t line = ownLine(asked);
    Json result = {{"verified", false}, {"line", asked}};
    auto made = line >= 1 && line <= UINT32_MAX ? cell_->breakAtLine(p, static_cast<std::uint32_t>(line))
                                                : diag::Result<int>(diag::refusal("no such line"));
    if (!made) {
      result["message"] = made.failure().message;
      out.push_back(result);
      continue;
    }
    std::optional<debug::Condition> condition;
    std::optional<debug::HitCondition> hits;
    if (std::string problem = qualifiers(b, *cell_->cell().robot(p).spec().image, condition, hits); !problem.empty()) {
      cell_->remove(*made);
      result["message"] = std::move(problem);
      out.push_back(result);
      continue;
    }
    cell_->qualify(*made, condition, hits);
    cellBreakpoints_[p].push_back(*made);
    out.push_back({{"id", *made}, {"verified", true},
                   {"line", clientLine(cell_->lineWithCode(p, static_cast<std::uint32_t>(line)))}});
  }
  return Json{{"breakpoints", out}};
}

Adapter::Reply Adapter::cellStackTrace(const Json& args) {
  const std::optional<std::size_t> thread = cellThread(args);
  if (!thread) return Error{"no such thread"};
  const std::size_t p = *thread;
  const runtime::RunView v = cell_->view(p);
  const vm::Image& image = *cell_->cell().robot(p).spec().image;
  const diag::SourceFile& src = cellSources_[p];
  const Json source = {{"name", std::filesystem::path(cellPaths_[p]).filename().string()}, {"path", cellPaths_[p]}};
  const auto name = [&](std::uint32_t line, std::uint32_t instruction) {
    if (line >= 1 && line <= src.lineCount()) {
      std::string_view text = src.line(line);
      text = debug::trimmed(text.substr(0, text.find(';')));
      if (!text.empty()) return base::safeText(text);
    }
    return base::safeText(vm::instructionText(image, instruction));
  };
  const auto column = [&](std::uint32_t instruction) {
    return clientColumn(image.columns.empty() ? 1 : image.columns[instruction]);
  };
  const std::int64_t base = static_cast<std::int64_t>(p + 1) * kCellPerThread;
  Json frames = Json::array();
  frames.push_back({{"id", base}, {"name", name(v.line, v.instruction)}, {"source", source},
                    {"line", clientLine(v.line)}, {"column", column(v.instruction)}});
  std::int64_t id = base + 1;
  for (auto f = v.callStack.rbegin(); f != v.callStack.rend(); ++f, ++id)
    frames.push_back({{"id", id}, {"name", name(f->line, f->gosub)}, {"source", source},
                      {"line", clientLine(f->line)}, {"column", column(f->gosub)}});
  return Json{{"stackFrames", frames}, {"totalFrames", frames.size()}};
}

Adapter::Reply Adapter::cellScopes(const Json& args) {
  const std::int64_t frame = args.at("frameId").get<std::int64_t>();
  const std::int64_t thread = frame / kCellPerThread;
  if (thread < 1 || thread > static_cast<std::int64_t>(cell_->size())) return Error{fmt::format("no frame {}", frame)};
  const runtime::RunView v = cell_->view(static_cast<std::size_t>(thread - 1));
  const auto scope = [&](std::string_view name, std::int64_t kind, std::size_t count) {
    return Json{{"name", name}, {"variablesReference", thread * kCellPerThread + kind}, {"namedVariables", count}, {"expensive", false}};
  };
  Json scopes = Json::array({scope("Variables", kCellVariablesScope, v.variables.size()),
                             scope("Motors", kCellMotorsScope, v.motors.size() + (v.tcp ? 1 : 0)),
                             scope("Inputs/Outputs", kCellIoScope, 2 * vm::kIoCount), scope("Clock", kCellClockScope, 2)});
  const runtime::Run& run = cell_->cell().robot(static_cast<std::size_t>(thread - 1));
  if (const std::vector<debug::DeviceRow> rows = debug::deviceRows(run, v); !rows.empty())
    scopes.push_back(scope("Devices", kCellDevicesScope, rows.size()));
  return Json{{"scopes", scopes}};
}

Adapter::Reply Adapter::cellVariables(const Json& args) {
  const std::int64_t ref = args.at("variablesReference").get<std::int64_t>();
  const std::int64_t thread = ref / kCellPerThread;
  if (thread < 1 || thread > static_cast<std::int64_t>(cell_->size()))
    return Error{fmt::format("no variables with reference {}", ref)};
  const auto p = static_cast<std::size_t>(thread - 1);
  const runtime::RunView v = cell_->view(p);
  const vm::Image& image = *cell_->cell().robot(p).spec().image;
  Json out = Json::array();
  switch (ref % kCellPerThread) {
    case kCellVariablesScope:
      for (const auto& [name, value] : v.variables) out.push_back(cellVariable(base::safeText(name), std::to_string(value)));
      break;
    case kCellMotorsScope:
      for (std::size_t m = 0; m < v.motors.size(); ++m)
        out.push_back(cellVariable(std::string(1, image.motors[m].letter), std::to_string(v.motors[m])));
      if (v.tcp) out.push_back(cellVariable("TCP", fmt::format("({:.3f}, {:.3f}, {:.3f})", (*v.tcp)[0], (*v.tcp)[1], (*v.tcp)[2])));
      break;
    case kCellIoScope:
      for (int i = 1; i <= vm::kIoCount; ++i)
        out.push_back(cellVariable(fmt::format("in {}", i), inputShown(cell_->cell().robot(p), i, vm::lineIsOn(v.inputs, i))));
      for (int i = 1; i <= vm::kIoCount; ++i) out.push_back(cellVariable(fmt::format("out {}", i), vm::lineIsOn(v.outputs, i) ? "on" : "off"));
      break;
    case kCellClockScope:
      out.push_back(cellVariable("time", fmt::format("{} s", base::formatSeconds(v.clock))));
      out.push_back(cellVariable("steps", std::to_string(v.steps)));
      break;
    case kCellDevicesScope:
      for (debug::DeviceRow& row : debug::deviceRows(cell_->cell().robot(p), v))
        out.push_back(cellVariable(std::move(row.name), std::move(row.value)));
      break;
    default:
      return Error{fmt::format("no variables with reference {}", ref)};
  }
  return Json{{"variables", out}};
}

// An input of a thread's Inputs/Outputs, as the terminal's `set input N
// on|off`: a stimulus at the cell's present moment (CellSession::setInput).
Adapter::Reply Adapter::cellSetVariable(const Json& args) {
  const std::int64_t ref = args.at("variablesReference").get<std::int64_t>();
  const std::int64_t thread = ref / kCellPerThread;
  if (thread < 1 || thread > static_cast<std::int64_t>(cell_->size()) || ref % kCellPerThread < 1 ||
      ref % kCellPerThread > kCellLastScope)
    return Error{fmt::format("no variables with reference {}", ref)};
  if (ref % kCellPerThread != kCellIoScope)
    return Error{"on a cell of several robots only inputs can be set: the variables, motors, clock and devices are the run's"};
  const auto p = static_cast<std::size_t>(thread - 1);
  const std::string value = args.at("value").get<std::string>();
  int input = 0;
  bool on = false;
  if (auto bad = inputSetting(*cell_->cell().robot(p).spec().image, args.at("name").get<std::string>(),
                              debug::trimmed(value), input, on))
    return *bad;
  if (auto problem = cell_->setInput(p, input, on)) return Error{*problem};
  return Json{{"value", on ? "on" : "off"}, {"variablesReference", 0}};
}

// One value of a robot (the frame's thread, else the current robot): what the terminal's print takes.
Adapter::Reply Adapter::cellEvaluate(const Json& args) {
  std::size_t p = cell_->current();
  if (args.contains("frameId")) {
    const std::int64_t thread = args.at("frameId").get<std::int64_t>() / kCellPerThread;
    if (thread < 1 || thread > static_cast<std::int64_t>(cell_->size())) return Error{"no such frame"};
    p = static_cast<std::size_t>(thread - 1);
  }
  const std::int64_t base = static_cast<std::int64_t>(p + 1) * kCellPerThread;
  const std::string asked = args.at("expression").get<std::string>();
  return evaluateIn(cell_->cell().robot(p), cell_->view(p), debug::trimmed(asked),
                    {base + kCellVariablesScope, base + kCellMotorsScope, base + kCellIoScope, 0, base + kCellDevicesScope});
}

void Adapter::reportCellStop(const debug::CellStop& stop) {
  using debug::StopReason;
  const auto stopped = [&](std::string_view reason) {
    Json body = {{"reason", reason}, {"threadId", stop.robot + 1}, {"allThreadsStopped", true}, {"description", stop.message}};
    if (!stop.breakpoints.empty()) body["hitBreakpointIds"] = stop.breakpoints;
    if (stop.finished()) body["text"] = stop.message;
    event("stopped", std::move(body));
  };
  const auto among = [&stop](const std::vector<int>& ids) {
    return std::any_of(ids.begin(), ids.end(), [&stop](int id) {
      return std::find(stop.breakpoints.begin(), stop.breakpoints.end(), id) != stop.breakpoints.end();
    });
  };
  // The collision and warning filters' stops are exceptions, as for one robot.
  if (!stop.finished() && among(exceptionBreakpoints_)) {
    Json body = {{"reason", "exception"}, {"threadId", stop.robot + 1}, {"allThreadsStopped", true},
                 {"description", stop.message}, {"text", stop.message}, {"hitBreakpointIds", stop.breakpoints}};
    return event("stopped", std::move(body));
  }
  // A device's or label's breakpoint is the client's function breakpoint (a line's too: the line's reason).
  const bool atLine = std::any_of(cellBreakpoints_.begin(), cellBreakpoints_.end(), among);
  const bool atDevice = among(functionBreakpoints_);
  if (!stop.finished() && atDevice && !atLine) return stopped("function breakpoint");
  if (!stop.finished()) return stopped(vm::adapterReason(stop.reason));
  if (stop.reason == StopReason::End) {
    output("console", stop.message + "\n");
    event("exited", {{"exitCode", 0}});
    event("terminated");
    state_ = State::Terminated;
    return;
  }
  const bool stops = stop.reason == StopReason::Deadlock       ? stopOnDeadlock_
                     : stop.reason == StopReason::RuntimeError ? stopOnRuntimeError_
                                                               : stopOnLimit_;
  if (stops) return stopped(vm::adapterReason(stop.reason));
  output("stderr", stop.message + "\n");
  event("exited", {{"exitCode", 1}});
  event("terminated");
  state_ = State::Terminated;
}

}  // namespace rs::dap
