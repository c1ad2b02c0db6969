// Every field of every message is read with its type checked (tools/lsp/params.h):
// a wrong one is InvalidParams naming the field, a notification's is
// logged and changes nothing, and the server goes on. The sweep below
// gives every field of a full initialize every other JSON type, the way
// issue 26 found 72 mistyped initializes that killed the server.
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <vector>

#include "tests/lsp/lsp_session.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

// A full initialize as an editor sends it: every field the server reads,
// and others it does not.
Json fullInitialize() {
  return Json::parse(R"({
    "processId": 1234,
    "clientInfo": {"name": "a client", "version": "1.0"},
    "locale": "en",
    "rootPath": "/tmp/robotsim-ws",
    "rootUri": "file:///tmp/robotsim-ws",
    "initializationOptions": {"robotsim": {"cell": "", "lib": ["/tmp/robotsim-lib"], "collisions": "warn"}},
    "capabilities": {
      "general": {"positionEncodings": ["utf-8", "utf-16"]},
      "textDocument": {
        "completion": {"completionItem": {"snippetSupport": true, "documentationFormat": ["markdown"]}},
        "hover": {"contentFormat": ["markdown", "plaintext"]},
        "publishDiagnostics": {"relatedInformation": true, "versionSupport": true}
      },
      "workspace": {"inlayHint": {"refreshSupport": true}, "configuration": true}
    },
    "trace": "off",
    "workspaceFolders": [{"uri": "file:///tmp/robotsim-ws", "name": "ws"}]
  })");
}

// The fields the server reads, as the error names them (from "params").
const std::set<std::string> kRead = {
    "params.capabilities",
    "params.capabilities.general",
    "params.capabilities.general.positionEncodings",
    "params.capabilities.general.positionEncodings[0]",
    "params.capabilities.general.positionEncodings[1]",
    "params.capabilities.textDocument",
    "params.capabilities.textDocument.completion",
    "params.capabilities.textDocument.completion.completionItem",
    "params.capabilities.textDocument.completion.completionItem.snippetSupport",
    "params.capabilities.workspace",
    "params.capabilities.workspace.inlayHint",
    "params.capabilities.workspace.inlayHint.refreshSupport",
    "params.rootUri",
    "params.workspaceFolders",
    "params.workspaceFolders[0]",
    "params.workspaceFolders[0].uri",
    "params.initializationOptions.robotsim",
    "params.initializationOptions.robotsim.cell",
    "params.initializationOptions.robotsim.lib",
    "params.initializationOptions.robotsim.lib[0]",
    "params.initializationOptions.robotsim.collisions",
};

struct Place {
  std::string path;           // as the server names it
  Json::json_pointer pointer;  // where it is in the params
  Json::value_t type;
};

void places(const Json& value, const std::string& path, const Json::json_pointer& pointer, std::vector<Place>& out) {
  out.push_back({path, pointer, value.type()});
  if (value.is_object())
    for (const auto& [key, member] : value.items()) places(member, path + "." + key, pointer / key, out);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i)
      places(value[i], path + "[" + std::to_string(i) + "]", pointer / i, out);
}

bool sameKind(Json::value_t a, Json::value_t b) {
  const auto number = [](Json::value_t t) {
    return t == Json::value_t::number_integer || t == Json::value_t::number_unsigned || t == Json::value_t::number_float;
  };
  return a == b || (number(a) && number(b));
}

int errorCodeOf(const Json& response) { return response.at("error").at("code").get<int>(); }

// After a refused initialize the server is still waiting for one: a good
// one is answered, and the server then serves a document.
void goesOn(LspSession& s) {
  CHECK(errorCodeOf(s.request("textDocument/hover", LspSession::at("file:///a.rsp", 0, 9))) == -32002);
  REQUIRE(s.initialize().contains("result"));
  s.open("file:///a.rsp", "        MOVE 1 0 0 0 0\n        END\n");
  s.idle();
  CHECK(s.result("textDocument/hover", LspSession::at("file:///a.rsp", 0, 9)).contains("contents"));
}

}  // namespace

