#include "tools/lsp/server.h"

#include <fmt/format.h>

#include <map>

#include "base/file_io.h"
#include "base/text.h"
#include "tools/lsp/params.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "tools/lsp/uri.h"

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
      {"codeLensProvider", {{"resolveProvider", false}}},
      {"callHierarchyProvider", true},
      {"semanticTokensProvider", {{"legend", semanticTokensLegend()}, {"full", true}}},
  };
}

}  // namespace

Server::Server(Send send, std::ostream& log, std::string version)
    : send_(std::move(send)), log_(log), version_(std::move(version)), runs_([this](const RunJob& job, const CheckedRun& run) { runMade(job, run); }) {
  registerHandlers();
}

void Server::send(const Json& message) {
  const std::lock_guard<std::mutex> lock(sendMutex_);
  sendLocked(message);
}

void Server::sendLocked(const Json& message) {
  if (!clientGone_ && !send_(message)) clientGone_ = true;
}

// A notification that could not be acted on has no answer: it is said in
// the server's log and in the client's (window/logMessage, an error).
void Server::logProblem(const std::string& problem) {
  log_ << "robotsim lsp: " << problem << '\n';
  send(notification("window/logMessage", {{"type", 1}, {"message", "robotsim lsp: " + problem}}));
}

void Server::receive(const std::vector<Frame>& frames) {
  // Read everything first: a $/cancelRequest later in the batch cancels
  // a request before it. Then everything in order.
  std::vector<IncomingMessage> messages;
  std::set<std::string> cancelled;
  for (const Frame& f : frames) {
    if (f.kind != Frame::Kind::Message) log_ << "robotsim lsp: " << f.problem << '\n';
    IncomingMessage m = readMessage(f);
    if (m.kind == IncomingMessage::Kind::Notification && m.method == "$/cancelRequest" && m.params.is_object() &&
        m.params.contains("id") && (m.params["id"].is_string() || m.params["id"].is_number_integer()))
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
  if (m.kind == Kind::Response) return;  // a client's response: to a refresh, which needs no answer
  const std::string& method = m.method;
  const Json& params = m.params;
  if (m.kind == Kind::Notification) {
    if (method == "exit") {
      state_ = State::Exited;
      return;
    }
    if (state_ != State::Running || method.starts_with("$/")) return;
    currentInvalidUtf8_ = m.invalidUtf8;
    const std::string problem = dispatcher_.notify(method, params);
    currentInvalidUtf8_ = false;
    if (!problem.empty()) logProblem(problem + " (the notification changed nothing)");
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
    send(response(id, state_ == State::Uninitialized
                          ? Dispatcher::guarded(method, params, [this](const Field& p) { return initialize(p); })
                          : Reply(RpcError{errc::kInvalidRequest, "initialize was already received"})));
    return;
  }
  if (shutdown_) {
    send(response(id, RpcError{errc::kInvalidRequest, "the server is shutting down: only exit is expected"}));
    return;
  }
  send(response(id, dispatcher_.request(method, params)));
}

namespace {

// robotsim.cell, robotsim.lib, robotsim.collisions: at the top level of
// the options or under "robotsim". Options that are not an object say
// nothing to this server (LSPAny).
Settings settingsFrom(const Field& options) {
  Settings settings;
  if (!options.present() || !options.any().is_object()) return settings;
  const Field s = options.any().contains("robotsim") ? options["robotsim"] : options;
  if (!s.present()) return settings;
  s.object();
  settings.cell = s["cell"].string("");
  const Field lib = s["lib"];
  for (std::size_t i = 0; i < lib.size(false); ++i) settings.libDirs.push_back(lib.element(i).string());
  const std::string collisions = s["collisions"].string("error");
  const std::optional<runtime::CollisionMode> mode = runtime::collisionModeByName(collisions);
  if (!mode) throw BadParams(fmt::format("{}: expected \"error\", \"warn\" or \"off\", found \"{}\"",
                                         s["collisions"].path(), base::safeText(collisions)));
  settings.collisions = *mode;
  return settings;
}

}  // namespace

Reply Server::initialize(const Field& params) {
  params.object();
  // Everything is read (and its type checked) before anything changes: a
  // refused initialize leaves the server as it was, ready for another.
  const Field caps = params["capabilities"];
  Encoding encoding = Encoding::Utf16;
  const Field encodings = caps["general"]["positionEncodings"];
  for (std::size_t i = 0; i < encodings.size(false); ++i)
    if (encodings.element(i).string() == "utf-8") encoding = Encoding::Utf8;
  const bool snippets = caps["textDocument"]["completion"]["completionItem"]["snippetSupport"].boolean(false);
  const bool refresh = caps["workspace"]["inlayHint"]["refreshSupport"].boolean(false);
  const bool refreshLenses = caps["workspace"]["codeLens"]["refreshSupport"].boolean(false);
  const std::string rootUri = params["rootUri"].string("");
  std::string root;
  const Field folders = params["workspaceFolders"];
  for (std::size_t i = 0; i < folders.size(false); ++i) {
    const std::string uri = folders.element(i)["uri"].string();
    if (i == 0) root = pathOfUri(uri);
  }
  if (root.empty()) root = pathOfUri(rootUri);
  Settings settings = settingsFrom(params["initializationOptions"]);

  encoding_ = encoding;
  snippets_ = snippets;
  refreshInlayHints_ = refresh;
  refreshCodeLenses_ = refreshLenses;
  workspace_.setRoot(root);
  workspace_.setSettings(std::move(settings));
  state_ = State::Running;
  Json serverInfo{{"name", "robotsim"}};
  if (!version_.empty()) serverInfo["version"] = version_;
  return Json{{"capabilities", capabilities(encoding_)}, {"serverInfo", std::move(serverInfo)}};
}

void Server::didOpen(const Field& params, bool invalidUtf8) {
  const Field td = params["textDocument"];
  const std::string uri = td["uri"].string();
  const std::string languageId = td["languageId"].string("");
  const std::int64_t version = td["version"].optionalInteger().value_or(0);
  Document& doc = workspace_.open(uri, languageOf(languageId, uri), version, td["text"].string());
  doc.setHadInvalidUtf8(invalidUtf8);
  if (doc.language() == Language::Description || doc.language() == Language::Urdf)
    workspace_.descriptionsChanged(), allProgramsChanged();
  if (doc.language() == Language::Stimuli) workspace_.stimuliChanged(), allProgramsChanged();
  pending_.insert(uri);
}

void Server::didChange(const Field& params, bool invalidUtf8) {
  const Field td = params["textDocument"];
  Document* doc = workspace_.document(td["uri"].string());
  const std::optional<std::int32_t> version = td["version"].optionalInteger();
  // Every change is read before the first is made: a malformed one
  // leaves the document as it was.
  struct Change {
    std::optional<Range> range;
    std::string text;
  };
  std::vector<Change> changes;
  const Field list = params["contentChanges"];
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Field c = list.element(i);
    c.object();
    changes.push_back({c["range"].present() ? std::optional<Range>(rangeFrom(c["range"])) : std::nullopt,
                       c["text"].string()});
  }
  if (!doc) return;
  workspace_.changing(doc->uri());
  for (const Change& change : changes) doc->edit(change.range, change.text, encoding_);
  if (version) doc->setVersion(*version);
  if (invalidUtf8) doc->setHadInvalidUtf8(true);
  if (doc->language() == Language::Stimuli) workspace_.stimuliChanged(), allProgramsChanged();
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
    case Language::Urdf: return urdfDiagnostics(doc, encoding_, workspace_.cells().searchPath());
    case Language::Other: return Json::array();
  }
  return Json::array();
}

