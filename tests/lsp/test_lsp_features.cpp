// Every language feature on programs, through the server's methods, with
// the exact results worked out by hand from the program below (lines and
// characters 0-based, as LSP counts them).
#include <catch2/catch.hpp>

#include "tests/lsp/lsp_session.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

const std::string kUri = "file:///work/test.rsp";
// Times of the checked run (what robotsim check runs), by hand: SET at 0; MOVE E+100 at 400 units/s
// takes 0.25 s, three passes (E = 300 at 0.75 s); MOVEP HOME brings E from
// 300 to 0: 0.75 s, so 1.5 s; RETURN and END at 1.5 s.
const std::string kProgram =
    "; a test program\n"                            // 0
    "        SET N 0\n"                             // 1
    "loop:   MOVE 100 0 0 0 0        ; 0.25 s\n"    // 2
    "        ADD N 1\n"                             // 3
    "        JMPVAR N < 3 loop\n"                   // 4
    "        GOSUB sub\n"                           // 5
    "        END\n"                                 // 6
    "\n"                                            // 7
    "sub:    MOVEP HOME\n"                          // 8
    "        RETURN\n"                              // 9
    "\n"                                            // 10
    "POINTS\n"                                      // 11
    "HOME 0 0 0 0 0\n";                             // 12

Json range(unsigned l0, unsigned c0, unsigned l1, unsigned c1) { return LspSession::range(l0, c0, l1, c1); }
Json loc(unsigned l0, unsigned c0, unsigned l1, unsigned c1) { return {{"uri", kUri}, {"range", range(l0, c0, l1, c1)}}; }

struct Opened {
  LspSession s;
  explicit Opened(const std::string& text = kProgram, Json caps = Json::object(), Json options = nullptr) {
    s.initialize(std::move(caps), std::move(options));
    s.open(kUri, text);
    s.idle();
  }
  Json hoverText(unsigned line, unsigned character) {
    const Json h = s.result("textDocument/hover", LspSession::at(kUri, line, character));
    return h.is_null() ? h : h["contents"]["value"];
  }
};

}  // namespace

TEST_CASE("lsp: a clean program publishes no diagnostics", "[lsp][features]") {
  Opened o;
  CHECK(o.s.diagnostics(kUri) == Json::array());
}

TEST_CASE("lsp: diagnostics as you type, with codes and related places", "[lsp][features]") {
  Opened o;
  // Type a second "loop:" label on line 6 ("        END" -> "loop:   END").
  o.s.notify("textDocument/didChange", {{"textDocument", {{"uri", kUri}, {"version", 2}}},
                                        {"contentChanges", {{{"range", range(6, 0, 6, 5)}, {"text", "loop:"}}}}});
  o.s.idle();
  const Json d = o.s.diagnostics(kUri);
  REQUIRE(d.size() == 1);
  CHECK(d[0] == Json({{"range", range(6, 0, 6, 5)},
                      {"severity", 1},
                      {"source", "robotsim"},
                      {"code", "duplicate-label"},
                      {"message", "label 'loop' is already defined on line 3"},
                      {"relatedInformation", {{{"location", loc(2, 0, 2, 5)}, {"message", "'loop' is first defined here"}}}}}));
  // Two changes in one batch are checked once: one publication.
  o.s.clearSent();
  o.s.notify("textDocument/didChange", {{"textDocument", {{"uri", kUri}, {"version", 3}}},
                                        {"contentChanges", {{{"range", range(6, 0, 6, 5)}, {"text", "     "}}}}});
  o.s.notify("textDocument/didChange", {{"textDocument", {{"uri", kUri}, {"version", 4}}},
                                        {"contentChanges", {{{"range", range(4, 8, 4, 14)}, {"text", "JMPVRA"}}}}});
  o.s.idle();
  REQUIRE(o.s.sent().size() == 1);
  CHECK(o.s.sent()[0]["params"]["version"] == 4);
  const Json d2 = o.s.diagnostics(kUri);
  REQUIRE(d2.size() == 1);
  CHECK(d2[0]["code"] == "unknown-instruction");
  CHECK(d2[0]["message"] == "unknown instruction 'JMPVRA' (did you mean JMPVAR?)");
  CHECK(d2[0]["range"] == range(4, 8, 4, 14));
}

