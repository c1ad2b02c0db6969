// robotsim debug --view: the live workcell page follows the debugger. The
// live-view server (tools/live/live_server.h) serves a
// read-only source (tools/teach/run_source.h) that one DebugSession observer feeds at
// every stop, forwards or backwards (reverse steps, goto-time), and after
// `set input`: the page draws the robot, the objects, the inputs and
// outputs and the clock of the stopped moment, and refuses every command
// (403). On 127.0.0.1 and a free port only, behind a fresh token. The glue
// lives here because tools/debug/ and tools/teach/ may not include each other.
#pragma once

#include <memory>
#include <string>

#include "tools/debug/debug_session.h"
#include "tools/live/live_server.h"
#include "tools/teach/run_source.h"

namespace rs::cli {

class DebugView {
 public:
  /// Serves `session`'s run, drawn on its cell, from now until destroyed
  /// (the session goes on on this thread only; a stop after the view is
  /// gone is not published). Null, with `error` set, when the run has no
  /// workcell or no port is free.
  static std::shared_ptr<DebugView> start(debug::DebugSession& session, const std::string& program, std::string& error);
  ~DebugView();
  DebugView(const DebugView&) = delete;
  DebugView& operator=(const DebugView&) = delete;

  /// The page's address, token included.
  std::string url() const { return server_.url(); }

 private:
  DebugView(const workcell::Workcell& cell, const std::string& program);
  void publish(const debug::DebugSession& session, const debug::Stop& stop);

  teach::RunSource source_;
  live::LiveServer server_;
};

}  // namespace rs::cli