namespace {

bool hasStimuli(const RunOptions& o) { return o.stimuliText || !o.stimuliPath.empty(); }

}  // namespace

void Server::publishPending() {
  // Programs whose cell runs read a program that changed are checked again.
  for (std::string& uri : workspace_.takeDependents()) pending_.insert(std::move(uri));
  // Every publication first, then the runs: a run that claims another
  // document (a cell run) can then never be followed by an older
  // publication of that document.
  struct Due {
    std::string uri;
    std::shared_ptr<const ProgramAnalysis> analysis;
  };
  std::vector<Due> due;
  std::map<std::string, Json> published;
  for (const std::string& uri : pending_) {
    if (finished()) break;
    const Document* doc = workspace_.document(uri);
    Json params = {{"uri", uri}, {"diagnostics", doc ? diagnosticsOf(*doc) : Json::array()}};
    if (doc) params["version"] = doc->version();
    std::shared_ptr<const ProgramAnalysis> analysis;
    if (doc && doc->language() == Language::Program) analysis = workspace_.program(*doc);
    if (analysis && analysis->ok()) published[uri] = params["diagnostics"];
    // A run made already (the same version published again) goes with it.
    if (analysis)
      if (const CheckedRun* run = analysis->run(); run && run->end != CheckedRun::End::Abandoned)
        params["diagnostics"] = withRunDiagnostics(std::move(params["diagnostics"]),
                                                   runDiagnostics(*analysis, uri, encoding_, *run));
    send(notification("textDocument/publishDiagnostics", params));
    if (analysis && analysis->ok()) due.push_back({uri, std::move(analysis)});
  }
  pending_.clear();
  // Then its run, off this thread: what it finds follows for this version.
  for (Due& d : due) {
    if (shutdown_ || finished() || !d.analysis->askForRun()) continue;
    const Document* doc = workspace_.document(d.uri);
    if (!doc) continue;
    RunOptions options = workspace_.runOptions(d.analysis->source().name());
    CellRunPlan plan = workspace_.cellRunPlan(d.uri, *d.analysis);
    // Another open program of the cell, checked as its robot, takes this
    // run as its own (one run of the cell for both) unless a stimuli file
    // beside either makes their runs differ.
    for (CellPartner& p : plan.partners) {
      const Document* other = p.uri.empty() ? nullptr : workspace_.document(p.uri);
      if (!other || hasStimuli(options) || hasStimuli(workspace_.runOptions(p.analysis->source().name())) ||
          !p.analysis->askForRun())
        continue;
      p.claimed = true;
      p.version = other->version();
      const auto it = published.find(p.uri);
      p.compileDiagnostics = it != published.end() ? it->second : diagnosticsOf(*other);
    }
    Json diagnostics = published[d.uri];
    runs_.submit({d.uri, doc->version(), d.analysis, std::move(diagnostics), encoding_, std::move(options),
                  std::move(plan)});
  }
}