TEST_CASE("lsp: hover on the straight-line moves gives their help from the opcode table", "[lsp][features]") {
  // On the XR-4's cell (the "; cell:" line), a line down to a point and back up.
  Opened o("; cell: xr4-cell\n"
           "        MOVEP ABOVE\n"
           "        MOVES DOWN\n"
           "        DEPART 20\n"
           "        END\n"
           "POINTS\n"
           "ABOVE AT 240 870 -40 APPROACH 0 -1 0\n"
           "DOWN AT 240 850 -40 APPROACH 0 -1 0\n");
  CHECK(o.s.diagnostics(kUri) == Json::array());
  const std::string moves = o.hoverText(2, 9).get<std::string>();
  CHECK(moves.starts_with("**MOVES** — instruction 2\n\n`MOVES <point>`: move the tool centre point along a straight "
                          "line to a taught point"));
  const std::string depart = o.hoverText(3, 9).get<std::string>();
  CHECK(depart.starts_with("**DEPART** — instruction 3\n\n`DEPART <length>`: move the tool straight back along its "
                           "approach axis by a distance"));
}

TEST_CASE("lsp: hover", "[lsp][features]") {
  Opened o;
  const std::string move = o.hoverText(2, 9).get<std::string>();
  CHECK(move.starts_with("**MOVE** — instruction 2\n\n`MOVE <value per motor>`: move every motor by a relative number"));
  CHECK(move.find("- `E` revolute, -1000..1000, 400 units/s") != std::string::npos);
  CHECK(move.ends_with("In the checked run: from 0 s to 0.25 s (takes 0.25 s), the first of 3 times."));
  // The Rhino SCARA's tool centre point at home: (-135, -35, 0), as stdlib/robots/rhino-scara.rsd derives it.
  CHECK(o.hoverText(8, 15) == "**point** `HOME` (line 13): E=0 D=0 C=0 B=0 A=0\n\n"
                              "Tool centre point of rhino-scara: (-135, -35, 0)");
  CHECK(o.hoverText(4, 22) == "**label** `loop`: instruction 2 (line 3, `MOVE 100 0 0 0 0`)");
  CHECK(o.hoverText(5, 15) == "**subroutine** `sub`: instruction 7 (line 9, `MOVEP HOME`)");
  CHECK(o.hoverText(1, 12) == "**variable** `N`: a 32-bit integer, 0 at the start\n\n"
                              "written on line(s) 2, 4; read on line(s) 5");
  const Json h = o.s.result("textDocument/hover", LspSession::at(kUri, 4, 22));
  CHECK(h["range"] == range(4, 21, 4, 25));
  CHECK(o.hoverText(0, 3).is_null());  // a comment
}

TEST_CASE("lsp: a point written as a tool pose hovers with its resolved encoders", "[lsp][features][cell][pose]") {
  // The gantry's tool centre point is (500 + X/10, 200 - Y/10, 400 + Z/10) (see the next test), so
  // AT 220 50 680 is X = -2800, Z = 2800, Y = 1500; the gripper keeps home's 0.
  // The move there goes through a block (check says so): collisions off, as
  // the robotsim.collisions setting allows, for a clean compile's hover.
  const Json off = {{"robotsim", {{"collisions", "off"}}}};
  Opened o("; cell: gantry-cell\n        MOVEP P\n        END\nPOINTS\nP AT 220 50 680\n", Json::object(), off);
  CHECK(o.s.diagnostics(kUri) == Json::array());
  CHECK(o.hoverText(1, 15) == "**point** `P` (line 5): X=-2800 Z=2800 Y=1500 A=0, resolved from the tool pose "
                              "`AT 220 50 680`\n\nTool centre point of gantry: (220, 50, 680)");
  // Out of the gantry's range (X: 0.1 per count, -5000..5000, so x 0..1000): a diagnostic, and the hover says so.
  Opened far("; cell: gantry-cell\n        MOVEP P\n        END\nPOINTS\nP AT 2000 50 680\n");
  const Json d = far.s.diagnostics(kUri);
  REQUIRE(d.size() == 1);
  CHECK(d[0]["code"] == "pose-out-of-range");
  CHECK(far.hoverText(1, 15) ==
        "**point** `P` (line 5): the tool pose `AT 2000 50 680`, not resolved (see its diagnostic)");
}

