// A language server driven in-process, message by message, for the tests:
// what it sends back is kept and can be looked at by id or by method. The
// server sends from two threads (its own, and the run worker's for the
// run-time diagnostics): idle() publishes and then waits for the runs, so
// that what a test looks at is complete.
#pragma once

#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/lsp/server.h"

namespace rs::testing {

class LspSession {
 public:
  using Json = lsp::Json;

  LspSession()
      : server_(
            [this](const Json& m) {
              const std::lock_guard<std::mutex> lock(mutex_);
              sent_.push_back(m);
              return true;
            },
            log_) {}

  /// initialize (with these client capabilities and options) and initialized.
  Json initialize(Json capabilities = Json::object(), Json options = nullptr, std::string rootUri = "") {
    Json params = {{"processId", nullptr}, {"capabilities", std::move(capabilities)}};
    if (!options.is_null()) params["initializationOptions"] = std::move(options);
    if (!rootUri.empty()) params["rootUri"] = rootUri;
    Json reply = request("initialize", params);
    notify("initialized", Json::object());
    return reply;
  }
  /// Sends a request and returns the whole response message.
  Json request(const std::string& method, Json params) {
    const int id = ++lastId_;
    receive({{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
    return responseTo(id);
  }
  /// The result of a request (null when it answered with an error).
  Json result(const std::string& method, Json params) { return request(method, std::move(params)).value("result", Json()); }
  void notify(const std::string& method, Json params) {
    receive({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
  }
  void receive(const Json& message) { raw(lsp::dumpJson(message)); }
  /// A message body as it came off the wire.
  void raw(std::string body) { server_.receive({lsp::Frame{lsp::Frame::Kind::Message, std::move(body), {}}}); }
  void batch(const std::vector<Json>& messages) {
    std::vector<lsp::Frame> frames;
    for (const Json& m : messages) frames.push_back({lsp::Frame::Kind::Message, lsp::dumpJson(m), {}});
    server_.receive(frames);
  }
  /// The end of a batch: diagnostics of changed documents are published,
  /// then those of their runs.
  void idle() {
    server_.publishPending();
    server_.settle();
  }
  /// The end of a batch without waiting for the runs.
  void publishOnly() { server_.publishPending(); }

  void open(const std::string& uri, const std::string& text, const std::string& languageId = "robotsim-program") {
    notify("textDocument/didOpen",
           {{"textDocument", {{"uri", uri}, {"languageId", languageId}, {"version", 1}, {"text", text}}}});
  }
  /// The last diagnostics published for `uri` (after idle()).
  Json diagnostics(const std::string& uri) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    Json last;
    for (const Json& m : sent_)
      if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri)
        last = m["params"]["diagnostics"];
    return last;
  }
  Json responseTo(const Json& id) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const Json& m : sent_)
      if (m.contains("id") && m["id"] == id && !m.contains("method")) return m;
    return nullptr;
  }
  std::vector<Json> sent() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return sent_;
  }
  void clearSent() {
    const std::lock_guard<std::mutex> lock(mutex_);
    sent_.clear();
  }
  lsp::Server& server() { return server_; }
  std::string log() const { return log_.str(); }

  static Json at(const std::string& uri, unsigned line, unsigned character) {
    return {{"textDocument", {{"uri", uri}}}, {"position", {{"line", line}, {"character", character}}}};
  }
  /// The 0-based line of the first line of `text` that starts with `start`
  /// (an LSP position's line); throws, failing the test, where none does.
  static unsigned lineOf(const std::string& text, const std::string& start) {
    unsigned line = 0;
    for (std::size_t at = 0; at < text.size(); ++line) {
      if (text.compare(at, start.size(), start) == 0) return line;
      at = text.find('\n', at);
      if (at == std::string::npos) break;
      ++at;
    }
    throw std::runtime_error("no line starts with " + start);
  }
  static Json range(unsigned l0, unsigned c0, unsigned l1, unsigned c1) {
    return {{"start", {{"line", l0}, {"character", c0}}}, {"end", {{"line", l1}, {"character", c1}}}};
  }

 private:
  std::ostringstream log_;
  mutable std::mutex mutex_;
  std::vector<Json> sent_;
  lsp::Server server_;  // last: its run worker stops before the rest goes
  int lastId_ = 0;
};

}  // namespace rs::testing
