// Issue 35 in the editor: hover on an input number says what drives it (a
// wire of the program's cell, the stimuli file beside the program, a
// reactive rule in it, or nothing), and a WAITFOR on an input nothing can
// ever turn on is the warning `input-never-on`. The expected texts are
// worked out from stdlib/workcells/adept-cell.rsd (its SENSOR eye and the
// WIRE from it to input 1) and the stimuli written here.
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace lsp_inputs_test {

// The 1-based line of `cell` that starts with `start`, as messages number lines.
unsigned lineNumberOf(const std::string& text, const std::string& start) { return LspSession::lineOf(text, start) + 1; }

Json hoverText(LspSession& s, const std::string& uri, unsigned line, unsigned character) {
  const Json h = s.result("textDocument/hover", LspSession::at(uri, line, character));
  return h.is_null() ? h : h["contents"]["value"];
}

std::vector<Json> withCode(const Json& diagnostics, const std::string& code) {
  std::vector<Json> out;
  for (const Json& d : diagnostics)
    if (d.value("code", "") == code) out.push_back(d);
  return out;
}

const std::string kWiredInputsProgram =
    "; cell: adept-cell\n"        // 0
    "        WAITFOR 1 ON\n"      // 1: wired from the sensor eye
    "        JMPIN 4 ON done\n"   // 2: a timed stimulus
    "        WAITFOR 5 ON\n"      // 3: a reactive rule
    "        WAITFOR 3 ON\n"      // 4: nothing
    "        WAITFOR 6 OFF\n"     // 5: nothing, but inputs start OFF
    "done:   END\n";              // 6

// The diagnostics the server published first for `uri`: the compile's,
// before a run's replace any.
Json firstPublished(const LspSession& s, const std::string& uri) {
  for (const Json& m : s.sent())
    if (m.value("method", "") == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri)
      return m["params"]["diagnostics"];
  return nullptr;
}

// A cell whose wires hold inputs at one level: ON INVERTED and OFF never on,
// OFF INVERTED always on; input 5 has no wire while 1..4 have.
const std::string kHeldWiresCell =
    "WORKCELL wired\n"                               // 1
    "  ROBOT adept-one AT 0 0 0\n"                   // 2
    "  SENSOR eye BEAM 300 520 440  300 520 760\n"   // 3
    "  WIRE eye TO IN 1\n"                           // 4
    "  WIRE ON TO IN 3 INVERTED\n"                   // 5
    "  WIRE OFF TO IN 2\n"                           // 6
    "  WIRE OFF TO IN 4 INVERTED\n"                  // 7
    "END\n";

const std::string kHeldWiresProgram =
    "; cell: wired.rsd\n"    // 0
    "        WAITFOR 3 ON\n"  // 1: ON INVERTED
    "        WAITFOR 2 ON\n"  // 2: OFF
    "        WAITFOR 4 ON\n"  // 3: OFF INVERTED: always ON
    "        WAITFOR 5 ON\n"  // 4: no wire
    "        END\n";

}  // namespace lsp_inputs_test

using namespace lsp_inputs_test;