TEST_CASE("lsp: hover shows the tool centre point on the cell the directive names", "[lsp][features][cell]") {
  // The gantry: motors X Z Y A; its tool centre point is (500 + X/10, 200 - Y/10, 400 + Z/10)
  // (stdlib/robots/gantry.rsd): X = -2800, Z = 2800, Y = 1500 -> (220, 50, 680).
  Opened o("; cell: gantry-cell\n        MOVEP P\n        END\nPOINTS\nP -2800 2800 1500 0\n", Json::object(),
           {{"robotsim", {{"collisions", "off"}}}});
  CHECK(o.s.diagnostics(kUri) == Json::array());
  // With collisions checked, as robotsim check does, the move to P hits a block.
  Opened checked("; cell: gantry-cell\n        MOVEP P\n        END\nPOINTS\nP -2800 2800 1500 0\n");
  const Json hit = checked.s.diagnostics(kUri);
  REQUIRE(hit.size() == 1);
  // At 2.452 s, or up to the swept check's bound later (docs/models.md, "Collisions"). The joint
  // move comes at P (inside block 2) on a slant, so a finger meets that block's side: only the
  // fingers closing or opening round a part are exempt from it, not a move that ends in it.
  CHECK_THAT(hit[0]["message"].get<std::string>(),
             Catch::Matches("runtime error: collision at 2\\.(45[2-9]|46[0-4]) s: finger 2 \\(gantry_finger_l\\) hits object 2 \\(block\\).*"));
  CHECK(o.hoverText(1, 15) == "**point** `P` (line 5): X=-2800 Z=2800 Y=1500 A=0\n\n"
                              "Tool centre point of gantry: (220, 50, 680)");
}

TEST_CASE("lsp: hover lists a motor's acceleration and a gripper's actuation time", "[lsp][features][cell]") {
  // stdlib/robots/abb-irb120.rsd: G 25000 units/s, 280000 units/s²; the
  // gripper A 900 units/s with a fixed 0.1 s.
  Opened o("; cell: irb120-cell\n        MOVE 9000 0 0 0 0 0 0\n        END\n");
  CHECK(o.s.diagnostics(kUri) == Json::array());
  const std::string move = o.hoverText(1, 9).get<std::string>();
  CHECK(move.find("- `G` revolute, -16500..16500, 25000 units/s, 280000 units/s²") != std::string::npos);
  CHECK(move.find("- `A` gripper, 0..90, 900 units/s, 0.100 s a move") != std::string::npos);
}

TEST_CASE("lsp: the robotsim.cell setting, and the directive over it", "[lsp][features][cell]") {
  LspSession s;
  s.initialize(Json::object(), {{"robotsim", {{"cell", "gantry-cell"}}}});
  s.open(kUri, "        MOVETO 0 0 0 0\n        END\n");
  s.idle();
  CHECK(s.diagnostics(kUri) == Json::array());  // four motors: the gantry
  s.notify("workspace/didChangeConfiguration", {{"settings", {{"robotsim", {{"cell", ""}}}}}});
  s.idle();
  const Json d = s.diagnostics(kUri);
  REQUIRE(d.size() == 1);
  CHECK(d[0]["message"] == "MOVETO expects 5 values (one per motor: E D C B A), found 4");
  s.open("file:///work/bad.rsp", "; cell: no-such-cell\n        END\n");
  s.idle();
  const Json bad = s.diagnostics("file:///work/bad.rsp");
  REQUIRE(bad.size() == 1);
  CHECK(bad[0]["code"] == "unknown-cell");
  CHECK(bad[0]["range"] == range(0, 8, 0, 20));
}

TEST_CASE("lsp: go to definition, references, highlights", "[lsp][features]") {
  Opened o;
  CHECK(o.s.result("textDocument/definition", LspSession::at(kUri, 4, 22)) == loc(2, 0, 2, 4));
  CHECK(o.s.result("textDocument/definition", LspSession::at(kUri, 8, 15)) == loc(12, 0, 12, 4));
  CHECK(o.s.result("textDocument/definition", LspSession::at(kUri, 3, 12)) == loc(1, 12, 1, 13));  // first write
  CHECK(o.s.result("textDocument/definition", LspSession::at(kUri, 6, 9)).is_null());
  Json params = LspSession::at(kUri, 4, 22);
  params["context"] = {{"includeDeclaration", true}};
  CHECK(o.s.result("textDocument/references", params) == Json({loc(2, 0, 2, 4), loc(4, 21, 4, 25)}));
  params["context"]["includeDeclaration"] = false;
  CHECK(o.s.result("textDocument/references", params) == Json::array({loc(4, 21, 4, 25)}));
  CHECK(o.s.result("textDocument/documentHighlight", LspSession::at(kUri, 2, 1)) ==
        Json({{{"range", range(2, 0, 2, 4)}, {"kind", 3}}, {{"range", range(4, 21, 4, 25)}, {"kind", 2}}}));
}

