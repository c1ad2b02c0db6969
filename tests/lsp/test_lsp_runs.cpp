// The editor sees what `robotsim check` sees (issue 23): each example with a
// mistake, and programs that end every other way, are opened in the server
// and every diagnostic it publishes is checked against `robotsim check
// --format=json` for the same file; the run is made off the request
// thread, published after the compile's diagnostics for the same version,
// abandoned by a newer edit and bounded; hovers and inlay hints agree with
// it.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/checked_run.h"
#include "tools/lsp/program_analysis.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

const std::string kMistakes = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/mistakes/";

// check's JSON report; `collisions` as --collisions (check's exit is 1
// when the run stopped, 0 when it only warned).
Json checkJson(const std::string& path, const std::string& collisions = "error", int exitCode = 1) {
  const rs::testing::CliResult r = rs::testing::runCli({"check", path, "--format=json", "--collisions=" + collisions});
  INFO(r.err);
  REQUIRE(r.code == exitCode);
  return Json::parse(r.out);
}

// LSP's severities: 1 error, 2 warning, 3 information.
int lspSeverity(const std::string& name) { return name == "error" ? 1 : name == "warning" ? 2 : 3; }

// Every diagnostic check reports is published at its line and column, with
// its severity, message, hint and code, and the server publishes nothing
// else (the programs here have no compile diagnostics).
void sameAsCheck(const std::string& path, const std::string& collisions = "error", int exitCode = 1) {
  CAPTURE(path, collisions);
  const Json check = checkJson(path, collisions, exitCode)["diagnostics"];
  REQUIRE(!check.empty());
  LspSession s;
  s.initialize(Json::object(), {{"robotsim", {{"collisions", collisions}}}});
  const std::string uri = rs::lsp::uriOfPath(path);
  s.open(uri, rs::testing::readBytes(path));
  s.idle();
  const Json lsp = s.diagnostics(uri);
  CAPTURE(check.dump(), lsp.dump());
  REQUIRE(lsp.size() == check.size());
  for (std::size_t i = 0; i < check.size(); ++i) {
    const Json& c = check[i];
    const Json& l = lsp[i];
    CHECK(l["range"]["start"]["line"] == c["line"].get<int>() - 1);
    CHECK(l["range"]["start"]["character"] == c["column"].get<int>() - 1);  // ASCII lines: characters are columns
    CHECK(l["severity"] == lspSeverity(c["severity"]));
    const std::string message = c["message"].get<std::string>() +
                                (c.contains("hint") ? "\nhint: " + c["hint"].get<std::string>() : std::string());
    CHECK(l["message"] == message);
    CHECK(l.value("code", "") == c.value("code", ""));
  }
}

std::vector<Json> publications(const LspSession& s, const std::string& uri) {
  std::vector<Json> out;
  for (const Json& m : s.sent())
    if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri) out.push_back(m["params"]);
  return out;
}

// A loop that would run until check's step limit, 100,000,000 instructions
// (the clock moves a millisecond every 203 instructions, so neither the
// time limit nor the clock-standing-still one comes first): far longer
// than any test waits, even on a fast machine (0.17 s at the VM's bare
// 1.7 ns an instruction).
const std::string kEndless =
    "loop:   DELAY 0.001\n"
    "        SET I 0\n"
    "spin:   ADD I 1\n"
    "        JMPVAR I < 100 spin\n"
    "        GOTO loop\n";

}  // namespace

TEST_CASE("lsp: each example with a mistake shows in the editor what robotsim check says", "[lsp][runs]") {
  for (const char* name : {"out_of_range.rsp", "collision.rsp", "deadlock.rsp"}) sameAsCheck(kMistakes + name);
  // And what each says, worked out from the programs (examples/mistakes/):
  const auto message = [](const std::string& name) { return checkJson(kMistakes + name)["diagnostics"][0]["message"]; };
  CHECK(message("out_of_range.rsp") == "runtime error: MOVE takes motor E to 1200, outside its range -1000..1000 (instruction 2)");
  // The first contact comes within the swept check's bound (docs/models.md,
  // "Collisions": the part travels at most 1 unit past it) of 1.297 s.
  CHECK_THAT(message("collision.rsp").get<std::string>(),
             Catch::Matches("runtime error: collision at 1\\.(29[0-9]|30[0-4]) s: finger .*"));
  CHECK_THAT(message("deadlock.rsp").get<std::string>(), Catch::StartsWith("deadlock: input 2 never turns ON"));
}

