// libFuzzer target: the start of a language-server session, where issue 26
// found wrongly typed fields (capabilities, snippetSupport,
// workspaceFolders[0]) killing the server. The input is the params of
// `initialize`, as JSON text. Besides libFuzzer's byte mutations, a custom
// mutator changes it as JSON: any value replaced by one of another type, a
// member dropped, a member the server reads added, so that every field
// meets every type. A short session follows the initialize: a document
// opened (its run made on the run worker), a hover, shutdown, exit.
//
// The server must answer the initialize exactly once, with a result or
// with InvalidParams (ParseError when the params are not JSON), never
// crash, and go on: after a refused initialize a good one is answered, and
// the session is served to its end.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "base/text.h"
#include "tools/lsp/server.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

using rs::lsp::Json;

// Members an initialize has, or that the server reads in one.
const char* const kKeys[] = {"capabilities", "general",  "positionEncodings", "textDocument", "completion",
                             "completionItem", "snippetSupport", "workspace", "inlayHint", "refreshSupport",
                             "workspaceFolders", "uri", "name", "rootUri", "rootPath", "initializationOptions",
                             "robotsim", "cell", "lib", "collisions", "processId", "trace"};

Json anyValue(std::minstd_rand& rng, const std::vector<Json*>& nodes) {
  switch (rng() % 12) {
    case 0: return nullptr;
    case 1: return rng() % 2 == 0;
    case 2: return static_cast<int>(rng() % 5) - 1;
    case 3: return 2.5;
    case 4: return "utf-8";
    case 5: return "file:///tmp/robotsim-fuzz";
    case 6: return rng() % 2 ? "off" : "scara-pick";
    case 7: return "";
    case 8: return Json::array();
    case 9: return Json::object();
    case 10: return Json::array({"utf-16", nullptr});
    default: return *nodes[rng() % nodes.size()];  // a copy of another value
  }
}

void collect(Json& j, std::vector<Json*>& nodes) {
  nodes.push_back(&j);
  if (j.is_object() || j.is_array())
    for (Json& child : j) collect(child, nodes);
}

struct Session {
  std::mutex mutex;
  std::vector<Json> sent;
  std::ostringstream log;
  rs::lsp::Server server{[this](const Json& m) {
                           const std::lock_guard<std::mutex> lock(mutex);
                           sent.push_back(m);
                           return true;
                         },
                         log};

  void send(const std::string& body) {
    server.receive({rs::lsp::Frame{rs::lsp::Frame::Kind::Message, body, {}}});
    server.publishPending();
  }
  // The answers to request `id` so far.
  std::vector<Json> answersTo(const Json& id) {
    const std::lock_guard<std::mutex> lock(mutex);
    std::vector<Json> out;
    for (const Json& m : sent)
      if (m.contains("id") && !m.contains("method") && m["id"] == id) out.push_back(m);
    return out;
  }
};

std::string request(int id, const std::string& method, const std::string& params) {
  return "{\"jsonrpc\":\"2.0\",\"id\":" + std::to_string(id) + ",\"method\":\"" + method + "\",\"params\":" + params + "}";
}

void require(bool ok) {
  if (!ok) std::abort();
}

// The text as the server reads it (lsp.md, Bad input): each byte that is
// not UTF-8 becomes U+FFFD. The first campaign's first finding was this
// target's own: params with a stray 0xFA in a key are JSON to the server,
// so it answered the initialize instead of a ParseError.
std::string asTheServerReadsIt(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = rs::base::utf8SequenceLength(text, i);
    out += n == 0 ? std::string_view("\xEF\xBF\xBD") : text.substr(i, n);
    i += n == 0 ? 1 : n;
  }
  return out;
}

// JSON as RFC 8259 has it: the JSON library alone takes a NUL byte for the
// end of the text (the campaign's second finding: params "2.5" and NULs),
// and skips a byte-order mark at the start of a text, which inside a
// message (after "params":) is no JSON (the third: a BOM and "1").
bool isJsonText(std::string_view text) {
  return text.find('\0') == std::string_view::npos && !text.starts_with("\xEF\xBB\xBF") &&
         Json::accept(asTheServerReadsIt(text));
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t maxSize,
                                                unsigned int seed) {
  std::minstd_rand rng(seed);
  Json j = Json::parse(data, data + size, nullptr, false);
  if (j.is_discarded() || rng() % 4 == 0) return LLVMFuzzerMutate(data, size, maxSize);
  std::vector<Json*> nodes;
  collect(j, nodes);
  Json& node = *nodes[rng() % nodes.size()];
  switch (rng() % 3) {
    case 0: node = anyValue(rng, nodes); break;
    case 1:  // drop a member
      if (node.is_object() && !node.empty()) {
        auto it = node.begin();
        std::advance(it, static_cast<long>(rng() % node.size()));
        node.erase(it);
      }
      break;
    default:  // add a member the server may read
      if (node.is_object()) node[kKeys[rng() % std::size(kKeys)]] = anyValue(rng, nodes);
      else node = Json::object({{kKeys[rng() % std::size(kKeys)], anyValue(rng, nodes)}});
      break;
  }
  const std::string out = j.dump();
  if (out.size() > maxSize) return LLVMFuzzerMutate(data, size, maxSize);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string params(reinterpret_cast<const char*>(data), size);
  const std::string message = request(1, "initialize", params);
  const bool isJson = isJsonText(params);
  Session s;
  s.server.setRunBudget(std::chrono::milliseconds(50));
  s.send(message);
  // Params that are not one JSON value but close the message early and go
  // on (`{}, "id": 7, "x": {`) make another message: its answer is not
  // the one this target predicts; the sanitizers still watch it.
  if (!isJson && isJsonText(message)) return 0;
  bool initialized = false;
  if (isJson) {
    const std::vector<Json> answers = s.answersTo(1);
    require(answers.size() == 1);
    const Json& a = answers[0];
    require(a.contains("result") != a.contains("error"));
    if (a.contains("error")) require(a["error"]["code"] == -32602);
    initialized = a.contains("result");
  } else {
    require(s.answersTo(nullptr).size() == 1 && s.answersTo(nullptr)[0]["error"]["code"] == -32700);
  }
  if (!initialized) {
    s.send(request(2, "initialize", R"({"capabilities":{}})"));
    require(s.answersTo(2).size() == 1 && s.answersTo(2)[0].contains("result"));
  }
  s.send(R"({"jsonrpc":"2.0","method":"initialized","params":{}})");
  s.send(R"({"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///tmp/robotsim-fuzz/a.rsp","languageId":"robotsim-program","version":1,"text":"        MOVE 10 0 0 0 0\n        WAITFOR 1 ON\n        END\n"}}})");
  s.send(request(3, "textDocument/hover", R"({"textDocument":{"uri":"file:///tmp/robotsim-fuzz/a.rsp"},"position":{"line":0,"character":9}})"));
  const std::vector<Json> hover = s.answersTo(3);
  require(hover.size() == 1 && hover[0].contains("result"));
  s.server.settle();
  s.send(request(4, "shutdown", "null"));
  s.send(R"({"jsonrpc":"2.0","method":"exit"})");
  require(s.server.finished() && s.server.exitCode() == 0);
  return 0;
}
