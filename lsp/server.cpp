#include "lsp/server.h"

#include <fmt/format.h>

#include "base/file_io.h"
#include "base/text.h"
#include "lsp/features/features.h"
#include "lsp/protocol.h"
#include "lsp/uri.h"

namespace rs::lsp {

namespace {

constexpr std::size_t kMaxWorkspaceFileBytes = std::size_t{4} << 20;
constexpr std::size_t kMaxWorkspaceFiles = 500;

std::string idKey(const Json& id) { return dumpJson(id); }

Json capabilities(Encoding enc) {
  return {
      {"positionEncoding", enc == Encoding::Utf8 ? "utf-8" : "utf-16"},
      {"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
      {"hoverProvider", true},
      {"completionProvider", {{"triggerCharacters", {" ", ":"}}, {"resolveProvider", false}}},
      {"signatureHelpProvider", {{"triggerCharacters", {" "}}, {"retriggerCharacters", {" "}}}},
      {"definitionProvider", true},
      {"referencesProvider", true},
      {"documentHighlightProvider", true},
      {"documentSymbolProvider", true},
      {"workspaceSymbolProvider", true},
      {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}},
      {"documentFormattingProvider", true},
      {"renameProvider", {{"prepareProvider", true}}},
      {"foldingRangeProvider", true},
      {"inlayHintProvider", true},
      {"semanticTokensProvider", {{"legend", semanticTokensLegend()}, {"full", true}}},
  };
}

}  // namespace

Server::Server(Send send, std::ostream& log) : send_(std::move(send)), log_(log) { registerHandlers(); }

void Server::send(const Json& message) {
  if (!clientGone_ && !send_(message)) clientGone_ = true;
}

void Server::receive(const std::vector<Frame>& frames) {
  // Read everything first: a $/cancelRequest later in the batch cancels
  // a request before it. Then everything in order.
  std::vector<IncomingMessage> messages;
  std::set<std::string> cancelled;
  for (const Frame& f : frames) {
    if (f.kind != Frame::Kind::Message) log_ << "robotsim lsp: " << f.problem << '\n';
    IncomingMessage m = readMessage(f);
    if (m.kind != IncomingMessage::Kind::Invalid && m.kind != IncomingMessage::Kind::Response &&
        m.method == "$/cancelRequest" && m.params.is_object() && m.params.contains("id"))
      cancelled.insert(idKey(m.params["id"]));
    messages.push_back(std::move(m));
  }
  for (const IncomingMessage& m : messages) {
    if (finished()) break;
    handle(m, cancelled);
  }
}

void Server::handle(const IncomingMessage& m, const std::set<std::string>& cancelled) {
  using Kind = IncomingMessage::Kind;
  if (m.kind == Kind::Invalid) {
    send(response(m.id, m.error));
    return;
  }
  if (m.kind == Kind::Response) return;  // a client's response: nothing asked for one
  const std::string& method = m.method;
  const Json& params = m.params;
  if (m.kind == Kind::Notification) {
    if (method == "exit") {
      state_ = State::Exited;
      return;
    }
    if (state_ != State::Running || method.starts_with("$/")) return;
    currentInvalidUtf8_ = m.invalidUtf8;
    dispatcher_.notify(method, params);
    currentInvalidUtf8_ = false;
    return;
  }
  const Json& id = m.id;
  if (state_ == State::Uninitialized && method != "initialize") {
    send(response(id, RpcError{errc::kServerNotInitialized, "the server is not initialized: send initialize first"}));
    return;
  }
  if (cancelled.count(idKey(id))) {
    send(response(id, RpcError{errc::kRequestCancelled, "cancelled"}));
    return;
  }
  if (method == "initialize") {
    send(response(id, state_ == State::Uninitialized ? initialize(params)
                                                     : Reply(RpcError{errc::kInvalidRequest, "initialize was already received"})));
    return;
  }
  if (shutdown_) {
    send(response(id, RpcError{errc::kInvalidRequest, "the server is shutting down: only exit is expected"}));
    return;
  }
  send(response(id, dispatcher_.request(method, params)));
}

void Server::settingsFrom(const Json& options) {
  if (!options.is_object()) return;
  const Json& s = options.contains("robotsim") && options["robotsim"].is_object() ? options["robotsim"] : options;
  Settings settings;
  if (s.contains("cell") && s["cell"].is_string()) settings.cell = s["cell"].get<std::string>();
  if (s.contains("lib") && s["lib"].is_array())
    for (const Json& dir : s["lib"])
      if (dir.is_string()) settings.libDirs.push_back(dir.get<std::string>());
  workspace_.setSettings(std::move(settings));
}

Reply Server::initialize(const Json& params) {
  if (!params.is_object()) return RpcError{errc::kInvalidParams, "initialize takes an object"};
  const Json caps = params.value("capabilities", Json::object());
  if (caps.contains("general") && caps["general"].contains("positionEncodings"))
    for (const Json& e : caps["general"]["positionEncodings"])
      if (e == "utf-8") encoding_ = Encoding::Utf8;
  const Json completionItem =
      caps.value("textDocument", Json::object()).value("completion", Json::object()).value("completionItem", Json::object());
  snippets_ = completionItem.value("snippetSupport", false);
  std::string root;
  if (params.contains("workspaceFolders") && params["workspaceFolders"].is_array() && !params["workspaceFolders"].empty())
    root = pathOfUri(params["workspaceFolders"][0].value("uri", ""));
  if (root.empty() && params.contains("rootUri") && params["rootUri"].is_string())
    root = pathOfUri(params["rootUri"].get<std::string>());
  workspace_.setRoot(root);
  settingsFrom(params.value("initializationOptions", Json(nullptr)));
  state_ = State::Running;
  return Json{{"capabilities", capabilities(encoding_)}, {"serverInfo", {{"name", "robotsim"}, {"version", "0.1.0"}}}};
}

void Server::didOpen(const Json& params, bool invalidUtf8) {
  const Json& td = params.at("textDocument");
  const std::string uri = td.at("uri").get<std::string>();
  Document& doc = workspace_.open(uri, languageOf(td.value("languageId", ""), uri), td.value("version", 0),
                                  td.at("text").get<std::string>());
  doc.setHadInvalidUtf8(invalidUtf8);
  if (doc.language() == Language::Description) workspace_.descriptionsChanged(), allProgramsChanged();
  pending_.insert(uri);
}

void Server::didChange(const Json& params, bool invalidUtf8) {
  const Json& td = params.at("textDocument");
  Document* doc = workspace_.document(td.at("uri").get<std::string>());
  if (!doc) return;
  for (const Json& change : params.at("contentChanges")) {
    std::optional<Range> range;
    if (change.contains("range")) range = rangeFrom(change["range"]);
    doc->edit(range, change.at("text").get<std::string>(), encoding_);
  }
  if (td.contains("version") && td["version"].is_number_integer()) doc->setVersion(td["version"].get<std::int64_t>());
  if (invalidUtf8) doc->setHadInvalidUtf8(true);
  pending_.insert(doc->uri());
}

void Server::allProgramsChanged() {
  for (const auto& [uri, doc] : workspace_.documents())
    if (doc.language() == Language::Program) pending_.insert(uri);
}

Json Server::diagnosticsOf(const Document& doc) {
  switch (doc.language()) {
    case Language::Program: {
      const auto analysis = workspace_.program(doc);
      return programDiagnostics({doc, *analysis, encoding_});
    }
    case Language::Description: return descriptionDiagnostics(doc, encoding_);
    case Language::Stimuli: return stimuliDiagnostics(doc, encoding_);
    case Language::Other: return Json::array();
  }
  return Json::array();
}

void Server::publishPending() {
  for (const std::string& uri : pending_) {
    if (finished()) break;
    const Document* doc = workspace_.document(uri);
    Json params = {{"uri", uri}, {"diagnostics", doc ? diagnosticsOf(*doc) : Json::array()}};
    if (doc) params["version"] = doc->version();
    send(notification("textDocument/publishDiagnostics", std::move(params)));
  }
  pending_.clear();
}

Reply Server::workspaceSymbols(const Json& params) {
  const std::string query = params.value("query", "");
  Json out = Json::array();
  std::set<std::string> seen;
  for (const auto& [uri, doc] : workspace_.documents()) {
    if (doc.language() != Language::Program) continue;
    seen.insert(pathOfUri(uri));
    lsp::workspaceSymbols({doc, *workspace_.program(doc), encoding_}, query, out);
  }
  std::size_t read = 0;
  for (const std::string& path : workspace_.files(".rsp")) {
    if (seen.count(path) || ++read > kMaxWorkspaceFiles) continue;
    base::FileRead file = base::readFile(path, kMaxWorkspaceFileBytes);
    if (!file.bytes) continue;
    const Document doc(uriOfPath(path), Language::Program, 0, *file.bytes);
    const auto analysis = workspace_.programFile(path, std::move(*file.bytes));
    lsp::workspaceSymbols({doc, *analysis, encoding_}, query, out);
  }
  return out;
}

void Server::registerHandlers() {
  Dispatcher& d = dispatcher_;
  d.onRequest("shutdown", [this](const Json&) -> Reply {
    shutdown_ = true;
    return Json(nullptr);
  });
  d.onNotification("initialized", [](const Json&) {});
  d.onNotification("textDocument/didOpen", [this](const Json& p) { didOpen(p, currentInvalidUtf8_); });
  d.onNotification("textDocument/didChange", [this](const Json& p) { didChange(p, currentInvalidUtf8_); });
  d.onNotification("textDocument/didClose", [this](const Json& p) {
    const std::string uri = p.at("textDocument").at("uri").get<std::string>();
    workspace_.close(uri);
    pending_.insert(uri);  // publishes an empty list: the markers go
  });
  d.onNotification("textDocument/didSave", [this](const Json& p) {
    if (languageOf("", p.at("textDocument").at("uri").get<std::string>()) == Language::Description)
      workspace_.descriptionsChanged(), allProgramsChanged();
  });
  d.onNotification("workspace/didChangeConfiguration", [this](const Json& p) {
    settingsFrom(p.value("settings", Json(nullptr)));
    allProgramsChanged();
  });
  d.onNotification("workspace/didChangeWatchedFiles", [this](const Json&) {
    workspace_.descriptionsChanged();
    allProgramsChanged();
  });

  // Each request on a document: its analysis, by language.
  const auto on = [this](const std::string& method, std::function<Reply(const ProgramContext&, const Json&)> program,
                         std::function<Reply(const Document&, const Json&)> other = nullptr) {
    dispatcher_.onRequest(method, [this, program, other](const Json& params) -> Reply {
      Document* doc = workspace_.document(params.at("textDocument").at("uri").get<std::string>());
      if (!doc) return Json(nullptr);
      if (doc->language() != Language::Program) return other ? other(*doc, params) : Reply(Json(nullptr));
      const auto analysis = workspace_.program(*doc);
      return program({*doc, *analysis, encoding_}, params);
    });
  };
  const auto position = [](const Json& params) { return positionFrom(params.at("position")); };
  on("textDocument/hover", [position](const ProgramContext& p, const Json& q) -> Reply { return hover(p, position(q)); },
     [this, position](const Document& doc, const Json& q) -> Reply {
       if (doc.language() == Language::Description)
         return descriptionHover(doc, encoding_, position(q), workspace_.cells().searchPath());
       if (doc.language() == Language::Stimuli) return stimuliHover(doc, encoding_, position(q));
       return Json(nullptr);
     });
  on("textDocument/definition",
     [this, position](const ProgramContext& p, const Json& q) -> Reply {
       return definition(p, position(q), workspace_.cells().searchPath());
     },
     [this, position](const Document& doc, const Json& q) -> Reply {
       if (doc.language() != Language::Description) return Json(nullptr);
       return descriptionDefinition(doc, encoding_, position(q), workspace_.cells().searchPath());
     });
  on("textDocument/references", [position](const ProgramContext& p, const Json& q) -> Reply {
    return references(p, position(q), q.value("context", Json::object()).value("includeDeclaration", true));
  });
  on("textDocument/documentHighlight",
     [position](const ProgramContext& p, const Json& q) -> Reply { return documentHighlight(p, position(q)); });
  on("textDocument/prepareRename",
     [position](const ProgramContext& p, const Json& q) -> Reply { return prepareRename(p, position(q)); });
  on("textDocument/rename", [position](const ProgramContext& p, const Json& q) -> Reply {
    return rename(p, position(q), q.at("newName").get<std::string>());
  });
  on("textDocument/documentSymbol", [](const ProgramContext& p, const Json&) -> Reply { return documentSymbols(p); },
     [this](const Document& doc, const Json&) -> Reply {
       if (doc.language() == Language::Description) return descriptionSymbols(doc, encoding_);
       if (doc.language() == Language::Stimuli) return stimuliSymbols(doc, encoding_);
       return Json::array();
     });
  on("textDocument/foldingRange", [](const ProgramContext& p, const Json&) -> Reply { return foldingRanges(p); });
  on("textDocument/formatting",
     [this](const ProgramContext& p, const Json&) -> Reply { return formatting(p.doc, encoding_); });
  on("textDocument/completion", [this, position](const ProgramContext& p, const Json& q) -> Reply {
    return completion(p, position(q), snippets_);
  });
  on("textDocument/signatureHelp",
     [position](const ProgramContext& p, const Json& q) -> Reply { return signatureHelp(p, position(q)); });
  on("textDocument/codeAction", [](const ProgramContext& p, const Json& q) -> Reply {
    return codeActions(p, rangeFrom(q.at("range")), q.value("context", Json::object()).value("diagnostics", Json::array()));
  });
  on("textDocument/inlayHint",
     [](const ProgramContext& p, const Json& q) -> Reply { return inlayHints(p, rangeFrom(q.at("range"))); });
  on("textDocument/semanticTokens/full",
     [](const ProgramContext& p, const Json&) -> Reply { return semanticTokens(p); });
  d.onRequest("workspace/symbol", [this](const Json& params) { return workspaceSymbols(params); });
}

int serve(Input& in, Output& out, std::ostream& log) {
  Server server([&out](const Json& message) { return out.write(frameMessage(dumpJson(message))); }, log);
  FrameParser parser;
  std::vector<char> buffer(std::size_t{1} << 16);
  bool eof = false;
  while (!server.finished() && !eof) {
    // Wait for a frame, then take every frame that has arrived meanwhile.
    std::vector<Frame> batch;
    for (;;) {
      while (std::optional<Frame> f = parser.next()) batch.push_back(std::move(*f));
      if ((!batch.empty() && !in.ready()) || eof) break;
      const std::size_t n = in.read(buffer.data(), buffer.size());
      if (n == 0) {
        eof = true;
        continue;
      }
      parser.feed(std::string_view(buffer.data(), n));
    }
    server.receive(batch);
    server.publishPending();
  }
  if (eof && !server.finished()) {
    if (parser.partial()) log << "robotsim lsp: the input ended inside a message\n";
    if (!server.shutdownReceived()) log << "robotsim lsp: the client closed the connection without shutdown\n";
    return server.shutdownReceived() ? 0 : 1;
  }
  return server.exitCode();
}

}  // namespace rs::lsp