void Server::runMade(const RunJob& job, const CheckedRun& run) {
  const std::lock_guard<std::mutex> lock(sendMutex_);
  // Checked under the lock every message goes out under: once an edit
  // has abandoned this version, nothing of it is published.
  if (job.analysis->runControl().abandoned() || run.end == CheckedRun::End::Abandoned) return;
  if (!run.diagnostics.empty()) {
    Json all = withRunDiagnostics(job.compileDiagnostics, runDiagnostics(*job.analysis, job.uri, job.enc, run));
    sendLocked(notification("textDocument/publishDiagnostics",
                            {{"uri", job.uri}, {"version", job.version}, {"diagnostics", std::move(all)}}));
  }
  bool refresh = job.analysis->answeredWithoutRun();
  // The other programs of a cell run that took it as theirs: each in its document.
  for (const CellPartner& p : job.plan.partners) {
    if (!p.claimed || p.analysis->runControl().abandoned()) continue;
    const CheckedRun* theirs = p.analysis->run();
    if (!theirs || theirs->end == CheckedRun::End::Abandoned) continue;
    refresh = refresh || p.analysis->answeredWithoutRun();
    if (theirs->diagnostics.empty()) continue;
    Json all = withRunDiagnostics(p.compileDiagnostics, runDiagnostics(*p.analysis, p.uri, job.enc, *theirs));
    sendLocked(notification("textDocument/publishDiagnostics",
                            {{"uri", p.uri}, {"version", p.version}, {"diagnostics", std::move(all)}}));
  }
  if (refreshInlayHints_ && refresh)
    sendLocked({{"jsonrpc", "2.0"},
                {"id", fmt::format("robotsim-inlay-refresh-{}", ++refreshes_)},
                {"method", "workspace/inlayHint/refresh"}});
  if (refreshCodeLenses_ && refresh)
    sendLocked({{"jsonrpc", "2.0"},
                {"id", fmt::format("robotsim-lens-refresh-{}", ++refreshes_)},
                {"method", "workspace/codeLens/refresh"}});
}