TEST_CASE("lsp: a jump by number goes to that instruction", "[lsp][features]") {
  Opened o("        SET N 0\n; two\n        ADD N 1\n        JMPVAR N < 9 2\n");
  CHECK(o.s.result("textDocument/definition", LspSession::at(kUri, 3, 21)) == loc(2, 8, 2, 11));
}

TEST_CASE("lsp: rename", "[lsp][features]") {
  Opened o;
  Json params = LspSession::at(kUri, 4, 22);
  CHECK(o.s.result("textDocument/prepareRename", params) == Json({{"range", range(4, 21, 4, 25)}, {"placeholder", "loop"}}));
  params["newName"] = "again";
  CHECK(o.s.result("textDocument/rename", params) ==
        Json({{"changes", {{kUri, {{{"range", range(2, 0, 2, 4)}, {"newText", "again"}},
                                   {{"range", range(4, 21, 4, 25)}, {"newText", "again"}}}}}}}));
  params["newName"] = "MOVE";
  CHECK(o.s.request("textDocument/rename", params)["error"]["code"] == -32803);
  params["newName"] = "SUB";  // another label already has that name (any case)
  CHECK(o.s.request("textDocument/rename", params)["error"]["message"] == "the program already has a label 'SUB'");
  Json point = LspSession::at(kUri, 12, 2);
  point["newName"] = "PARK";
  CHECK(o.s.result("textDocument/rename", point) ==
        Json({{"changes", {{kUri, {{{"range", range(8, 14, 8, 18)}, {"newText", "PARK"}},
                                   {{"range", range(12, 0, 12, 4)}, {"newText", "PARK"}}}}}}}));
}

TEST_CASE("lsp: rename a variable everywhere it is written and read", "[lsp][features]") {
  Opened o;
  Json params = LspSession::at(kUri, 4, 15);  // the N of JMPVAR
  params["newName"] = "COUNT";
  CHECK(o.s.result("textDocument/rename", params) ==
        Json({{"changes", {{kUri, {{{"range", range(1, 12, 1, 13)}, {"newText", "COUNT"}},
                                   {{"range", range(3, 12, 3, 13)}, {"newText", "COUNT"}},
                                   {{"range", range(4, 15, 4, 16)}, {"newText", "COUNT"}}}}}}}));
}

TEST_CASE("lsp: document symbols and workspace symbols", "[lsp][features]") {
  Opened o;
  const Json symbols = o.s.result("textDocument/documentSymbol", {{"textDocument", {{"uri", kUri}}}});
  const Json want = Json::parse(R"([
    {"name":"loop","detail":"instruction 2","kind":20,"range":)" + range(2, 0, 2, 40).dump() +
                                R"(,"selectionRange":)" + range(2, 0, 2, 4).dump() + R"(},
    {"name":"sub","detail":"subroutine, instruction 7","kind":12,"range":)" + range(8, 0, 9, 14).dump() +
                                R"(,"selectionRange":)" + range(8, 0, 8, 3).dump() + R"(,"children":[]},
    {"name":"POINTS","detail":"1 taught points","kind":3,"range":)" + range(11, 0, 12, 14).dump() +
                                R"(,"selectionRange":)" + range(11, 0, 11, 6).dump() + R"(,"children":[
      {"name":"HOME","detail":"point","kind":14,"range":)" + range(12, 0, 12, 14).dump() +
                                R"(,"selectionRange":)" + range(12, 0, 12, 4).dump() + R"(}]}])");
  CHECK(symbols == want);
  const Json ws = o.s.result("workspace/symbol", {{"query", "sb"}});
  CHECK(ws == Json::parse(R"([{"name":"sub","kind":12,"location":)" + loc(8, 0, 8, 3).dump() +
                          R"(,"containerName":"/work/test.rsp"}])"));
}

