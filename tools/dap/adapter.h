// The debug adapter: the Debug Adapter Protocol on a debug::DebugSession, for
// VS Code and any DAP client. One thread ("program"), the GOSUB stack as
// its stack trace, five scopes (Variables, Motors with the tool centre
// point, Inputs/Outputs, Objects, Clock), line breakpoints with variable
// conditions and hit counts, exception breakpoints for deadlock, runtime
// error and limit, stepping in, over and out, and backwards (stepBack,
// reverseContinue: the capability supportsStepBack).
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
  std::string frameName(std::uint32_t line, std::uint32_t instruction) const;
  /// After the response to a request that moved the run: the events.
  void reportStop(const debug::Stop& stop);

  Send send_;
  std::ostream& log_;
  std::int64_t seq_ = 1;
  State state_ = State::New;
  bool clientGone_ = false;
  bool disconnected_ = false;
  std::unique_ptr<debug::DebugSession> session_;
  std::optional<diag::SourceFile> source_;
  std::string sourcePath_;
  std::vector<int> lineBreakpoints_;  // session ids from setBreakpoints
  bool stopOnEntry_ = false;
  bool stopOnDeadlock_ = true, stopOnRuntimeError_ = true, stopOnLimit_ = true;
  // DebugSession ids of the breakpoints the "collision" and "warning" exception
  // filters made (a stop by one of them is reported as an exception).
  std::vector<int> exceptionBreakpoints_;
  std::function<bool()> poll_;
  std::function<void()> pending_;  // the move a request asked for, run after its response
};

}  // namespace rs::dap
