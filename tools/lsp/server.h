// The language server: the lifecycle (initialize, initialized, shutdown,
// exit), the document notifications, and every feature's method wired to
// its function in tools/lsp/features/. Messages come in batches, every message
// that had arrived when the server last looked; diagnostics are published
// once a batch is handled, for the documents it changed. That is the
// debounce: while the client sends faster than the server checks, edits
// pile up and are checked once.
//
// A program's compile diagnostics are published at once; its run (what
// `robotsim check` runs, checked_run.h) is then made on the run worker's
// thread, and what it finds is published for the same version, with the
// compile's, unless the document has moved on meanwhile (an edit abandons
// the run of the version it replaces). Messages to the client go out one
// at a time, from either thread.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "tools/lsp/dispatcher.h"
#include "tools/lsp/document.h"
#include "tools/lsp/json.h"
#include "tools/lsp/jsonrpc.h"
#include "tools/lsp/message_reader.h"
#include "tools/lsp/run_worker.h"
#include "tools/lsp/transport.h"
#include "tools/lsp/workspace.h"

namespace rs::lsp {

class Server {
 public:
  /// `send` writes one message to the client; false when it is gone. It
  /// is called from the server's thread and the run worker's, never from
  /// both at once.
  using Send = std::function<bool(const Json&)>;
  /// `version` is what initialize reports as serverInfo.version (the
  /// build's, as `robotsim --version` prints it); empty leaves it out.
  Server(Send send, std::ostream& log, std::string version = {});

  /// Handles a batch of frames: cancellations first, then each message in order.
  void receive(const std::vector<Frame>& frames);
  /// Publishes the diagnostics of the documents changed since the last
  /// call, and hands their runs to the run worker.
  void publishPending();
  /// Waits until the run worker has made (and published) every run asked
  /// for so far: tests and benchmarks.
  void settle() { runs_.settle(); }
  /// The editor's bound on a run (checked_run.h); tests shorten it.
  void setRunBudget(std::chrono::milliseconds budget) { runs_.setBudget(budget); }

  /// After `exit`, or once the client is gone.
  bool finished() const { return state_ == State::Exited || clientGone_.load(); }
  /// 0 after shutdown then exit; 1 otherwise (LSP: exit without shutdown).
  int exitCode() const { return state_ == State::Exited && shutdown_ ? 0 : 1; }
  bool shutdownReceived() const { return shutdown_; }
  Workspace& workspace() { return workspace_; }

 private:
  enum class State { Uninitialized, Running, Exited };

  void handle(const IncomingMessage& message, const std::set<std::string>& cancelled);
  void send(const Json& message);
  void sendLocked(const Json& message);  // with sendMutex_ held
  void logProblem(const std::string& problem);
  void registerHandlers();
  Reply initialize(const Field& params);
  void didOpen(const Field& params, bool invalidUtf8);
  void didChange(const Field& params, bool invalidUtf8);
  void allProgramsChanged();
  Json diagnosticsOf(const Document& doc);
  Reply workspaceSymbols(const Field& params);
  void runMade(const RunJob& job, const CheckedRun& run);

  Send send_;
  std::ostream& log_;
  Dispatcher dispatcher_;
  Workspace workspace_;
  State state_ = State::Uninitialized;
  bool shutdown_ = false;
  std::atomic<bool> clientGone_ = false;
  Encoding encoding_ = Encoding::Utf16;
  bool snippets_ = false;
  bool refreshInlayHints_ = false;  // the client takes workspace/inlayHint/refresh
  bool refreshCodeLenses_ = false;  // ... and workspace/codeLens/refresh
  std::uint64_t refreshes_ = 0;     // ids of those requests
  std::string version_;             // serverInfo.version; empty: not reported
  std::set<std::string> pending_;   // URIs whose diagnostics are due
  bool currentInvalidUtf8_ = false;
  std::mutex sendMutex_;  // one message at a time, and a run's check-then-publish
  RunWorker runs_;        // last: its thread stops first
};

/// Runs a server on a byte stream until `exit` or the end of input; the
/// process's exit code.
int serve(Input& in, Output& out, std::ostream& log, std::string version = {});

}  // namespace rs::lsp