TEST_CASE("lsp: folding ranges", "[lsp][features]") {
  Opened o("; one\n; two\n" + kProgram);
  // Everything moves down two lines; the two comment lines at the top fold,
  // and so do lines 2..3 (the original's line 0 joins them).
  CHECK(o.s.result("textDocument/foldingRange", {{"textDocument", {{"uri", kUri}}}}) ==
        Json::parse(R"([{"startLine":10,"endLine":11,"kind":"region"},{"startLine":13,"endLine":14,"kind":"region"},
                        {"startLine":0,"endLine":2,"kind":"comment"}])"));
}

TEST_CASE("lsp: formatting", "[lsp][features]") {
  Opened o;
  const Json edits = o.s.result("textDocument/formatting", {{"textDocument", {{"uri", kUri}}}, {"options", {{"tabSize", 8}, {"insertSpaces", true}}}});
  CHECK(edits == Json::parse(R"([{"range":)" + range(2, 0, 2, 40).dump() +
                             R"(,"newText":"loop:   MOVE 100 0 0 0 0            ; 0.25 s"},{"range":)" +
                             range(12, 0, 12, 14).dump() + R"(,"newText":"HOME  0  0  0  0  0"}])"));
}

TEST_CASE("lsp: completion by the operand's kind", "[lsp][features]") {
  const std::string text =
      "        GOTO \n"            // 0
      "        OUTSIG 1 \n"        // 1
      "        JMPVAR \n"          // 2
      "        JMPVAR N \n"        // 3
      "start:  SET N 0\n"          // 4
      "        MOVEP \n"           // 5
      "        MO\n"               // 6
      "POINTS\n"                   // 7
      "P1 0 0 0 0 0\n";            // 8
  Opened o(text, {{"textDocument", {{"completion", {{"completionItem", {{"snippetSupport", true}}}}}}}});
  const auto complete = [&](unsigned l, unsigned c) { return o.s.result("textDocument/completion", LspSession::at(kUri, l, c)); };
  CHECK(complete(0, 13) == Json::parse(R"J([{"label":"start","kind":18,"detail":"instruction 5 (line 5)"}])J"));
  CHECK(complete(1, 17) == Json::parse(R"([{"label":"ON","kind":20,"detail":"switched on"},{"label":"OFF","kind":20,"detail":"switched off"}])"));
  CHECK(complete(2, 15) == Json::parse(R"([{"label":"N","kind":6,"detail":"variable"}])"));
  CHECK(complete(3, 17) == Json::parse(R"([{"label":"<","kind":24,"detail":"comparison"},{"label":">","kind":24,"detail":"comparison"},{"label":"=","kind":24,"detail":"comparison"}])"));
  CHECK(complete(5, 14) == Json::parse(R"([{"label":"P1","kind":21,"detail":"0 0 0 0 0"}])"));
  const Json ops = complete(6, 10);
  REQUIRE(ops.size() == 23);  // the paper's 20, then MOVES, APPRO, DEPART
  CHECK(ops[20]["label"] == "MOVES");
  CHECK(ops[21]["insertText"] == "APPRO ${1:50}");
  CHECK(ops[22]["label"] == "DEPART");
  CHECK(ops[0]["label"] == "MOVE");
  CHECK(ops[0]["insertText"] == "MOVE ${1:0} ${2:0} ${3:0} ${4:0} ${5:0}");
  CHECK(ops[0]["insertTextFormat"] == 2);
  CHECK(ops[3]["insertText"] == "GOTO ${1|start|}");
  CHECK(ops[4]["insertText"] == "JMPIN ${1|1,2,3,4,5,6,7,8|} ${2|ON,OFF|} ${3|start|}");
  CHECK(complete(8, 3) == Json::array());  // in POINTS
  const Json io = complete(1, 15);  // "OUTSIG " then the cursor before "1"
  CHECK(io.is_array());
}

