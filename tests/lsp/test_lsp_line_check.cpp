// The straight lines' path check in the editor: off the request path. The
// analysis every request answers from (hover, completion, ...) is the
// compile without it, so it plans no line; the check is made with the run
// on the run worker's thread, from the cell's cache of plans, and its
// error is what `robotsim check` says, published after the compile's
// diagnostics for the same version. An edit re-plans only the lines it
// changed. Counted in plans, not timed.
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/checked_run.h"
#include "tools/lsp/program_analysis.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

// On the XR-4: lines between a point over a block and the grasp below it,
// then one across the base's axis that the arm cannot follow
// (tests/runtime/test_straight_line.cpp).
std::string xr4Lines(int lines, bool across) {
  std::string text = "; cell: xr4-cell\n        MOVEP ABOVE\n";
  for (int i = 0; i < lines; ++i) text += i % 2 ? "        MOVES ABOVE\n" : "        MOVES GRASP\n";
  if (across) text += "        MOVEP A\n        MOVES B\n";
  return text + "        END\nPOINTS\nABOVE AT 240 870 -40 APPROACH 0 -1 0\nGRASP AT 240 810 -40 APPROACH 0 -1 0\n"
                "A AT 120 950 -120 APPROACH 0 -1 0\nB AT -120 950 120 APPROACH 0 -1 0\n";
}

std::vector<Json> linePublications(const LspSession& s, const std::string& uri) {
  std::vector<Json> out;
  for (const Json& m : s.sent())
    if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri) out.push_back(m["params"]);
  return out;
}

}  // namespace

TEST_CASE("lsp: the analysis requests answer without planning a line, the run worker checks them", "[lsp][straight]") {
  rs::lsp::CellCache cells;
  const std::shared_ptr<const rs::lsp::CellContext> cell = cells.get("xr4-cell");
  REQUIRE(cell->cell);
  REQUIRE_FALSE(cell->target.checkLines);
  REQUIRE(cell->target.linePlans);
  const rs::lsp::ProgramAnalysis analysis("lines.rsp", xr4Lines(400, true), cell, std::nullopt);
  // The compile left the check out: no plan, no error, an image to run.
  CHECK(cell->target.linePlans->misses() + cell->target.linePlans->hits() == 0);
  CHECK(analysis.ok());
  CHECK(analysis.compiled().diagnostics.empty());
  // The worker's run: the check first, which finds the line across the
  // axis and does not run the program.
  const rs::lsp::CheckedRun run = rs::lsp::checkRun(analysis, rs::lsp::RunOptions{}, analysis.runControl());
  CHECK(run.end == rs::lsp::CheckedRun::End::NotRun);
  REQUIRE(run.diagnostics.size() == 1);
  CHECK(run.diagnostics[0].pos.line == 404);
  CHECK(std::string(run.diagnostics[0].code).starts_with("line-"));
  CHECK(run.steps == 0);
  CHECK(cell->target.linePlans->misses() == 3);  // above to grasp, back, and across
}

TEST_CASE("lsp: a straight line the arm cannot follow shows as check says it, after the compile's diagnostics",
          "[lsp][straight]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("across.rsp", xr4Lines(4, true));
  const rs::testing::CliResult check = rs::testing::runCli({"check", path, "--format=json"});
  REQUIRE(check.code == 2);
  const Json want = Json::parse(check.out)["diagnostics"];
  REQUIRE(want.size() == 1);
  LspSession s;
  s.initialize();
  const std::string uri = rs::lsp::uriOfPath(path);
  s.open(uri, rs::testing::readBytes(path));
  s.idle();
  const std::vector<Json> sent = linePublications(s, uri);
  REQUIRE(sent.size() == 2);
  CHECK(sent[0]["diagnostics"].empty());  // the compile, without the check
  REQUIRE(sent[1]["diagnostics"].size() == 1);
  const Json& d = sent[1]["diagnostics"][0];
  CHECK(sent[1]["version"] == 1);
  CHECK(d["range"]["start"]["line"] == want[0]["line"].get<int>() - 1);
  CHECK(d["range"]["start"]["character"] == want[0]["column"].get<int>() - 1);
  CHECK(d["severity"] == 1);
  CHECK(d["message"] == want[0]["message"].get<std::string>() + "\nhint: " + want[0]["hint"].get<std::string>());
  CHECK(d["code"] == want[0]["code"]);
}

TEST_CASE("lsp: after an edit only the lines it changed are planned again", "[lsp][straight]") {
  LspSession s;
  s.initialize();
  const std::string uri = "file:///lines.rsp";
  const std::string text = xr4Lines(1000, false);
  s.open(uri, text);
  s.idle();
  const auto plans = s.server().workspace().cells().get("xr4-cell")->target.linePlans;
  REQUIRE(plans);
  CHECK(plans->misses() == 2);
  // A hover answers from the analysis: no plan is made for it.
  const std::uint64_t before = plans->misses() + plans->hits();
  const Json hover = s.result("textDocument/hover", LspSession::at(uri, 3, 10));
  CHECK(hover.is_object());
  CHECK(plans->misses() + plans->hits() == before);
  // The last MOVES now goes to a third point: one new line.
  std::string edited = text;
  const std::size_t last = edited.rfind("MOVES ABOVE");
  REQUIRE(last != std::string::npos);
  edited.replace(last, std::string("MOVES ABOVE").size(), "MOVES NEAR ");
  edited += "NEAR AT 240 840 -40 APPROACH 0 -1 0\n";
  s.notify("textDocument/didChange",
           {{"textDocument", {{"uri", uri}, {"version", 2}}}, {"contentChanges", {{{"text", edited}}}}});
  s.idle();
  CHECK(plans->misses() == 3);
}
