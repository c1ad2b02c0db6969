// The language server's code lenses over labels and the call hierarchy of
// GOSUBs (issue 34), the go-to-definition of a cell directive on the
// workcell's line, and run-time diagnostics with their codes. Times are
// worked out from the programs' comments and the motor speeds
// (examples/nested_subroutines.rsp: serve 4.2 s, pick and drop 1.6 s, grip
// 0.6 s; examples/counted_loop.rsp: E 100 in 0.25 s, B 100 in 0.2 s, E 250
// in 0.625 s).
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

const std::string kLensExamples = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/";

// 1-based line -> the lens title over it.
std::map<int, std::string> lensTitles(LspSession& s, const std::string& uri) {
  std::map<int, std::string> out;
  for (const Json& l : s.result("textDocument/codeLens", {{"textDocument", {{"uri", uri}}}})) {
    CHECK(l["command"]["command"] == "");  // a lens that only shows
    out[l["range"]["start"]["line"].get<int>() + 1] = l["command"]["title"].get<std::string>();
  }
  return out;
}

// The lines (1-based) of a call's fromRanges, by the name of the routine at its other end.
std::map<std::string, std::vector<int>> callLines(const Json& calls, const char* end) {
  std::map<std::string, std::vector<int>> out;
  for (const Json& c : calls)
    for (const Json& r : c["fromRanges"]) out[c[end]["name"].get<std::string>()].push_back(r["start"]["line"].get<int>() + 1);
  return out;
}

struct OpenProgram {
  LspSession s;
  std::string uri, text;
  explicit OpenProgram(const std::string& path, Json capabilities = Json::object())
      : uri(rs::lsp::uriOfPath(path)), text(rs::testing::readBytes(path)) {
    s.initialize(std::move(capabilities));
    s.open(uri, text);
    s.idle();
  }
};

}  // namespace

TEST_CASE("lsp: a lens over each subroutine: its calls and the time a call takes", "[lsp][lens]") {
  LspSession fresh;
  CHECK(fresh.initialize()["result"]["capabilities"]["codeLensProvider"] == Json({{"resolveProvider", false}}));
  OpenProgram o(kLensExamples + "nested_subroutines.rsp");
  // serve is called twice (lines 13, 15); pick, drop and grip by one GOSUB
  // each, which runs twice (once a serve).
  CHECK(lensTitles(o.s, o.uri) == std::map<int, std::string>{
                                      {20, "2 calls · 4.2 s a call, 8.4 s in all"},
                                      {27, "1 call · 1.6 s a call, 3.2 s in all"},
                                      {32, "1 call · 1.6 s a call, 3.2 s in all"},
                                      {38, "1 call · 0.6 s a call, 1.2 s in all"},
                                  });
}

TEST_CASE("lsp: a lens over each label: its jumps, the passes and the time to the next label", "[lsp][lens]") {
  OpenProgram o(kLensExamples + "counted_loop.rsp");
  // down: five passes of MOVE B (0.2 s) + ADD + JMPVAR; back: three passes
  // (POS 500, 250, 0), the MOVE E (0.625 s) in the first two; done: END.
  CHECK(lensTitles(o.s, o.uri) == std::map<int, std::string>{
                                      {18, "1 jump · passed 5 times, 1 s to the next label"},
                                      {24, "1 jump · passed 3 times, 1.25 s to the next label"},
                                      {28, "1 jump · passed 1 time, 0 s to the next label"},
                                  });
}

TEST_CASE("lsp: lenses without a run, times once it is made, and the refresh", "[lsp][lens]") {
  rs::testing::TempDir dir;
  const std::string path = dir.write("calls.rsp",
                                     "        GOSUB twice\n        GOSUB twice\n        GOTO out\n        GOSUB never\n"
                                     "out:    END\ntwice:  DELAY 0.5\n        JMPIN 1 ON short\n        DELAY 1\n"
                                     "short:  RETURN\nnever:  GOSUB twice\n        RETURN\n");
  LspSession s;
  s.initialize({{"workspace", {{"codeLens", {{"refreshSupport", true}}}}}});
  const std::string uri = rs::lsp::uriOfPath(path);
  s.open(uri, rs::testing::readBytes(path));
  // Before the version is published its run has not been asked for: counts only.
  CHECK(lensTitles(s, uri) == std::map<int, std::string>{{5, "1 jump"}, {6, "3 calls"}, {9, "1 jump"}, {10, "1 call"}});
  s.idle();
  bool refreshed = false;
  for (const Json& m : s.sent()) refreshed = refreshed || m.value("method", "") == "workspace/codeLens/refresh";
  CHECK(refreshed);
  // Each call of twice: 0.5 s + 1 s (input 1 stays off); never is never
  // called (its GOSUB is jumped over), though its GOSUB counts.
  const auto titles = lensTitles(s, uri);
  CHECK(titles.at(5) == "1 jump · passed 1 time, 0 s to the next label");
  CHECK(titles.at(6) == "3 calls · 1.5 s a call, 3 s in all");
  CHECK(titles.at(9) == "1 jump · passed 2 times, 0 s to the next label");
  CHECK(titles.at(10) == "1 call · not called in the run");
}

