// Issue 36 in the editor: a program in a cell where other robots have
// programs is checked by running the whole cell with them (their open
// documents' text first, else their files), and what the run finds is
// published in the document of the program it belongs to: the deadlock in
// each waiting robot's program at its WAITFOR, a collision in the moving
// robot's program; and in the edited program, naming the robot, what
// belongs to a program that is not open.
#include <catch2/catch.hpp>

#include <string>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

const std::string kTwoRobots = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// The example's programs, each with the directives that put it in the
// cell: left names its robot, right is found as the robot whose PROGRAM it is.
struct Interlock {
  rs::testing::TempDir dir;
  std::string left, right;          // the texts
  std::string leftUri, rightUri;
  Interlock() {
    dir.write("interlock.rsd", rs::testing::readBytes(kTwoRobots + "interlock.rsd"));
    left = "; cell: interlock.rsd\n; robot: left\n" + rs::testing::readBytes(kTwoRobots + "left.rsp");
    right = "; cell: interlock.rsd\n" + rs::testing::readBytes(kTwoRobots + "right.rsp");
    leftUri = rs::lsp::uriOfPath(dir.write("left.rsp", left));
    rightUri = rs::lsp::uriOfPath(dir.write("right.rsp", right));
  }
  // left waits for right's "your turn" before it gives its own: the two
  // wait for each other.
  static std::string waitingFirst(const std::string& left) {
    return replaced(left,
                    "        OUTSIG 1 ON             ; your turn\n"
                    "        WAITFOR 1 ON            ; wait for the right robot's \"your turn\"\n",
                    "        WAITFOR 1 ON            ; wait for the right robot's \"your turn\"\n"
                    "        OUTSIG 1 ON             ; your turn\n");
  }
};

std::vector<Json> diagnosticsWithCode(const Json& diagnostics, const std::string& code) {
  std::vector<Json> out;
  for (const Json& d : diagnostics)
    if (d.value("code", "") == code) out.push_back(d);
  return out;
}

std::vector<Json> errors(const Json& diagnostics) {
  std::vector<Json> out;
  for (const Json& d : diagnostics)
    if (d.value("severity", 0) == 1) out.push_back(d);
  return out;
}

void changeAll(LspSession& s, const std::string& uri, int version, const std::string& text) {
  s.notify("textDocument/didChange",
           {{"textDocument", {{"uri", uri}, {"version", version}}}, {"contentChanges", {{{"text", text}}}}});
}

// By hand, from the programs and stdlib/robots/rhino-xr4.rsd (motor F at
// 300 counts a second): left moves in and out (0 to 2 s), then waits on its
// input 1 (wired from right.OUT 1); right waits on its input 1 (wired from
// left.OUT 1) from the start. Neither output ever turns on: at 2 s both
// wait for ever. The lines: left's WAITFOR is the example's line 9 (its
// OUTSIG's, swapped) plus the two directive lines, right's the example's
// line 5 plus one; each WAITFOR starts at column 9 (after the label
// "again:  " on right's line, after 8 blanks on left's).
std::string deadlockMessage(const Interlock& c) {
  return "deadlock: left waits at " + c.dir.file("left.rsp") +
         ":11 for input 1 (wired from right.OUT 1); right waits at " + c.dir.file("right.rsp") +
         ":6 for input 1 (wired from left.OUT 1)";
}

}  // namespace

TEST_CASE("lsp cell run: a deadlock across the interlock example shows in each program at its WAITFOR",
          "[lsp][runs][cell-run]") {
  Interlock c;
  const std::string left = Interlock::waitingFirst(c.left);
  c.dir.write("left.rsp", left);
  LspSession s;
  s.initialize();
  s.open(c.leftUri, left);
  s.open(c.rightUri, c.right);
  s.idle();
  const std::vector<Json> l = diagnosticsWithCode(s.diagnostics(c.leftUri), "deadlock");
  const std::vector<Json> r = diagnosticsWithCode(s.diagnostics(c.rightUri), "deadlock");
  CAPTURE(s.diagnostics(c.leftUri).dump(), s.diagnostics(c.rightUri).dump());
  REQUIRE(l.size() == 1);
  REQUIRE(r.size() == 1);
  CHECK(LspSession::lineOf(left, "        WAITFOR 1 ON") == 10);
  CHECK(LspSession::lineOf(c.right, "again:  WAITFOR 1 ON") == 5);
  CHECK(l[0]["range"] == LspSession::range(10, 8, 10, 15));  // the word WAITFOR
  CHECK(r[0]["range"] == LspSession::range(5, 8, 5, 15));
  const std::string message = deadlockMessage(c) +
                              "\nhint: a robot waits for an input that only another waiting robot's output drives: "
                              "change the order of an OUTSIG and a WAITFOR in one program";
  CHECK(l[0]["message"] == message);
  CHECK(r[0]["message"] == message);
  CHECK(errors(s.diagnostics(c.leftUri)).size() == 1);
  CHECK(errors(s.diagnostics(c.rightUri)).size() == 1);
  // The command line says the same of the same files.
  const auto cli = rs::testing::runCli({"check", c.dir.file("left.rsp"), "--cell", c.dir.file("interlock.rsd")});
  CHECK(cli.err.find(deadlockMessage(c)) != std::string::npos);
}