TEST_CASE("lsp: every field of initialize, of every other type: InvalidParams or a result, never the end",
          "[lsp][params]") {
  const Json full = fullInitialize();
  std::vector<Place> all;
  places(full, "params", Json::json_pointer(), all);
  const std::vector<Json> values = {nullptr, true, 7, -1, 2.5, "x", Json::array(), Json::object()};
  int refused = 0, answered = 0;
  for (const Place& place : all) {
    if (place.path == "params") continue;  // the root: below
    for (const Json& value : values) {
      if (sameKind(value.type(), place.type)) continue;
      Json params = full;
      params[place.pointer] = value;
      CAPTURE(place.path, value.dump());
      LspSession s;
      const Json r = s.request("initialize", params);
      REQUIRE((r.contains("result") != r.contains("error")));
      // A field the server reads, of a wrong type, is refused and named;
      // null is an absent field (its default), and a field it does not
      // read cannot be wrong.
      if (kRead.count(place.path) && !value.is_null()) {
        REQUIRE(r.contains("error"));
        CHECK(errorCodeOf(r) == -32602);
        CHECK_THAT(r["error"]["message"].get<std::string>(),
                   Catch::StartsWith("invalid params for initialize: " + place.path + ": expected "));
        ++refused;
        goesOn(s);
      } else if (r.contains("error")) {
        // Null where the protocol needs a value (an element of a list the
        // server reads, a folder's uri) is refused the same way.
        CHECK(value.is_null());
        CHECK(errorCodeOf(r) == -32602);
        CHECK_THAT(r["error"]["message"].get<std::string>(), Catch::Contains(place.path + ": expected "));
        ++refused;
        goesOn(s);
      } else {
        ++answered;
        CHECK(r["result"]["capabilities"].is_object());
      }
    }
  }
  CHECK(refused >= static_cast<int>(kRead.size()) * 5);
  CHECK(answered > 50);
}

TEST_CASE("lsp: the mistyped initializes of issue 26 are InvalidParams, and the server goes on", "[lsp][params]") {
  const std::vector<std::pair<Json, std::string>> cases = {
      {{{"capabilities", "all of them"}}, "params.capabilities: expected an object, found a string"},
      {{{"capabilities", {{"textDocument", {{"completion", {{"completionItem", {{"snippetSupport", "yes"}}}}}}}}}},
       "params.capabilities.textDocument.completion.completionItem.snippetSupport: expected a boolean, found a string"},
      {{{"capabilities", Json::object()}, {"workspaceFolders", {5}}},
       "params.workspaceFolders[0]: expected an object, found an integer"},
      {{{"capabilities", {{"general", {{"positionEncodings", "utf-8"}}}}}},
       "params.capabilities.general.positionEncodings: expected an array, found a string"},
      {Json::array({1, 2}), "params: expected an object, found an array"},
      {{{"initializationOptions", {{"collisions", "sometimes"}}}},
       R"(params.initializationOptions.collisions: expected "error", "warn" or "off", found "sometimes")"},
  };
  for (const auto& [params, message] : cases) {
    CAPTURE(params.dump());
    LspSession s;
    const Json r = s.request("initialize", params);
    REQUIRE(r.contains("error"));
    CHECK(errorCodeOf(r) == -32602);
    CHECK(r["error"]["message"] == "invalid params for initialize: " + message);
    goesOn(s);
  }
}