TEST_CASE("lsp: signature help names each motor", "[lsp][features]") {
  Opened o("        MOVE 1 2 \n        OUTSIG 1 \n");
  const Json move = o.s.result("textDocument/signatureHelp", LspSession::at(kUri, 0, 17));
  CHECK(move["activeParameter"] == 2);
  CHECK(move["signatures"][0]["label"] == "MOVE E D C B A");
  CHECK(move["signatures"][0]["parameters"][0] ==
        Json({{"label", {5, 6}}, {"documentation", "motor E (revolute): by encoder units, range -1000..1000, 400 units/s"}}));
  CHECK(move["signatures"][0]["parameters"][2]["label"] == Json({9, 10}));
  const Json out = o.s.result("textDocument/signatureHelp", LspSession::at(kUri, 1, 17));
  CHECK(out["signatures"][0]["label"] == "OUTSIG <output> ON|OFF");
  CHECK(out["signatures"][0]["parameters"][0]["label"] == Json({7, 15}));
  CHECK(out["signatures"][0]["parameters"][1]["label"] == Json({16, 22}));
  CHECK(out["activeParameter"] == 1);
}

TEST_CASE("lsp: inlay hints: instruction numbers and when each ends in the default run", "[lsp][features]") {
  Opened o;
  const Json hints = o.s.result("textDocument/inlayHint", {{"textDocument", {{"uri", kUri}}}, {"range", range(0, 0, 12, 0)}});
  const auto number = [](unsigned l, int n) {
    return Json({{"position", {{"line", l}, {"character", 8}}}, {"label", "#" + std::to_string(n)}, {"paddingRight", true}});
  };
  const auto ends = [](unsigned l, unsigned c, const std::string& label) {
    return Json({{"position", {{"line", l}, {"character", c}}}, {"label", label}, {"paddingLeft", true}});
  };
  CHECK(hints == Json({number(1, 1), ends(1, 15, "ends 0 s"), number(2, 2), ends(2, 24, "ends 0.25 s (first of 3)"),
                       number(3, 3), ends(3, 15, "ends 0.25 s (first of 3)"), number(4, 4),
                       ends(4, 25, "ends 0.25 s (first of 3)"), number(5, 5), ends(5, 17, "ends 0.75 s"), number(6, 6),
                       ends(6, 11, "ends 1.5 s"), number(8, 7), ends(8, 18, "ends 1.5 s"), number(9, 8),
                       ends(9, 14, "ends 1.5 s")}));
}

TEST_CASE("lsp: inlay hints of a program that never ends come back (the run stops where check's does)", "[lsp][features]") {
  Opened o("loop:   ADD N 1\n        GOTO loop\n");
  const Json hints = o.s.result("textDocument/inlayHint", {{"textDocument", {{"uri", kUri}}}, {"range", range(0, 0, 2, 0)}});
  REQUIRE(hints.size() == 4);
  // 10,000,000 instructions without the clock moving: the ADD that would
  // be the next stops the run, after 5,000,000 of each.
  CHECK(hints[1]["label"] == "stops 0 s (clock standing still)");
  CHECK(hints[3]["label"] == "ends 0 s (first of 5000000)");
}

TEST_CASE("lsp: semantic tokens", "[lsp][features]") {
  Opened o("loop: MOVE 1 2 3 4 5 ; c\n        GOTO loop\n");
  const Json t = o.s.result("textDocument/semanticTokens/full", {{"textDocument", {{"uri", kUri}}}});
  CHECK(t["data"] == Json({0, 0, 4, 1, 1,  0, 6, 4, 0, 0,  0, 5, 1, 4, 0,  0, 2, 1, 4, 0,  0, 2, 1, 4, 0,  0, 2, 1, 4, 0,
                           0, 2, 1, 4, 0,  0, 2, 3, 6, 0,  1, 8, 4, 0, 0,  0, 5, 4, 1, 0}));
}

TEST_CASE("lsp: code actions: did you mean, add a point", "[lsp][features]") {
  const std::string text =
      "        MOVX 1 0 0 0 0\n"
      "        GOTO lop\n"
      "lop1:   MOVEP PIK\n"
      "        END\n"
      "POINTS\n"
      "PICK 0 0 0 0 0\n";
  Opened o(text);
  const Json diags = o.s.diagnostics(kUri);
  REQUIRE(diags.size() == 3);
  const Json actions = o.s.result("textDocument/codeAction", {{"textDocument", {{"uri", kUri}}}, {"range", range(0, 0, 6, 0)},
                                                              {"context", {{"diagnostics", diags}}}});
  REQUIRE(actions.size() == 4);
  const auto edit = [](const Json& a) { return a["edit"]["changes"][kUri]; };
  CHECK(actions[0]["title"] == "Change 'MOVX' to 'MOVE'");
  CHECK(edit(actions[0]) == Json({{{"range", range(0, 8, 0, 12)}, {"newText", "MOVE"}}}));
  CHECK(actions[1]["title"] == "Change 'lop' to 'lop1'");
  CHECK(edit(actions[1]) == Json({{{"range", range(1, 13, 1, 16)}, {"newText", "lop1"}}}));
  CHECK(actions[2]["title"] == "Change 'PIK' to 'PICK'");
  CHECK(actions[3]["title"] == "Add point 'PIK' to POINTS");
  CHECK(edit(actions[3]) == Json({{{"range", range(6, 0, 6, 0)}, {"newText", "PIK 0 0 0 0 0\n"}}}));
  CHECK(actions[0]["kind"] == "quickfix");
  CHECK(actions[0]["diagnostics"][0] == diags[0]);
}

