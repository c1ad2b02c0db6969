// The language server: the lifecycle (initialize, initialized, shutdown,
// exit), the document notifications, and every feature's method wired to
// its function in lsp/features/. Messages come in batches, every message
// that had arrived when the server last looked; diagnostics are published
// once a batch is handled, for the documents it changed. That is the
// debounce: while the client sends faster than the server checks, edits
// pile up and are checked once.
#pragma once

#include <functional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "lsp/dispatcher.h"
#include "lsp/document.h"
#include "lsp/json.h"
#include "lsp/jsonrpc.h"
#include "lsp/message_reader.h"
#include "lsp/transport.h"
#include "lsp/workspace.h"

namespace rs::lsp {

class Server {
 public:
  /// `send` writes one message to the client; false when it is gone.
  using Send = std::function<bool(const Json&)>;
  Server(Send send, std::ostream& log);

  /// Handles a batch of frames: cancellations first, then each message in order.
  void receive(const std::vector<Frame>& frames);
  /// Publishes the diagnostics of the documents changed since the last call.
  void publishPending();

  /// After `exit`, or once the client is gone.
  bool finished() const { return state_ == State::Exited || clientGone_; }
  /// 0 after shutdown then exit; 1 otherwise (LSP: exit without shutdown).
  int exitCode() const { return state_ == State::Exited && shutdown_ ? 0 : 1; }
  bool shutdownReceived() const { return shutdown_; }
  Workspace& workspace() { return workspace_; }

 private:
  enum class State { Uninitialized, Running, Exited };

  void handle(const IncomingMessage& message, const std::set<std::string>& cancelled);
  void send(const Json& message);
  void registerHandlers();
  Reply initialize(const Json& params);
  void didOpen(const Json& params, bool invalidUtf8);
  void didChange(const Json& params, bool invalidUtf8);
  void settingsFrom(const Json& options);
  void allProgramsChanged();
  Json diagnosticsOf(const Document& doc);
  Reply workspaceSymbols(const Json& params);

  Send send_;
  std::ostream& log_;
  Dispatcher dispatcher_;
  Workspace workspace_;
  State state_ = State::Uninitialized;
  bool shutdown_ = false;
  bool clientGone_ = false;
  Encoding encoding_ = Encoding::Utf16;
  bool snippets_ = false;
  std::set<std::string> pending_;  // URIs whose diagnostics are due
  bool currentInvalidUtf8_ = false;
};

/// Runs a server on a byte stream until `exit` or the end of input; the
/// process's exit code.
int serve(Input& in, Output& out, std::ostream& log);

}  // namespace rs::lsp