TEST_CASE("lsp: requests with a mistyped field are InvalidParams naming it", "[lsp][params]") {
  LspSession s;
  s.initialize();
  s.open("file:///a.rsp", "loop:   MOVE 1 0 0 0 0\n        GOTO loop\n");
  s.idle();
  const auto refused = [&](const std::string& method, const Json& params) {
    const Json r = s.request(method, params);
    REQUIRE(r.contains("error"));
    CHECK(errorCodeOf(r) == -32602);
    return r["error"]["message"].get<std::string>();
  };
  Json at = LspSession::at("file:///a.rsp", 0, 9);
  at["position"]["line"] = -1;
  CHECK(refused("textDocument/hover", at) ==
        "invalid params for textDocument/hover: params.position.line: expected an unsigned integer (0 to "
        "2147483647), found an integer");
  at["position"]["line"] = 1.0;
  CHECK_THAT(refused("textDocument/hover", at), Catch::EndsWith("found a number with a fraction"));
  at["position"]["line"] = 0;
  at["textDocument"]["uri"] = 3;
  CHECK_THAT(refused("textDocument/definition", at), Catch::EndsWith("params.textDocument.uri: expected a string, found an integer"));
  Json rename = LspSession::at("file:///a.rsp", 1, 14);
  rename["newName"] = Json::array();
  CHECK_THAT(refused("textDocument/rename", rename), Catch::EndsWith("params.newName: expected a string, found an array"));
  Json refs = LspSession::at("file:///a.rsp", 1, 14);
  refs["context"] = {{"includeDeclaration", "no"}};
  CHECK_THAT(refused("textDocument/references", refs),
             Catch::EndsWith("params.context.includeDeclaration: expected a boolean, found a string"));
  const Json action = {{"textDocument", {{"uri", "file:///a.rsp"}}},
                       {"range", LspSession::range(0, 0, 0, 1)},
                       {"context", {{"diagnostics", {{{"range", LspSession::range(0, 0, 0, 1)}, {"code", true}}}}}}};
  CHECK_THAT(refused("textDocument/codeAction", action),
             Catch::EndsWith("params.context.diagnostics[0].code: expected an integer (-2147483648 to 2147483647), found a boolean"));
  CHECK_THAT(refused("workspace/symbol", {{"query", 12}}), Catch::EndsWith("params.query: expected a string, found an integer"));
  // And the server still answers.
  CHECK(s.result("textDocument/hover", LspSession::at("file:///a.rsp", 0, 9)).contains("contents"));
}

TEST_CASE("lsp: a notification with a mistyped field is logged and changes nothing", "[lsp][params]") {
  LspSession s;
  s.initialize();
  const std::string uri = "file:///a.rsp";
  s.open(uri, "        END\n");
  s.idle();
  s.clearSent();
  // The second change is malformed: the first is not made either.
  s.notify("textDocument/didChange",
           {{"textDocument", {{"uri", uri}, {"version", 2}}},
            {"contentChanges", Json::array({Json{{"text", "        MOVX 1\n"}},
                                            Json{{"range", LspSession::range(0, 0, 0, 0)}, {"text", 5}}})}});
  s.idle();
  const std::vector<Json> sent = s.sent();
  REQUIRE(sent.size() == 1);
  CHECK(sent[0]["method"] == "window/logMessage");
  CHECK(sent[0]["params"]["type"] == 1);
  CHECK(sent[0]["params"]["message"] ==
        "robotsim lsp: invalid params for textDocument/didChange: params.contentChanges[1].text: expected a string, "
        "found an integer (the notification changed nothing)");
  CHECK_THAT(s.log(), Catch::Contains("params.contentChanges[1].text: expected a string"));
  // The document is as it was: END, no unknown instruction.
  s.notify("textDocument/didOpen", {{"textDocument", {{"uri", "file:///b.rsp"}, {"text", Json::array()}}}});
  CHECK(s.result("textDocument/documentSymbol", {{"textDocument", {{"uri", "file:///b.rsp"}}}}).is_null());
  const Json hover = s.result("textDocument/hover", LspSession::at(uri, 0, 9));
  CHECK_THAT(hover["contents"]["value"].get<std::string>(), Catch::StartsWith("**END**"));
  s.notify("workspace/didChangeConfiguration", {{"settings", {{"robotsim", {{"lib", "not a list"}}}}}});
  CHECK_THAT(s.log(), Catch::Contains("params.settings.robotsim.lib: expected an array, found a string"));
}
