#include "tools/dap/adapter.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/text.h"
#include "launch/program.h"
#include "launch/run_request.h"
#include "tools/dap/message_reader.h"
#include "vm/disasm.h"

namespace rs::dap {

namespace {

constexpr int kThread = 1;

// A request's arguments, read with nlohmann's checked accessors: a wrong
// type throws, which handle() answers as a bad request. The launch
// arguments' own readers name the argument and what it takes, instead of
// nlohmann's "[json.exception.type_error.302] type must be string".
struct BadArgument : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string stringArg(const Json& args, const char* name, std::string fallback = {}) {
  if (!args.contains(name) || args[name].is_null()) return fallback;
  if (!args[name].is_string()) throw BadArgument(fmt::format("{} is a string, not {}", name, args[name].type_name()));
  return args.at(name).get<std::string>();
}

std::vector<std::string> stringsArg(const Json& args, const char* name) {
  if (!args.contains(name) || args[name].is_null()) return {};
  const Json& list = args[name];
  if (!list.is_array() || !std::all_of(list.begin(), list.end(), [](const Json& j) { return j.is_string(); }))
    throw BadArgument(fmt::format("{} is a list of strings", name));
  return list.get<std::vector<std::string>>();
}

}  // namespace

Adapter::Adapter(Send send, std::ostream& log) : send_(std::move(send)), log_(log) {}
Adapter::~Adapter() = default;

void Adapter::send(Json message) {
  if (clientGone_) return;
  message["seq"] = seq_++;
  if (!send_(message)) clientGone_ = true;
}

void Adapter::event(std::string_view name, Json body) {
  send({{"type", "event"}, {"event", name}, {"body", std::move(body)}});
}

void Adapter::output(std::string_view category, std::string text) {
  event("output", {{"category", category}, {"output", std::move(text)}});
}

void Adapter::respond(const Json& request, const Reply& reply) {
  Json r = {{"type", "response"},
            {"request_seq", request.is_object() && request.contains("seq") && request["seq"].is_number_integer()
                                ? request["seq"]
                                : Json(0)},
            {"command", request.is_object() && request.contains("command") && request["command"].is_string()
                            ? request["command"]
                            : Json("")}};
  if (const Json* body = std::get_if<Json>(&reply)) {
    r["success"] = true;
    if (!body->is_null()) r["body"] = *body;
  } else {
    const std::string& message = std::get<Error>(reply).message;
    r["success"] = false;
    r["message"] = message;
    r["body"] = {{"error", {{"id", 1}, {"format", message}, {"showUser", true}}}};
  }
  send(std::move(r));
}

void Adapter::receive(const wire::Frame& frame) {
  if (frame.kind != wire::Frame::Kind::Message) log_ << "robotsim dap: " << frame.problem << '\n';
  const IncomingMessage m = readMessage(frame);
  if (m.kind == IncomingMessage::Kind::Invalid) respond(m.message, Error{m.problem});
  if (m.kind == IncomingMessage::Kind::Request) handle(m.message);
}

void Adapter::handle(const Json& request) {
  const std::string command = request["command"].get<std::string>();
  const Json args = request.value("arguments", Json::object());
  Reply reply = Error{"internal error"};
  try {
    if (!args.is_object()) reply = Error{fmt::format("the arguments of {} are not an object", command)};
    else reply = dispatch(command, args);
  } catch (const Json::exception& e) {
    // nlohmann-json reports a missing or mistyped argument by exception: at
    // this edge it becomes the client's error, never the adapter's end.
    reply = Error{fmt::format("bad arguments for {}: {}", command, wire::jsonProblem(e))};
    pending_ = nullptr;
  } catch (const BadArgument& e) {
    reply = Error{fmt::format("bad arguments for {}: {}", command, e.what())};
    pending_ = nullptr;
  }
  respond(request, reply);
  if (pending_) {
    auto move = std::move(pending_);
    pending_ = nullptr;
    move();
  }
}

Adapter::Reply Adapter::dispatch(const std::string& command, const Json& args) {
  if (command == "initialize") return initialize(args);
  if (state_ == State::New) return Error{"the adapter is not initialized: send initialize first"};
  if (command == "disconnect") {
    disconnected_ = true;
    return Json(nullptr);
  }
  if (command == "launch") return launch(args);
  if (command == "attach") return Error{"attach is not supported: robotsim dap launches the program itself"};
  if (cell_) return cellDispatch(command, args);
  if (command == "threads") return Json{{"threads", Json::array({{{"id", kThread}, {"name", "program"}}})}};
  if (!session_) return Error{fmt::format("{} before launch: launch a program first", command)};
  if (command == "setBreakpoints") return setBreakpoints(args);
  if (command == "setExceptionBreakpoints") return setExceptionBreakpoints(args);
  if (command == "setFunctionBreakpoints") return setFunctionBreakpoints(args);
  if (command == "dataBreakpointInfo") return dataBreakpointInfo(args);
  if (command == "setDataBreakpoints") return setDataBreakpoints(args);
  if (command == "configurationDone") {
    if (state_ != State::Launched) return Error{"configurationDone was already sent"};
    state_ = State::Running;
    pending_ = [this] {
      if (stopOnEntry_) reportStop(session_->lastStop());
      else reportStop(session_->resume());
    };
    return Json(nullptr);
  }
  if (command == "stackTrace") return stackTrace(args);
  if (command == "scopes") return scopes(args);
  if (command == "variables") return variables(args);
  if (command == "evaluate") return evaluate(args);
  if (command == "setVariable") return setVariable(args);
  if (command == "terminate") {
    if (state_ != State::Terminated) pending_ = [this] { event("terminated"); };
    state_ = State::Terminated;
    return Json(nullptr);
  }
  if (command == "pause") return Json(nullptr);  // a run in progress was paused by the poll; a stopped one stays
  const bool moves = command == "continue" || command == "next" || command == "stepIn" || command == "stepOut" ||
                     command == "stepBack" || command == "reverseContinue" || command == "gotoTime";
  if (!moves) return Error{fmt::format("unknown request '{}'", base::safeText(command.substr(0, 60)))};
  if (state_ == State::Launched) return Error{fmt::format("{} before configurationDone", command)};
  if (state_ == State::Terminated) return Error{fmt::format("{}: the debug session has been terminated", command)};
  if (command == "gotoTime") return gotoTime(args);
  if (command == "stepOut") {
    auto r = session_->finish();
    if (!r) return Error{r.failure().message};
    pending_ = [this, stop = *r] { reportStop(stop); };
    // finish() has already run: the response still goes first.
    return Json(nullptr);
  }
  pending_ = [this, command] {
    if (command == "continue") reportStop(session_->resume());
    else if (command == "next") reportStop(session_->next());
    else if (command == "stepIn") reportStop(session_->step());
    else if (command == "stepBack") reportStop(session_->reverseNext());
    else reportStop(session_->reverseContinue());
  };
  if (command == "continue") return Json{{"allThreadsContinued", true}};
  return Json(nullptr);
}

Adapter::Reply Adapter::initialize(const Json& args) {
  if (state_ != State::New) return Error{"initialize was already sent"};
  const auto flag = [&](const char* name) {
    if (!args.contains(name) || args[name].is_null()) return true;  // the protocol's default
    if (!args[name].is_boolean()) throw BadArgument(fmt::format("{} is true or false, not {}", name, args[name].type_name()));
    return args[name].get<bool>();
  };
  lineBase_ = flag("linesStartAt1") ? 1 : 0;
  columnBase_ = flag("columnsStartAt1") ? 1 : 0;
  state_ = State::Initialized;
  return Json{
      {"supportsConfigurationDoneRequest", true},
      {"supportsFunctionBreakpoints", true},
      {"supportsConditionalBreakpoints", true},
      {"supportsHitConditionalBreakpoints", true},
      {"supportsDataBreakpoints", true},
      {"supportsEvaluateForHovers", true},
      {"supportsSetVariable", true},
      {"supportsStepBack", true},
      {"supportsTerminateRequest", true},
      {"exceptionBreakpointFilters",
       Json::array({{{"filter", "deadlock"}, {"label", "Deadlock"}, {"default", true}},
                    {{"filter", "runtimeError"}, {"label", "Runtime error"}, {"default", true}},
                    {{"filter", "limit"}, {"label", "Step or time limit"}, {"default", true}},
                    {{"filter", "collision"},
                     {"label", "Collision"},
                     {"description", "Stop at the moment of each collision (the pose at the first contact)"},
                     {"default", false}},
                    {{"filter", "warning"},
                     {"label", "Gripper closing on nothing"},
                     {"description", "Stop after a closing move that took no object"},
                     {"default", false}}})},
  };
}

Adapter::Reply Adapter::launch(const Json& args) {
  if (session_ || cell_) return Error{"a program was already launched"};
  launch::ProgramRequest program;
  program.file = stringArg(args, "program");
  program.cell = stringArg(args, "cell");
  if (program.file.empty() && program.cell.empty())
    return Error{"launch needs a program (the path of a .rsp or .rsb file), or a cell whose robots have programs"};
  program.libDirs = stringsArg(args, "lib");
  launch::RunRequest run;
  run.stimuliFile = stringArg(args, "stimuli");
  run.collisions = stringArg(args, "collisions");  // error | warn | off, as --collisions
  run.inputs = stringsArg(args, "inputs");
  if (args.contains("maxSteps")) {
    const Json& n = args["maxSteps"];
    if (!n.is_number_unsigned() || n.get<std::uint64_t>() == 0 || n.get<std::uint64_t>() > (std::uint64_t{1} << 62))
      return Error{"maxSteps is a whole number of instructions from 1 (as --max-steps)"};
    run.maxSteps = n.get<std::uint64_t>();
  }
  if (args.contains("maxKnots")) {
    const Json& n = args["maxKnots"];
    if (!n.is_number_unsigned() || n.get<std::uint64_t>() == 0 || n.get<std::uint64_t>() > (std::uint64_t{1} << 62))
      return Error{"maxKnots is a whole number of straight-line knots from 1 (as --max-knots)"};
    run.maxKnots = n.get<std::uint64_t>();
  }
  // Seconds as --max-time reads them: a string as written, a whole number
  // as its digits, any other number with the six decimals it may have.
  if (const Json& t = args.value("maxTime", Json()); t.is_string()) run.maxTime = t.get<std::string>();
  else if (t.is_number_integer()) run.maxTime = t.dump();
  else if (!t.is_null()) run.maxTime = fmt::format("{:.6f}", t.get<double>());
  stopOnEntry_ = args.value("stopOnEntry", false);
  if (program.file.empty() || args.contains("programs")) return launchCell(program, run, args);

  launch::LoadedProgram loaded = launch::loadProgram(program);
  std::vector<diag::Diagnostic> diags = loaded.diagnostics;
  const std::optional<runtime::RunSpec> spec = launch::prepareRun(loaded, run, diags);
  std::ostringstream text;
  launch::printDiagnostics(text, diags, loaded);
  if (!text.str().empty()) output("stderr", text.str());
  if (!spec || !loaded.ok()) {
    std::string first = diags.empty() ? std::string("the program could not be loaded") : diags.front().message;
    // A cell that cannot be loaded is said by its name (the diagnostic's
    // file), as the command line says it; a bad option names itself.
    if (!loaded.ok() && !diags.empty() && !diags.front().file.empty() && diags.front().file != program.file)
      first = diags.front().pos.line == 0
                  ? fmt::format("cell '{}': {}", base::safeText(diags.front().file), first)
                  : fmt::format("{}:{}: {}", base::safeText(diags.front().file), diags.front().pos.line, first);
    return Error{fmt::format("cannot debug {}: {}", base::safeText(program.file), first)};
  }
  session_ = std::make_unique<debug::DebugSession>(*spec);
  session_->setInterrupt([this] { return poll_ && poll_(); });
  if (loaded.source) source_ = loaded.source;
  std::error_code ec;
  sourcePath_ = std::filesystem::absolute(program.file, ec).lexically_normal().string();
  if (ec) sourcePath_ = program.file;
  state_ = State::Launched;
  pending_ = [this] { event("initialized"); };
  return Json(nullptr);
}

Adapter::Reply Adapter::setBreakpoints(const Json& args) {
  Json out = Json::array();
  // Breakpoints in another file (a stimuli file, another program): none of
  // them can stop this run.
  const std::string path = stringArg(args.value("source", Json::object()), "path");
  std::error_code ec;
  if (!path.empty() && std::filesystem::absolute(path, ec).lexically_normal().string() != sourcePath_) {
    for (const Json& b : args.value("breakpoints", Json::array()))
      out.push_back({{"verified", false},
                     {"line", b.at("line").get<std::int64_t>()},
                     {"message", "not the program being debugged"}});  // as the client counts it
    return Json{{"breakpoints", out}};
  }
  for (int id : lineBreakpoints_) session_->remove(id);
  lineBreakpoints_.clear();
  for (const Json& b : args.value("breakpoints", Json::array())) {
    const std::int64_t asked = b.at("line").get<std::int64_t>();
    const std::int64_t line = ownLine(asked);
    Json result = {{"verified", false}, {"line", asked}};
    auto made = line >= 1 && line <= UINT32_MAX ? session_->breakAtLine(static_cast<std::uint32_t>(line))
                                                : diag::Result<int>(diag::refusal("no such line"));
    if (!made) {
      result["message"] = made.failure().message;
      out.push_back(result);
      continue;
    }
    const int id = *made;
    if (const std::string problem = qualify(id, b); !problem.empty()) {
      session_->remove(id);
      result["message"] = problem;
      out.push_back(result);
      continue;
    }
    lineBreakpoints_.push_back(id);
    result = {{"id", id},
              {"verified", true},
              {"line", clientLine(session_->lineWithCode(static_cast<std::uint32_t>(line)))}};
    out.push_back(result);
  }
  return Json{{"breakpoints", out}};
}

std::string Adapter::qualifiers(const Json& b, const vm::Image& image, std::optional<debug::Condition>& condition,
                               std::optional<debug::HitCondition>& hits) {
  if (const std::string c = stringArg(b, "condition"); !c.empty()) {
    auto parsed = debug::parseCondition(image, debug::ioWords(c));
    if (!parsed) return parsed.failure().message;
    condition = *parsed;
  }
  if (const std::string h = stringArg(b, "hitCondition"); !h.empty()) {
    auto parsed = debug::parseHitCondition(h);
    if (!parsed) return parsed.failure().message;
    hits = *parsed;
  }
  return {};
}

std::string Adapter::qualify(int id, const Json& b) {
  std::optional<debug::Condition> condition;
  std::optional<debug::HitCondition> hits;
  if (std::string problem = qualifiers(b, *session_->run().spec().image, condition, hits); !problem.empty()) return problem;
  session_->qualify(id, condition, hits);
  return {};
}

// The custom request of goto-time: {"time": SECONDS} (a number, or a
// string as the terminal's goto-time takes it); answered, then stopped
// with reason goto at that moment, forwards or backwards.
std::optional<Adapter::Error> Adapter::gotoTimeArgument(const Json& args, vm::Micros& at) {
  const Json& t = args.contains("time") ? args["time"] : Json();
  std::string text;
  if (t.is_string()) text = t.get<std::string>();
  else if (t.is_number_integer()) text = t.dump();
  else if (t.is_number_float()) text = fmt::format("{:.6f}", t.get<double>());
  else return Error{"gotoTime needs a time: {\"time\": SECONDS}"};
  const auto parsed = debug::parseSeconds(text);
  if (!parsed) return Error{parsed.failure().message};
  at = *parsed;
  return std::nullopt;
}

Adapter::Reply Adapter::gotoTime(const Json& args) {
  vm::Micros at = 0;
  if (std::optional<Error> bad = gotoTimeArgument(args, at)) return *bad;
  pending_ = [this, micros = at] {
    const debug::Stop stop = session_->gotoTime(micros);
    // Past the end: the session stands at the end and can still go back, as the terminal's does.
    if (stop.reason == debug::StopReason::End)
      event("stopped", {{"reason", "goto"}, {"threadId", kThread}, {"allThreadsStopped", true}, {"description", stop.message}});
    else reportStop(stop);
  };
  return Json(nullptr);
}

Adapter::Reply Adapter::setExceptionBreakpoints(const Json& args) {
  const Json filters = args.value("filters", Json::array());
  for (const Json& f : filters) {
    const std::string name = f.is_string() ? f.get<std::string>() : f.dump();
    if (name != "deadlock" && name != "runtimeError" && name != "limit" && name != "collision" && name != "warning")
      return Error{fmt::format("no exception filter '{}': deadlock, runtimeError, limit, collision, warning",
                               base::safeText(name))};
  }
  stopOnDeadlock_ = stopOnRuntimeError_ = stopOnLimit_ = false;
  if (session_)
    for (int id : exceptionBreakpoints_) session_->remove(id);
  exceptionBreakpoints_.clear();
  Json out = Json::array();
  for (const Json& f : filters) {
    const std::string name = f.get<std::string>();
    if (name == "deadlock") stopOnDeadlock_ = true;
    else if (name == "runtimeError") stopOnRuntimeError_ = true;
    else if (name == "limit") stopOnLimit_ = true;
    else if (!session_) {
      out.push_back({{"verified", false}, {"message", "launch the program first"}});
      continue;
    } else {
      exceptionBreakpoints_.push_back(name == "collision" ? session_->breakOnCollision() : session_->breakOnWarning());
    }
    out.push_back({{"verified", true}});
  }
  return Json{{"breakpoints", out}};
}

void Adapter::reportStop(const debug::Stop& stop) {
  using debug::StopReason;
  const auto stopped = [&](std::string_view reason, const std::string& text) {
    Json body = {{"reason", reason}, {"threadId", kThread}, {"allThreadsStopped", true}, {"description", text}};
    if (!stop.breakpoints.empty()) body["hitBreakpointIds"] = stop.breakpoints;
    if (stop.finished()) body["text"] = text;  // an exception stop
    event("stopped", std::move(body));
  };
  if (!stop.note.empty()) output("console", stop.note + "\n");  // a close on nothing, said at the step
  const bool exception = std::any_of(stop.breakpoints.begin(), stop.breakpoints.end(), [this](int id) {
    return std::find(exceptionBreakpoints_.begin(), exceptionBreakpoints_.end(), id) != exceptionBreakpoints_.end();
  });
  // A collision or warning filter's stop, also where the run ends (a
  // collision under --collisions=error, the default, ends it at the contact).
  if (exception) {
    Json body = {{"reason", "exception"}, {"threadId", kThread}, {"allThreadsStopped", true},
                 {"description", stop.message}, {"text", stop.message}, {"hitBreakpointIds", stop.breakpoints}};
    event("stopped", std::move(body));
    return;
  }
  const auto among = [&stop](const std::vector<int>& ids) {
    return std::any_of(stop.breakpoints.begin(), stop.breakpoints.end(),
                       [&ids](int id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); });
  };
  // A label's breakpoint is the client's function breakpoint; a watch its data breakpoint.
  if (!stop.finished() && among(functionBreakpoints_) && !among(lineBreakpoints_))
    return stopped("function breakpoint", stop.message);
  if (!stop.finished()) return stopped(vm::adapterReason(stop.reason), stop.message);
  if (stop.reason == StopReason::End) {
    output("console", stop.message + "\n");  // "the program ended", with the gripper warning if any
    // The debuggee exits, then the session ends: the protocol's order.
    event("exited", {{"exitCode", 0}});
    event("terminated");
    state_ = State::Terminated;
    return;
  }
  const bool stops = stop.reason == StopReason::Deadlock       ? stopOnDeadlock_
                     : stop.reason == StopReason::RuntimeError ? stopOnRuntimeError_
                                                               : stopOnLimit_;
  if (stops) return stopped(vm::adapterReason(stop.reason), stop.message);  // "exception"
  output("stderr", stop.message + "\n");
  event("exited", {{"exitCode", 1}});
  event("terminated");
  state_ = State::Terminated;
}

}  // namespace rs::dap