TEST_CASE("lsp cell run: an edit of one program publishes the other program's diagnostics", "[lsp][runs][cell-run]") {
  Interlock c;
  LspSession s;
  s.initialize();
  s.open(c.leftUri, c.left);
  s.open(c.rightUri, c.right);
  s.idle();
  // As the examples' test works out: the two take turns and end at 8.5 s.
  CHECK(errors(s.diagnostics(c.leftUri)).empty());
  CHECK(errors(s.diagnostics(c.rightUri)).empty());
  // The hover on right's move back says when it ran in the cell run (alone,
  // right would wait for ever at its first WAITFOR): left's OUT 1 turns on
  // at 2 s and reaches right at once, right's MOVE 300 takes 2 to 3 s and
  // its MOVE -300 3 to 4 s, on the first of its two turns.
  const unsigned back = LspSession::lineOf(c.right, "        MOVE -300");
  const Json hover = s.result("textDocument/hover", LspSession::at(c.rightUri, back, 9));
  CAPTURE(hover.dump());
  CHECK(hover.dump().find("In the checked run: from 3 s to 4 s (takes 1 s), the first of 2 times.") !=
        std::string::npos);

  s.clearSent();
  changeAll(s, c.leftUri, 2, Interlock::waitingFirst(c.left));
  s.idle();
  // Right's text did not change: its diagnostics come for its version 1.
  const std::vector<Json> r = diagnosticsWithCode(s.diagnostics(c.rightUri), "deadlock");
  REQUIRE(r.size() == 1);
  CHECK(r[0]["range"]["start"]["line"] == 5);
  bool forVersion1 = false;
  for (const Json& m : s.sent())
    if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == c.rightUri)
      forVersion1 = m["params"]["version"] == 1;
  CHECK(forVersion1);
  CHECK(diagnosticsWithCode(s.diagnostics(c.leftUri), "deadlock").size() == 1);
  // Undone: the deadlock goes from both.
  changeAll(s, c.leftUri, 3, c.left);
  s.idle();
  CHECK(errors(s.diagnostics(c.leftUri)).empty());
  CHECK(errors(s.diagnostics(c.rightUri)).empty());
}

TEST_CASE("lsp cell run: the example's program named by its cell's PROGRAM, with robotsim.cell", "[lsp][runs][cell-run]") {
  // No directive: the setting names the cell, and right.rsp is the PROGRAM
  // of robot right; left.rsp is read from its file. The times as in the
  // test above: right's move back runs from 3 s to 4 s, twice.
  LspSession s;
  s.initialize(Json::object(), {{"robotsim", {{"cell", kTwoRobots + "interlock.rsd"}}}});
  const std::string right = rs::testing::readBytes(kTwoRobots + "right.rsp");
  const std::string uri = rs::lsp::uriOfPath(kTwoRobots + "right.rsp");
  s.open(uri, right);
  s.idle();
  CHECK(errors(s.diagnostics(uri)).empty());
  const Json hover = s.result("textDocument/hover", LspSession::at(uri, LspSession::lineOf(right, "        MOVE -300"), 9));
  CAPTURE(hover.dump());
  CHECK(hover.dump().find("In the checked run: from 3 s to 4 s (takes 1 s), the first of 2 times.") !=
        std::string::npos);
}

TEST_CASE("lsp cell run: the other robot's program is read from its file when it is not open", "[lsp][runs][cell-run]") {
  Interlock c;
  LspSession s;
  s.initialize();
  const std::string left = Interlock::waitingFirst(c.left);
  s.open(c.leftUri, left);
  s.idle();
  // right.rsp from disk: the same deadlock, once, in left (its message names right's line).
  const std::vector<Json> l = diagnosticsWithCode(s.diagnostics(c.leftUri), "deadlock");
  REQUIRE(l.size() == 1);
  CHECK(l[0]["message"].get<std::string>().starts_with(deadlockMessage(c)));
  CHECK(s.diagnostics(c.rightUri).is_null());  // nothing is published for a document that is not open

  // Right's program saved with an error: the cell is not run, and a note says why.
  c.dir.write("right.rsp", replaced(c.right, "OUTSIG 1 ON", "OUTSIG 9 ON"));
  changeAll(s, c.leftUri, 2, left + "\n");
  s.idle();
  const std::vector<Json> notes = diagnosticsWithCode(s.diagnostics(c.leftUri), "run-not-made");
  REQUIRE(notes.size() == 1);
  CHECK(notes[0]["message"].get<std::string>().starts_with(
      "not run in the editor: robot right's program right.rsp has errors (the cell runs every robot's program "
      "together)"));
  CHECK(diagnosticsWithCode(s.diagnostics(c.leftUri), "deadlock").empty());
}