TEST_CASE("lsp: hover on an input number says what drives it, a WAITFOR nothing can end warns", "[lsp][inputs]") {
  rs::testing::TempDir dir;
  const std::string program = rs::lsp::uriOfPath(dir.write("p.rsp", kWiredInputsProgram));
  dir.write("p.stim", "at 1.5 input 4 on\nwhen output 1 on then input 5 on after 0.5\n");
  LspSession s;
  s.initialize();
  s.open(program, kWiredInputsProgram);
  s.idle();

  const std::string cell = rs::testing::readBytes(std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/workcells/adept-cell.rsd");
  const unsigned wire = lineNumberOf(cell, "  WIRE     eye TO IN 1");
  // "        WAITFOR 1 ON": the number at character 16, the hover on it and just after it.
  const std::string eye = "input 1: sensor eye (BEAM 300 520 440 300 520 760), wired on line " + std::to_string(wire) +
                          " of adept-cell";
  CHECK(hoverText(s, program, 1, 16) == eye);
  CHECK(hoverText(s, program, 1, 17) == eye);
  const Json h = s.result("textDocument/hover", LspSession::at(program, 1, 16));
  CHECK(h["range"] == LspSession::range(1, 16, 1, 17));
  CHECK(hoverText(s, program, 2, 14) == "input 4: the stimuli file p.stim (line 1)");
  CHECK(hoverText(s, program, 3, 16) ==
        "input 5: a reactive rule in p.stim (line 2: when output 1 turns ON, it turns ON 0.5 s later)");
  CHECK(hoverText(s, program, 4, 16) ==
        "input 3: nothing drives it (no wire in the cell, nothing in p.stim): it stays OFF");
  // The mnemonic still has the instruction's help.
  CHECK_THAT(hoverText(s, program, 1, 9).get<std::string>(), Catch::StartsWith("**WAITFOR**"));

  // Only the WAITFOR 3 ON can never end: at its number, with a hint.
  const std::vector<Json> warned = withCode(s.diagnostics(program), "input-never-on");
  REQUIRE(warned.size() == 1);
  CHECK(warned[0]["severity"] == 2);
  CHECK(warned[0]["range"] == LspSession::range(4, 16, 4, 17));
  // adept-cell wires input 1 only, and the message says so.
  CHECK(warned[0]["message"] ==
        "input 3 has no wire in adept-cell (input 1 does), and p.stim never turns it on: it is never ON, so WAITFOR 3 "
        "ON can never end\n"
        "hint: wire a source to it in the cell (WIRE eye TO IN 3), or give it a stimulus "
        "(\"at 1 input 3 on\" in the program's .stim file)");
}

TEST_CASE("lsp: without a cell or a stimuli file, every WAITFOR n ON warns and gives way to the run's deadlock",
          "[lsp][inputs]") {
  LspSession s;
  s.initialize();
  const std::string uri = "file:///nowhere/w.rsp";
  s.open(uri, "        JMPIN 2 ON skip\n        WAITFOR 2 ON\nskip:   WAITFOR 7 ON\n        END\n");
  s.publishOnly();
  CHECK(hoverText(s, uri, 0, 14) ==
        "input 2: nothing drives it (no wire in the cell, no stimuli file beside the program): it stays OFF");
  s.idle();
  // The run stops with a deadlock at line 1 (input 2): that warning gives
  // way to the error; line 2's, which the run never reached, stays.
  const Json d = s.diagnostics(uri);
  const std::vector<Json> warned = withCode(d, "input-never-on");
  REQUIRE(warned.size() == 1);
  CHECK(warned[0]["range"]["start"]["line"] == 2);
  const std::vector<Json> deadlocks = withCode(d, "deadlock");
  REQUIRE(deadlocks.size() == 1);
  CHECK(deadlocks[0]["range"]["start"]["line"] == 1);
}

TEST_CASE("lsp: input-never-on follows the wire: OFF and ON INVERTED are never ON", "[lsp][inputs][devices]") {
  rs::testing::TempDir dir;
  dir.write("wired.rsd", kHeldWiresCell);
  const std::string program = rs::lsp::uriOfPath(dir.write("p.rsp", kHeldWiresProgram));
  LspSession s;
  s.initialize();
  s.open(program, kHeldWiresProgram);
  s.idle();
  // The hover says what a held wire does.
  CHECK(hoverText(s, program, 1, 16) == "input 3: ON INVERTED, wired on line 5 of wired.rsd: always OFF");
  CHECK(hoverText(s, program, 2, 16) == "input 2: OFF, wired on line 6 of wired.rsd: always OFF");
  CHECK(hoverText(s, program, 3, 16) == "input 4: OFF INVERTED, wired on line 7 of wired.rsd: always ON");
  // Three of the four waits can never end; the compile's warnings, before the run's deadlock takes line 1's place.
  const std::vector<Json> warned = withCode(firstPublished(s, program), "input-never-on");
  REQUIRE(warned.size() == 3);
  CHECK(warned[0]["range"] == LspSession::range(1, 16, 1, 17));
  CHECK(warned[0]["message"] ==
        "input 3 is wired from ON INVERTED (line 5 of wired.rsd): it is never ON, so WAITFOR 3 ON can never end\n"
        "hint: drop INVERTED from the WIRE on line 5, or give it a stimulus (\"at 1 input 3 on\" in the program's "
        ".stim file)");
  CHECK(warned[1]["range"]["start"]["line"] == 2);
  CHECK(warned[1]["message"] ==
        "input 2 is wired from OFF (line 6 of wired.rsd): it is never ON, so WAITFOR 2 ON can never end\n"
        "hint: wire a sensor or an output to it on line 6 instead of OFF, or give it a stimulus (\"at 1 input 2 on\" "
        "in the program's .stim file)");
  CHECK(warned[2]["range"]["start"]["line"] == 4);
  CHECK_THAT(warned[2]["message"].get<std::string>(),
             Catch::StartsWith("input 5 has no wire in wired.rsd (inputs 1, 2, 3 and 4 do), no stimulus and no rule: "
                               "it is never ON, so WAITFOR 5 ON can never end\n"));
  // A stimulus that turns input 3 on ends that wait after all: no warning on it.
  dir.write("p.stim", "at 1 input 3 on\n");
  LspSession t;
  t.initialize();
  t.open(program, kHeldWiresProgram);
  t.idle();
  const std::vector<Json> left = withCode(firstPublished(t, program), "input-never-on");
  REQUIRE(left.size() == 2);
  CHECK(left[0]["range"]["start"]["line"] == 2);
}

// A polling loop is a WAITFOR written out: its one way out is a JMPIN n ON,
// and when nothing turns input n on it can never end. The loop on input 1
// (adept-cell's sensor wire) can; the one on input 3 cannot. A JMPIN that
// only skips ahead (line 7) is no loop, whatever its input.
TEST_CASE("lsp: input-never-on covers a polling loop whose one way out is a JMPIN", "[lsp][inputs]") {
  const std::string text =
      "; cell: adept-cell\n"      // 0
      "poll:   DELAY 0.1\n"       // 1
      "        JMPIN 1 ON next\n" // 2
      "        GOTO poll\n"       // 3
      "next:   JMPIN 3 ON done\n" // 4
      "        GOTO next\n"       // 5
      "        JMPIN 6 ON done\n" // 6
      "done:   END\n";            // 7
  rs::testing::TempDir dir;
  const std::string program = rs::lsp::uriOfPath(dir.write("poll.rsp", text));
  LspSession s;
  s.initialize();
  s.open(program, text);
  s.idle();
  const std::vector<Json> warned = withCode(firstPublished(s, program), "input-never-on");
  REQUIRE(warned.size() == 1);
  CHECK(warned[0]["range"] == LspSession::range(4, 14, 4, 15));
  CHECK(warned[0]["message"] ==
        "input 3 has no wire in adept-cell (input 1 does), no stimulus and no rule: it is never ON, so the loop of "
        "lines 5..6 can never end (its one way out is JMPIN 3 ON)\n"
        "hint: wire a source to it in the cell (WIRE eye TO IN 3), or give it a stimulus "
        "(\"at 1 input 3 on\" in the program's .stim file)");
}