Reply Server::workspaceSymbols(const Field& params) {
  const std::string query = params["query"].string("");
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
  d.onRequest("shutdown", [this](const Field&) -> Reply {
    shutdown_ = true;
    workspace_.abandonRuns();
    return Json(nullptr);
  });
  d.onNotification("initialized", [](const Field&) {});
  d.onNotification("textDocument/didOpen", [this](const Field& p) { didOpen(p, currentInvalidUtf8_); });
  d.onNotification("textDocument/didChange", [this](const Field& p) { didChange(p, currentInvalidUtf8_); });
  d.onNotification("textDocument/didClose", [this](const Field& p) {
    const std::string uri = documentUri(p);
    const Document* doc = workspace_.document(uri);
    // A closed stimuli file is read from disk again (its saved text).
    if (doc && doc->language() == Language::Stimuli) workspace_.stimuliChanged(), allProgramsChanged();
    workspace_.close(uri);
    pending_.insert(uri);  // publishes an empty list: the markers go
  });
  d.onNotification("textDocument/didSave", [this](const Field& p) {
    const Language language = languageOf("", documentUri(p));
    if (language == Language::Description || language == Language::Urdf)
      workspace_.descriptionsChanged(), allProgramsChanged();
    if (language == Language::Stimuli) workspace_.stimuliChanged(), allProgramsChanged();
  });
  d.onNotification("workspace/didChangeConfiguration", [this](const Field& p) {
    workspace_.setSettings(settingsFrom(p["settings"]));
    allProgramsChanged();
  });
  d.onNotification("workspace/didChangeWatchedFiles", [this](const Field&) {
    workspace_.descriptionsChanged();
    allProgramsChanged();
  });

  // Each request on a document: its analysis, by language.
  const auto on = [this](const std::string& method, std::function<Reply(const ProgramContext&, const Field&)> program,
                         std::function<Reply(const Document&, const Field&)> other = nullptr) {
    dispatcher_.onRequest(method, [this, program, other](const Field& params) -> Reply {
      Document* doc = workspace_.document(documentUri(params));
      if (!doc) return Json(nullptr);
      if (doc->language() != Language::Program) return other ? other(*doc, params) : Reply(Json(nullptr));
      const auto analysis = workspace_.program(*doc);
      return program({*doc, *analysis, encoding_}, params);
    });
  };
  const auto position = [](const Field& params) { return positionFrom(params["position"]); };
  on("textDocument/hover", [position](const ProgramContext& p, const Field& q) -> Reply { return hover(p, position(q)); },
     [this, position](const Document& doc, const Field& q) -> Reply {
       if (doc.language() == Language::Description)
         return descriptionHover(doc, encoding_, position(q), workspace_.cells().searchPath());
       if (doc.language() == Language::Stimuli) return stimuliHover(doc, encoding_, position(q));
       return Json(nullptr);
     });
  on("textDocument/definition",
     [this, position](const ProgramContext& p, const Field& q) -> Reply {
       return definition(p, position(q), workspace_.cells().searchPath());
     },
     [this, position](const Document& doc, const Field& q) -> Reply {
       if (doc.language() != Language::Description) return Json(nullptr);
       return descriptionDefinition(doc, encoding_, position(q), workspace_.cells().searchPath());
     });
  on("textDocument/references", [position](const ProgramContext& p, const Field& q) -> Reply {
    return references(p, position(q), q["context"]["includeDeclaration"].boolean(true));
  });
  on("textDocument/documentHighlight",
     [position](const ProgramContext& p, const Field& q) -> Reply { return documentHighlight(p, position(q)); });
  on("textDocument/prepareRename",
     [position](const ProgramContext& p, const Field& q) -> Reply { return prepareRename(p, position(q)); });
  on("textDocument/rename", [position](const ProgramContext& p, const Field& q) -> Reply {
    const Position at = position(q);
    return rename(p, at, q["newName"].string());
  });
  on("textDocument/documentSymbol", [](const ProgramContext& p, const Field&) -> Reply { return documentSymbols(p); },
     [this](const Document& doc, const Field&) -> Reply {
       if (doc.language() == Language::Description) return descriptionSymbols(doc, encoding_);
       if (doc.language() == Language::Stimuli) return stimuliSymbols(doc, encoding_);
       return Json::array();
     });
  on("textDocument/foldingRange", [](const ProgramContext& p, const Field&) -> Reply { return foldingRanges(p); });
  on("textDocument/formatting",
     [](const ProgramContext& p, const Field&) -> Reply { return formatting(p); });
  on("textDocument/completion", [this, position](const ProgramContext& p, const Field& q) -> Reply {
    return completion(p, position(q), snippets_);
  });
  on("textDocument/signatureHelp",
     [position](const ProgramContext& p, const Field& q) -> Reply { return signatureHelp(p, position(q)); });
  on("textDocument/codeAction", [](const ProgramContext& p, const Field& q) -> Reply {
    const Range range = rangeFrom(q["range"]);
    return codeActions(p, range, q["context"]["diagnostics"]);
  });
  on("textDocument/inlayHint",
     [](const ProgramContext& p, const Field& q) -> Reply { return inlayHints(p, rangeFrom(q["range"])); });
  on("textDocument/codeLens", [](const ProgramContext& p, const Field&) -> Reply { return codeLenses(p); });
  on("textDocument/prepareCallHierarchy",
     [position](const ProgramContext& p, const Field& q) -> Reply { return prepareCallHierarchy(p, position(q)); });
  // An item names its document itself (item.uri) and its routine in data.
  for (const bool incoming : {true, false})
    d.onRequest(incoming ? "callHierarchy/incomingCalls" : "callHierarchy/outgoingCalls",
                [this, incoming](const Field& params) -> Reply {
                  const Field item = params["item"];
                  Document* doc = workspace_.document(item["uri"].string());
                  if (!doc || doc->language() != Language::Program) return Json::array();
                  const std::string label = item["data"]["label"].string("");
                  const auto analysis = workspace_.program(*doc);
                  const ProgramContext p{*doc, *analysis, encoding_};
                  return incoming ? incomingCalls(p, label) : outgoingCalls(p, label);
                });
  on("textDocument/semanticTokens/full",
     [](const ProgramContext& p, const Field&) -> Reply { return semanticTokens(p); });
  d.onRequest("workspace/symbol", [this](const Field& params) { return workspaceSymbols(params); });
}

int serve(Input& in, Output& out, std::ostream& log, std::string version) {
  Server server(
      [&out](const Json& message) {
        const std::string body = dumpJson(message);  // header and body apart: a large answer is not copied again
        return out.write(frameHeader(body.size())) && out.write(body);
      },
      log, std::move(version));
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