namespace {

// The cell of tests/cli/test_cell_run.cpp's collision test: two XR-4s
// facing each other 600 apart, clear at home; left's shoulder (motor E)
// swung by 600 counts brings its wrist into right's gripper.
struct Facing {
  rs::testing::TempDir dir;
  std::string leftUri, rightUri;
  Facing(const std::string& left, const std::string& right) {
    dir.write("c.rsd", "WORKCELL face\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
                       "  ROBOT rhino-xr4 AT 600 750 0 ROTATE Y 180 AS right PROGRAM r.rsp\nEND\n");
    leftUri = rs::lsp::uriOfPath(dir.write("l.rsp", "; cell: c.rsd\n" + left));
    rightUri = rs::lsp::uriOfPath(dir.write("r.rsp", "; cell: c.rsd\n" + right));
  }
};

const std::string kSwing = "        MOVE 0 600 0 0 0 0\n        END\n";
const std::string kStand = "        DELAY 3\n        END\n";

}  // namespace

TEST_CASE("lsp cell run: a collision between the robots shows in the moving robot's program", "[lsp][runs][cell-run]") {
  SECTION("left moves into right") {
    Facing c(kSwing, kStand);
    LspSession s;
    s.initialize();
    s.open(c.leftUri, "; cell: c.rsd\n" + kSwing);
    s.open(c.rightUri, "; cell: c.rsd\n" + kStand);
    s.idle();
    const std::vector<Json> l = errors(s.diagnostics(c.leftUri));
    CAPTURE(s.diagnostics(c.leftUri).dump(), s.diagnostics(c.rightUri).dump());
    REQUIRE(l.size() == 1);
    CHECK(l[0]["code"] == "runtime-error");
    CHECK(l[0]["range"]["start"] == Json{{"line", 1}, {"character", 8}});  // the MOVE, after the directive
    const std::string message = l[0]["message"];
    CHECK(message.starts_with("runtime error: collision at "));
    CHECK(message.find("of robot 'left' hits ") != std::string::npos);
    CHECK(message.find("of robot 'right'") != std::string::npos);
    CHECK(message.find("robot left stopped the cell") != std::string::npos);
    CHECK(errors(s.diagnostics(c.rightUri)).empty());  // right only stood there
  }
  SECTION("right moves into left, and right is not open: left says so, naming right's line") {
    Facing c(kStand, kSwing);
    LspSession s;
    s.initialize();
    s.open(c.leftUri, "; cell: c.rsd\n" + kStand);
    s.idle();
    const std::vector<Json> l = errors(s.diagnostics(c.leftUri));
    CAPTURE(s.diagnostics(c.leftUri).dump());
    REQUIRE(l.size() == 1);
    const std::string message = l[0]["message"];
    CHECK(message.starts_with("robot right (r.rsp:2): runtime error: collision at "));
    CHECK(message.find("of robot 'right' hits ") != std::string::npos);
    // At left's DELAY, where the cell stopped it.
    CHECK(l[0]["range"]["start"] == Json{{"line", 1}, {"character", 8}});
    REQUIRE(l[0].contains("relatedInformation"));
    CHECK(l[0]["relatedInformation"][0]["location"]["uri"] == c.rightUri);
  }
}

TEST_CASE("lsp cell run: a program put in another's place does not speak for the other's document",
          "[lsp][runs][cell-run]") {
  // scratch.rsp runs on left (its "; robot: left" line) in place of left.rsp,
  // and deadlocks with right as left.rsp edited does above; right.rsp's own
  // check runs the cell's PROGRAMs (left.rsp as written: no deadlock), so
  // right.rsp's document keeps what its own run found.
  Interlock c;
  const std::string scratch = Interlock::waitingFirst(c.left);
  const std::string scratchUri = rs::lsp::uriOfPath(c.dir.write("scratch.rsp", scratch));
  LspSession s;
  s.initialize();
  s.open(c.rightUri, c.right);
  s.idle();
  s.open(scratchUri, scratch);
  s.idle();
  CHECK(errors(s.diagnostics(c.rightUri)).empty());
  const std::vector<Json> d = diagnosticsWithCode(s.diagnostics(scratchUri), "deadlock");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["message"].get<std::string>().starts_with("deadlock: left waits at " + c.dir.file("scratch.rsp") + ":11 "));
  CHECK(errors(s.diagnostics(scratchUri)).size() == 1);
}