TEST_CASE("lsp: with robotsim.collisions warn, each collision is a warning as check --collisions=warn says it",
          "[lsp][runs]") {
  // The run goes on through the blocks and ends: no error, a warning for
  // each collision at its MOVE (check exits 0: warnings alone do not fail).
  sameAsCheck(kMistakes + "collision.rsp", "warn", 0);
  const Json check = checkJson(kMistakes + "collision.rsp", "warn", 0)["diagnostics"];
  REQUIRE(!check.empty());
  for (const Json& d : check) {
    CHECK(d["severity"] == "warning");
    CHECK(d["code"] == "collision");
  }
  // The first is where the program's comment says: the swing of line 11,
  // 1.297 s in (within the swept check's bound), as with
  // --collisions=error (where it stops the run).
  CHECK(check[0]["line"] == 11);
  CHECK_THAT(check[0]["message"].get<std::string>(), Catch::Matches("collision at 1\\.(29[0-9]|30[0-4]) s: finger .*"));
}

TEST_CASE("lsp: the empty gripper and the limits show as check says them", "[lsp][runs]") {
  rs::testing::TempDir dir;
  // The gripper closes at home on scara-pick, where no block is: a warning
  // (the run itself is fine, so check's exit is 1 only through --strict;
  // here the time limit of a second program makes the point of exit 1).
  const std::string gripper = dir.write("gripper.rsp", "; cell: scara-pick\n        MOVE 0 0 0 0 120\n        END\n");
  const rs::testing::CliResult r = rs::testing::runCli({"check", gripper, "--format=json"});
  REQUIRE(r.code == 0);
  const Json warning = Json::parse(r.out)["diagnostics"];
  REQUIRE(warning.size() == 1);
  CHECK(warning[0]["code"] == "gripper-took-nothing");
  LspSession s;
  s.initialize();
  s.open(rs::lsp::uriOfPath(gripper), rs::testing::readBytes(gripper));
  s.idle();
  const Json lsp = s.diagnostics(rs::lsp::uriOfPath(gripper));
  REQUIRE(lsp.size() == 1);
  CHECK(lsp[0]["code"] == "gripper-took-nothing");
  CHECK(lsp[0]["severity"] == 2);
  CHECK(lsp[0]["range"]["start"]["line"] == 1);
  CHECK(lsp[0]["message"] == warning[0]["message"].get<std::string>() + "\nhint: " + warning[0]["hint"].get<std::string>());
  // An hour of DELAYs: the time limit; a loop that never moves the clock:
  // 10,000,000 instructions, and the clock standing still.
  sameAsCheck(dir.write("time.rsp", "again:  DELAY 1000\n        GOTO again\n"));
  sameAsCheck(dir.write("still.rsp", "again:  ADD N 1\n        GOTO again\n"));
}

TEST_CASE("lsp: compile diagnostics first, the run's follow for the same version", "[lsp][runs]") {
  LspSession s;
  s.initialize();
  const std::string uri = rs::lsp::uriOfPath(kMistakes + "deadlock.rsp");
  s.open(uri, rs::testing::readBytes(kMistakes + "deadlock.rsp"));
  s.idle();
  const std::vector<Json> sent = publications(s, uri);
  REQUIRE(sent.size() == 2);
  CHECK(sent[0]["version"] == 1);
  // The compile found nothing but the server's warning on the WAITFOR
  // nothing can end, which gives way to the run's deadlock at its line.
  REQUIRE(sent[0]["diagnostics"].size() == 1);
  CHECK(sent[0]["diagnostics"][0]["code"] == "input-never-on");
  CHECK(sent[1]["version"] == 1);
  REQUIRE(sent[1]["diagnostics"].size() == 1);
  CHECK_THAT(sent[1]["diagnostics"][0]["message"].get<std::string>(), Catch::StartsWith("deadlock:"));
  // A program whose run finds nothing is published once.
  s.clearSent();
  s.open("file:///fine.rsp", "        MOVE 10 0 0 0 0\n        END\n");
  s.idle();
  CHECK(publications(s, "file:///fine.rsp").size() == 1);
}

TEST_CASE("lsp: a newer edit abandons the run, and nothing of the old version is published", "[lsp][runs]") {
  LspSession s;
  s.initialize();
  const std::string uri = "file:///endless.rsp";
  s.open(uri, kEndless);
  s.publishOnly();  // the run starts on the worker
  const auto edited = std::chrono::steady_clock::now();
  // Version 2 ends at once with a deadlock.
  s.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 2}}},
                                      {"contentChanges", {{{"text", "        WAITFOR 1 ON\n        END\n"}}}}});
  s.idle();
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - edited).count();
  const std::vector<Json> sent = publications(s, uri);
  REQUIRE(sent.size() == 3);  // version 1's compile, version 2's compile, version 2's run
  CHECK(sent[0]["version"] == 1);
  CHECK(sent[0]["diagnostics"].empty());
  CHECK(sent[1]["version"] == 2);
  REQUIRE(sent[1]["diagnostics"].size() == 1);  // the WAITFOR's warning, until the run's deadlock replaces it
  CHECK(sent[1]["diagnostics"][0]["code"] == "input-never-on");
  CHECK(sent[2]["version"] == 2);
  REQUIRE(sent[2]["diagnostics"].size() == 1);
  CHECK_THAT(sent[2]["diagnostics"][0]["message"].get<std::string>(), Catch::StartsWith("deadlock:"));
  // The abandoned run paused at its next step: far sooner than the
  // budget, which a run left to go on would have used up.
  CHECK(waited < 0.8 * std::chrono::duration<double>(rs::lsp::kRunBudget).count());
}