TEST_CASE("lsp: the call hierarchy of GOSUBs", "[lsp][calls]") {
  OpenProgram o(kLensExamples + "nested_subroutines.rsp");
  LspSession fresh;
  CHECK(fresh.initialize()["result"]["capabilities"]["callHierarchyProvider"] == true);
  const auto prepare = [&](unsigned line, unsigned character) {
    return o.s.result("textDocument/prepareCallHierarchy", LspSession::at(o.uri, line, character));
  };
  // On "GOSUB pick" of line 20 (the label from column 14): pick.
  const Json pick = prepare(19, 15);
  REQUIRE(pick.size() == 1);
  CHECK(pick[0]["name"] == "pick");
  CHECK(pick[0]["kind"] == 12);
  CHECK(pick[0]["selectionRange"] == LspSession::range(26, 0, 26, 4));  // "pick:" on line 27
  CHECK(pick[0]["range"]["start"]["line"] == 26);
  CHECK(pick[0]["range"]["end"]["line"] == 29);  // its RETURN, line 30
  const auto incoming = [&](const Json& item) { return o.s.result("callHierarchy/incomingCalls", {{"item", item}}); };
  const auto outgoing = [&](const Json& item) { return o.s.result("callHierarchy/outgoingCalls", {{"item", item}}); };
  CHECK(callLines(incoming(pick[0]), "from") == std::map<std::string, std::vector<int>>{{"serve", {20}}});
  CHECK(callLines(outgoing(pick[0]), "to") == std::map<std::string, std::vector<int>>{{"grip", {28}}});
  // Inside serve, not on a label: serve, which the main program calls twice and which calls pick and drop.
  const Json serve = prepare(20, 10);
  REQUIRE(serve.size() == 1);
  CHECK(serve[0]["name"] == "serve");
  CHECK(callLines(incoming(serve[0]), "from") == std::map<std::string, std::vector<int>>{{"main program", {13, 15}}});
  CHECK(callLines(outgoing(serve[0]), "to") == std::map<std::string, std::vector<int>>{{"drop", {22}}, {"pick", {20}}});
  // In the main program: the main program, called by nobody.
  const Json main = prepare(13, 9);
  REQUIRE(main.size() == 1);
  CHECK(main[0]["name"] == "main program");
  CHECK(incoming(main[0]) == Json::array());
  CHECK(callLines(outgoing(main[0]), "to") == std::map<std::string, std::vector<int>>{{"serve", {13, 15}}});
  // grip calls nothing.
  const Json grip = prepare(37, 1);
  REQUIRE(grip.size() == 1);
  CHECK(grip[0]["name"] == "grip");
  CHECK(outgoing(grip[0]) == Json::array());
  // An item of a document the server does not have: nothing, not an error.
  Json stranger = grip[0];
  stranger["uri"] = "file:///nowhere.rsp";
  CHECK(incoming(stranger) == Json::array());
}

TEST_CASE("lsp: a cell directive goes to the workcell's line in its file", "[lsp][cell]") {
  rs::testing::TempDir dir;
  const std::string path = dir.write("prog.rsp", "; cell: scara-pick\n        END\n");
  OpenProgram o(path);
  const Json d = o.s.result("textDocument/definition", LspSession::at(o.uri, 0, 10));
  REQUIRE(d.is_object());
  const std::string file = std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/workcells/scara-pick.rsd";
  CHECK(d["uri"] == rs::lsp::uriOfPath(file));
  // "WORKCELL scara-pick": found in the file independently, its name from column 9.
  const std::string text = rs::testing::readBytes(file);
  const auto at = text.find("\nWORKCELL scara-pick");
  REQUIRE(at != std::string::npos);
  const auto line = static_cast<unsigned>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at) + 1, '\n'));
  CHECK(line > 0);
  CHECK(d["range"] == LspSession::range(line, 9, line, 19));
}

TEST_CASE("lsp: run-time diagnostics carry codes", "[lsp][runs]") {
  rs::testing::TempDir dir;
  const auto codeOf = [&](const std::string& name, const std::string& text) {
    LspSession s;
    s.initialize();
    const std::string uri = rs::lsp::uriOfPath(dir.write(name, text));
    s.open(uri, text);
    s.idle();
    const Json d = s.diagnostics(uri);
    REQUIRE(!d.empty());
    return d.back().value("code", "");  // the run's come after the compile's
  };
  CHECK(codeOf("deadlock.rsp", "        WAITFOR 1 ON\n        END\n") == "deadlock");
  CHECK(codeOf("range.rsp", "again:  MOVE 300 0 0 0 0\n        GOTO again\n") == "runtime-error");
  CHECK(codeOf("still.rsp", "again:  GOTO again\n") == "clock-standing-still");
  CHECK(codeOf("slow.rsp", "again:  DELAY 1000\n        GOTO again\n") == "time-limit");
}
