// The debug adapter: the Debug Adapter Protocol on a debug::DebugSession, for
// VS Code and any DAP client. One thread ("program"), the GOSUB stack as
// its stack trace, five scopes (Variables, Motors with the tool centre
// point, Inputs/Outputs, Objects, Clock; paged by start and count), line
// breakpoints and label breakpoints (function breakpoints) with variable
// conditions and hit counts, watches (data breakpoints), exception
// breakpoints for deadlock, runtime error, limit, collision and warning,
// stepping in, over and out, and backwards (stepBack, reverseContinue:
// the capability supportsStepBack), setVariable for variables and
// inputs, and the custom request gotoTime. Lines and columns count from 1
// or 0, as the client's initialize says.
//
// A launch with a `cell` and no `program` debugs the cell's robots
// together (cell_requests.cpp, a debug::CellSession): one thread per robot,
// a stop stops them all, stepBack and reverseContinue put the whole cell
// back.
//
// Every request gets a response: a malformed message, a request before
// `initialize` or before `launch`, or one with bad arguments is answered
// with success false and a message, and the adapter goes on. A run that
// takes long asks `poll` between slices whether the client wants it
// paused, or has gone.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "diag/source_file.h"
#include "launch/program.h"
#include "launch/run_request.h"
#include "tools/debug/cell_session.h"
#include "tools/debug/debug_session.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace rs::dap {

using wire::Json;

class Adapter {
 public:
  /// `send` writes one message; false when the client is gone.
  using Send = std::function<bool(const Json&)>;
  Adapter(Send send, std::ostream& log);
  ~Adapter();

  /// Handles one frame from the client.
  void receive(const wire::Frame& frame);
  /// Asked between slices of a long run: true pauses it (a pause,
  /// terminate or disconnect request arrived, or the client left).
  void setPoll(std::function<bool()> poll) { poll_ = std::move(poll); }

  /// After disconnect, or once the client is gone.
  bool finished() const { return disconnected_ || clientGone_; }
  bool disconnected() const { return disconnected_; }

 private:
  enum class State { New, Initialized, Launched, Running, Terminated };
  struct Error {
    std::string message;
  };
  using Reply = std::variant<Json, Error>;

  void handle(const Json& request);
  Reply dispatch(const std::string& command, const Json& args);
  void send(Json message);
  void respond(const Json& request, const Reply& reply);
  void event(std::string_view name, Json body = Json::object());
  void output(std::string_view category, std::string text);

  Reply initialize(const Json& args);
  Reply launch(const Json& args);
  Reply setBreakpoints(const Json& args);
  Reply setExceptionBreakpoints(const Json& args);
  Reply stackTrace(const Json& args);
  Reply scopes(const Json& args);
  Reply variables(const Json& args);
  Reply evaluate(const Json& args);
  Reply setVariable(const Json& args);
  Reply setFunctionBreakpoints(const Json& args);
  Reply dataBreakpointInfo(const Json& args);
  Reply setDataBreakpoints(const Json& args);
  Reply gotoTime(const Json& args);
  /// gotoTime's {"time": SECONDS} (a number, or a string as the
  /// terminal's goto-time takes it) into `at`, or what is wrong with it.
  static std::optional<Error> gotoTimeArgument(const Json& args, vm::Micros& at);
  /// A breakpoint's condition and hitCondition (DAP's fields) on session
  /// breakpoint `id`: the problem with them, or "" when they are set.
  std::string qualify(int id, const Json& breakpoint);
  /// A breakpoint's condition and hitCondition, read on `image`'s program:
  /// what is wrong with them, else empty.
  static std::string qualifiers(const Json& breakpoint, const vm::Image& image, std::optional<debug::Condition>& condition,
                                std::optional<debug::HitCondition>& hits);
  /// Lines and columns as the client counts them (from 1 or from 0), and back.
  std::int64_t clientLine(std::uint32_t line) const { return std::int64_t{line} - 1 + lineBase_; }
  std::int64_t clientColumn(std::uint32_t column) const { return std::int64_t{column} - 1 + columnBase_; }
  std::int64_t ownLine(std::int64_t line) const { return line + 1 - lineBase_; }
  std::string frameName(std::uint32_t line, std::uint32_t instruction) const;
  /// After the response to a request that moved the run: the events.
  void reportStop(const debug::Stop& stop);

  // A cell of several robots (cell_requests.cpp).
  Reply launchCell(const launch::ProgramRequest& program, const launch::RunRequest& run, const Json& args);
  Reply cellDispatch(const std::string& command, const Json& args);
  Reply cellSetBreakpoints(const Json& args);
  Reply cellStackTrace(const Json& args);
  Reply cellScopes(const Json& args);
  Reply cellVariables(const Json& args);
  Reply cellEvaluate(const Json& args);
  /// The variablesReference of each scope that evaluate answers a whole
  /// scope with (0: the client has no such scope to open).
  struct ScopeRefs {
    std::int64_t variables = 0, motors = 0, io = 0, objects = 0, devices = 0;
  };
  /// What evaluate answers for `text` on `run` as `view` shows it (one
  /// robot's, or one robot of a cell's).
  static Reply evaluateIn(const runtime::Run& run, const runtime::RunView& view, std::string_view text, const ScopeRefs& refs);
  /// An input's value as the Inputs scope and evaluate show it: "on", or
  /// "on (since 10.000 s: wire from sensor eye)" when something changed it.
  static std::string inputShown(const runtime::Run& run, int input, bool on);
  Reply cellSetFunctionBreakpoints(const Json& args);
  Reply cellSetVariable(const Json& args);
  /// setVariable's `in N` = on|off on `image`'s program: the input and its value, or what is wrong.
  static std::optional<Error> inputSetting(const vm::Image& image, const std::string& name, std::string_view typed,
                                           int& input, bool& on);
  Reply cellDataBreakpointInfo(const Json& args);
  Reply cellSetDataBreakpoints(const Json& args);
  /// The robot a request's threadId names (the current one without it); nullopt: none.
  std::optional<std::size_t> cellThread(const Json& args) const;
  void reportCellStop(const debug::CellStop& stop);

  Send send_;
  std::ostream& log_;
  std::int64_t seq_ = 1;
  State state_ = State::New;
  bool clientGone_ = false;
  bool disconnected_ = false;
  std::unique_ptr<debug::DebugSession> session_;
  std::unique_ptr<debug::CellSession> cell_;
  std::vector<diag::SourceFile> cellSources_;  // per robot (program index)
  std::vector<std::string> cellPaths_;         // per robot: its program's absolute path
  std::vector<std::vector<int>> cellBreakpoints_;  // per robot: the ids setBreakpoints made
  std::optional<diag::SourceFile> source_;
  std::string sourcePath_;
  int lineBase_ = 1, columnBase_ = 1;  // initialize's linesStartAt1, columnsStartAt1
  std::vector<int> lineBreakpoints_;  // session ids from setBreakpoints
  std::vector<int> functionBreakpoints_;  // from setFunctionBreakpoints: labels
  std::vector<int> dataBreakpoints_;  // from setDataBreakpoints: watches
  bool stopOnEntry_ = false;
  bool stopOnDeadlock_ = true, stopOnRuntimeError_ = true, stopOnLimit_ = true;
  // DebugSession ids of the breakpoints the "collision" and "warning" exception
  // filters made (a stop by one of them is reported as an exception).
  std::vector<int> exceptionBreakpoints_;
  std::function<bool()> poll_;
  std::function<void()> pending_;  // the move a request asked for, run after its response
};

}  // namespace rs::dap