TEST_CASE("lsp: abandoning a run pauses it at its next step", "[lsp][runs]") {
  const auto cell = std::make_shared<rs::lsp::CellContext>();
  cell->target = rs::lsp::CellCache().get("")->target;
  const rs::lsp::ProgramAnalysis analysis("endless.rsp", kEndless, cell, std::nullopt);
  REQUIRE(analysis.ok());
  rs::lsp::CheckedRun run;
  std::thread worker([&] { run = rs::lsp::checkRun(analysis, rs::lsp::RunOptions{}, analysis.runControl()); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  analysis.runControl().abandon();
  worker.join();
  CHECK(run.end == rs::lsp::CheckedRun::End::Abandoned);
  CHECK(run.diagnostics.empty());
  CHECK(run.steps < 100'000'000);  // check's limit: the run did not go on to it
}

TEST_CASE("lsp: a run past the editor's budget ends with a note, not a guess", "[lsp][runs]") {
  LspSession s;
  s.initialize();
  s.server().setRunBudget(std::chrono::milliseconds(50));
  s.open("file:///endless.rsp", kEndless);
  s.idle();
  const Json d = s.diagnostics("file:///endless.rsp");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["severity"] == 3);
  CHECK(d[0]["code"] == "run-not-finished");
  CHECK_THAT(d[0]["message"].get<std::string>(),
             Catch::StartsWith("the editor's run stopped here after 0.05 s of checking (") &&
                 Catch::Contains("before the program ended: what comes after is not checked in the editor"));
  CHECK_THAT(d[0]["message"].get<std::string>(), Catch::EndsWith("hint: robotsim check runs it to its end"));
}

TEST_CASE("lsp: hovers and inlay hints agree with the run", "[lsp][runs]") {
  LspSession s;
  s.initialize(Json::object());
  const std::string path = kMistakes + "out_of_range.rsp";
  const std::string uri = rs::lsp::uriOfPath(path);
  s.open(uri, rs::testing::readBytes(path));
  s.idle();
  const auto hover = [&](unsigned line, unsigned character) {
    return s.result("textDocument/hover", LspSession::at(uri, line, character))["contents"]["value"].get<std::string>();
  };
  // Line 10 (0-based 9): "again:  MOVE 300 0 0 0 0". E moves 300 at 400
  // units/s: 0.75 s a time; three times to 900 by 2.25 s, then the fourth
  // would end at 1200 and stops the run there.
  CHECK_THAT(hover(9, 9), Catch::EndsWith("In the checked run it stops here at 2.25 s: MOVE takes motor E to 1200, "
                                          "outside its range -1000..1000."));
  // HRDHOME (line 13) never runs: the run stopped before.
  CHECK_THAT(hover(12, 9), Catch::EndsWith("In the checked run it never runs: the run stopped by an error at 2.25 s "
                                           "(line 10: MOVE takes motor E to 1200, outside its range -1000..1000)."));
  const Json hints = s.result("textDocument/inlayHint",
                              {{"textDocument", {{"uri", uri}}}, {"range", LspSession::range(0, 0, 14, 0)}});
  std::vector<std::string> labels;
  for (const Json& h : hints) labels.push_back(h["label"].get<std::string>());
  // SET runs once (0 s), the MOVE stops the run, ADD and JMPVAR ran three
  // times (first at 0.75 s), HRDHOME and END never ran.
  CHECK(labels == std::vector<std::string>{"#1", "ends 0 s", "#2", "stops 2.25 s (runtime error)", "#3",
                                           "ends 0.75 s (first of 3)", "#4", "ends 0.75 s (first of 3)", "#5", "#6"});
}

TEST_CASE("lsp: a hover waits for the run being made, and hints made before it are refreshed", "[lsp][runs]") {
  LspSession s;
  s.initialize({{"workspace", {{"inlayHint", {{"refreshSupport", true}}}}}});
  const std::string path = kMistakes + "out_of_range.rsp";
  const std::string uri = rs::lsp::uriOfPath(path);
  s.open(uri, rs::testing::readBytes(path));
  // Hints asked for before the version is published: its run has not been
  // asked for, so they come at once, without times.
  const Json range = {{"textDocument", {{"uri", uri}}}, {"range", LspSession::range(0, 0, 14, 0)}};
  CHECK(s.result("textDocument/inlayHint", range).size() == 6);  // #1 .. #6
  s.publishOnly();
  // The run is being made: a hover waits for it (it takes microseconds).
  const Json hover = s.result("textDocument/hover", LspSession::at(uri, 9, 9));
  CHECK_THAT(hover["contents"]["value"].get<std::string>(), Catch::EndsWith("it stops here at 2.25 s: MOVE takes "
                                                                             "motor E to 1200, outside its range "
                                                                             "-1000..1000."));
  s.idle();
  // Once the run is made, the client is asked to refresh its hints.
  std::vector<Json> refreshes;
  for (const Json& m : s.sent())
    if (m.value("method", "") == "workspace/inlayHint/refresh") refreshes.push_back(m);
  REQUIRE(refreshes.size() == 1);
  CHECK(refreshes[0]["id"] == "robotsim-inlay-refresh-1");
  CHECK(s.result("textDocument/inlayHint", range).size() == 10);
  // The client's answer is taken without a word.
  s.clearSent();
  s.receive({{"jsonrpc", "2.0"}, {"id", "robotsim-inlay-refresh-1"}, {"result", nullptr}});
  CHECK(s.sent().empty());
  // A client that cannot refresh is not asked.
  LspSession t;
  t.initialize();
  t.open(uri, rs::testing::readBytes(path));
  t.result("textDocument/inlayHint", range);
  t.idle();
  for (const Json& m : t.sent()) CHECK(m.value("method", "") != "workspace/inlayHint/refresh");
}

TEST_CASE("lsp: the run takes the stimuli file beside the program, as the editor holds it", "[lsp][runs]") {
  // As the editors' Check command runs it: robotsim check P.rsp --stimuli P.stim.
  const std::string example = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/pick_and_place";
  const rs::testing::CliResult check =
      rs::testing::runCli({"check", example + ".rsp", "--stimuli", example + ".stim", "--format=json"});
  REQUIRE(check.code == 0);
  CHECK(Json::parse(check.out)["diagnostics"].empty());
  LspSession s;
  s.initialize();
  s.open(rs::lsp::uriOfPath(example + ".rsp"), rs::testing::readBytes(example + ".rsp"));
  s.idle();
  CHECK(s.diagnostics(rs::lsp::uriOfPath(example + ".rsp")) == Json::array());  // no deadlock: the .stim was read

  // Unsaved stimuli text counts, and each change to it runs the program again.
  rs::testing::TempDir dir;
  const std::string program = rs::lsp::uriOfPath(dir.write("wait.rsp", "        WAITFOR 1 ON\n        END\n"));
  const std::string stimuli = rs::lsp::uriOfPath(dir.file("wait.stim"));  // not on disk
  s.open(program, "        WAITFOR 1 ON\n        END\n");
  s.idle();
  REQUIRE(s.diagnostics(program).size() == 1);
  CHECK_THAT(s.diagnostics(program)[0]["message"].get<std::string>(), Catch::StartsWith("deadlock: input 1 never turns ON"));
  s.open(stimuli, "at 1.5 input 1 on\n", "robotsim-stimuli");
  s.idle();
  CHECK(s.diagnostics(program) == Json::array());
  const Json hover = s.result("textDocument/hover", LspSession::at(program, 0, 9));
  CHECK_THAT(hover["contents"]["value"].get<std::string>(), Catch::EndsWith("In the checked run: from 0 s to 1.5 s (takes 1.5 s)."));
  s.notify("textDocument/didChange", {{"textDocument", {{"uri", stimuli}, {"version", 2}}},
                                      {"contentChanges", {{{"text", "at 1.5 input 9 on\n"}}}}});
  s.idle();
  const Json note = s.diagnostics(program);
  REQUIRE(note.size() == 1);
  CHECK(note[0]["severity"] == 3);
  CHECK(note[0]["code"] == "run-not-made");
  CHECK(note[0]["message"] == "not run in the editor: the stimuli file beside it, wait.stim, has errors\n"
                              "hint: its diagnostics are in that file");
  CHECK(s.diagnostics(stimuli).size() == 1);
  // Closed (and never saved): the program runs without stimuli again.
  s.notify("textDocument/didClose", {{"textDocument", {{"uri", stimuli}}}});
  s.idle();
  REQUIRE(s.diagnostics(program).size() == 1);
  CHECK_THAT(s.diagnostics(program)[0]["message"].get<std::string>(), Catch::StartsWith("deadlock:"));
}