TEST_CASE("lsp: code actions: END before a subroutine the main program falls into", "[lsp][features]") {
  Opened o("        GOSUB sub\nsub:    MOVE 1 0 0 0 0\n        RETURN\n");
  Json diags = o.s.diagnostics(kUri);
  REQUIRE(diags.size() == 2);
  // The run says it too, as check does: the second RETURN has no GOSUB.
  CHECK(diags[1]["message"] == "runtime error: RETURN without a GOSUB (instruction 3)\nhint: did the program run "
                               "on into a subroutine? an END before the subroutine stops it there");
  diags.erase(1);
  CHECK(diags[0]["code"] == "falls-into-subroutine");
  CHECK(diags[0]["range"] == range(1, 0, 1, 4));
  const Json actions = o.s.result("textDocument/codeAction", {{"textDocument", {{"uri", kUri}}}, {"range", range(1, 0, 1, 4)},
                                                              {"context", {{"diagnostics", diags}}}});
  REQUIRE(actions.size() == 1);
  CHECK(actions[0]["title"] == "Add END before the subroutine");
  CHECK(actions[0]["edit"]["changes"][kUri] == Json({{{"range", range(1, 0, 1, 0)}, {"newText", "        END\n"}}}));
}

TEST_CASE("lsp: code actions: remove unreachable code", "[lsp][features]") {
  Opened o("        END\n        SET N 1\n        ADD N 2\n; c\n");
  const Json diags = o.s.diagnostics(kUri);
  REQUIRE(diags.size() == 1);
  CHECK(diags[0]["code"] == "unreachable-code");
  CHECK(diags[0]["range"] == range(1, 8, 1, 11));
  const Json actions = o.s.result("textDocument/codeAction", {{"textDocument", {{"uri", kUri}}}, {"range", range(1, 8, 1, 11)},
                                                              {"context", {{"diagnostics", diags}}}});
  REQUIRE(actions.size() == 1);
  CHECK(actions[0]["title"] == "Remove the unreachable instructions");
  CHECK(actions[0]["edit"]["changes"][kUri] == Json({{{"range", range(1, 0, 3, 0)}, {"newText", ""}}}));
}

TEST_CASE("lsp: positions count UTF-16 code units, or bytes when the client negotiates UTF-8", "[lsp][features]") {
  // "é" is 1 UTF-16 unit and 2 bytes; "😀" 2 units and 4 bytes: GOTO starts at 12 (UTF-16) or 15 (UTF-8).
  const std::string text = "        \xC3\xA9\xF0\x9F\x98\x80 GOTO x\nx:      END\n";
  Opened utf16(text);
  const Json d16 = utf16.s.diagnostics(kUri);
  REQUIRE(d16.size() == 2);
  CHECK(d16[0]["range"]["start"]["character"] == 8);
  CHECK(d16[1]["range"]["start"]["character"] == 9);
  CHECK(utf16.s.result("textDocument/hover", LspSession::at(kUri, 0, 13))["range"] == range(0, 12, 0, 16));
  Opened utf8(text, {{"general", {{"positionEncodings", {"utf-8", "utf-16"}}}}});
  const Json d8 = utf8.s.diagnostics(kUri);
  REQUIRE(d8.size() == 2);
  CHECK(d8[1]["range"]["start"]["character"] == 10);
  CHECK(utf8.s.result("textDocument/hover", LspSession::at(kUri, 0, 16))["range"] == range(0, 15, 0, 19));
  CHECK(utf8.s.result("textDocument/definition", LspSession::at(kUri, 0, 20)) == loc(1, 0, 1, 1));
}
