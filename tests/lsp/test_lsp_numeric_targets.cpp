// Jumps by instruction number (issue 26): `GOTO 3` silently lands elsewhere
// once an instruction is added above it. The server warns at each one, and
// its quick fix gives the target a label and jumps to the label, after
// which adding a line above moves the label with its instruction.
#include <catch2/catch.hpp>

#include <algorithm>

#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "tests/lsp/lsp_session.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

const std::string kJumpsUri = "file:///jumps.rsp";

// Instruction numbers on the right.
const std::string kNumberedJumps =
    "        SET I 0\n"            // 0   1
    "        MOVE 10 0 0 0 0\n"    // 1   2   <- JMPVAR ... 2
    "  ADD I 1\n"                  // 2   3   <- GOTO 3 (two blanks: no room for a label)
    "        JMPVAR I < 5 2\n"     // 3   4
    "\tGOSUB 7\n"                  // 4   5
    "        END\n"                // 5   6
    "sub:    RETURN\n"             // 6   7   <- GOSUB 7: already labelled
    "L3:     GOTO 3\n";            // 7   8   (L3 is taken: the new label is L3_2)

// The text with LSP edits made (ASCII: characters are bytes).
std::string applied(std::string text, Json edits) {
  const auto offset = [&](const Json& p) {
    std::size_t at = 0;
    for (int l = 0; l < p["line"].get<int>(); ++l) at = text.find('\n', at) + 1;
    return at + p["character"].get<std::size_t>();
  };
  std::vector<Json> list(edits.begin(), edits.end());
  std::sort(list.begin(), list.end(), [&](const Json& a, const Json& b) {
    return offset(a["range"]["start"]) > offset(b["range"]["start"]);
  });
  for (const Json& e : list) {
    const std::size_t from = offset(e["range"]["start"]), to = offset(e["range"]["end"]);
    text.replace(from, to - from, e["newText"].get<std::string>());
  }
  return text;
}

rs::vm::Image imageOf(const std::string& text) {
  const rs::diag::SourceFile source("jumps.rsp", text);
  rs::compiler::CompileResult r = rs::compiler::compile(source, rs::launch::defaultTarget());
  INFO(text);
  REQUIRE(r.image);
  return *r.image;
}

Json numericWarnings(const Json& diagnostics) {
  Json out = Json::array();
  for (const Json& d : diagnostics)
    if (d.value("code", "") == "numeric-target") out.push_back(d);
  return out;
}

}  // namespace

TEST_CASE("lsp: a jump by instruction number is warned about where the number is", "[lsp][jumps]") {
  LspSession s;
  s.initialize();
  s.open(kJumpsUri, kNumberedJumps);
  s.idle();
  const Json warnings = numericWarnings(s.diagnostics(kJumpsUri));
  REQUIRE(warnings.size() == 3);
  CHECK(warnings[0]["range"] == LspSession::range(3, 21, 3, 22));
  CHECK(warnings[0]["severity"] == 2);
  CHECK(warnings[0]["message"] ==
        "a jump to instruction 2 by its number: an instruction added or removed before it makes the jump land "
        "elsewhere\nhint: give instruction 2 a label and jump to the label (quick fix)");
  CHECK(warnings[1]["range"] == LspSession::range(4, 7, 4, 8));
  CHECK(warnings[2]["range"] == LspSession::range(7, 13, 7, 14));
  // Jumps by label are not.
  s.open("file:///labels.rsp", "loop:   MOVE 1 0 0 0 0\n        GOTO loop\n");
  s.idle();
  CHECK(numericWarnings(s.diagnostics("file:///labels.rsp")).empty());
}

TEST_CASE("lsp: the quick fix jumps to a label, and the program means what it meant", "[lsp][jumps]") {
  LspSession s;
  s.initialize();
  s.open(kJumpsUri, kNumberedJumps);
  s.idle();
  const Json warnings = numericWarnings(s.diagnostics(kJumpsUri));
  REQUIRE(warnings.size() == 3);
  const Json actions = s.result("textDocument/codeAction", {{"textDocument", {{"uri", kJumpsUri}}},
                                                            {"range", warnings[0]["range"]},
                                                            {"context", {{"diagnostics", {warnings[0]}}}}});
  REQUIRE(actions.size() == 2);
  CHECK(actions[0]["title"] == "Jump to a label instead of instruction 2");
  CHECK(actions[0]["isPreferred"] == true);
  // The MOVE gets "L2:" in its blanks (the layout stays), the jump its name.
  CHECK(actions[0]["edit"]["changes"][kJumpsUri] ==
        Json::parse(R"([{"range":{"start":{"line":1,"character":0},"end":{"line":1,"character":8}},"newText":"L2:     "},
                        {"range":{"start":{"line":3,"character":21},"end":{"line":3,"character":22}},"newText":"L2"}])"));
  CHECK(actions[1]["title"] == "Jump to labels instead of instruction numbers (3 jumps)");
  const std::string fixed = applied(kNumberedJumps, actions[1]["edit"]["changes"][kJumpsUri]);
  CHECK(fixed ==
        "        SET I 0\n"
        "L2:     MOVE 10 0 0 0 0\n"
        "L3_2:   ADD I 1\n"
        "        JMPVAR I < 5 L2\n"
        "\tGOSUB sub\n"
        "        END\n"
        "sub:    RETURN\n"
        "L3:     GOTO L3_2\n");
  // The same instructions, jumps and all: labels do not count.
  CHECK(imageOf(fixed).code == imageOf(kNumberedJumps).code);
  s.notify("textDocument/didChange", {{"textDocument", {{"uri", kJumpsUri}, {"version", 2}}}, {"contentChanges", {{{"text", fixed}}}}});
  s.idle();
  CHECK(numericWarnings(s.diagnostics(kJumpsUri)).empty());
  // What the warning was about: an instruction added at the top. The
  // labels still name their instructions; the numbers now name others.
  const rs::vm::Image labelled = imageOf("        DELAY 1\n" + fixed);
  // The jumps' targets (operand d, a 0-based index): JMPVAR is now at
  // index 4, GOSUB at 5.
  CHECK(labelled.code[4].d == 2);  // the MOVE, now at index 2
  CHECK(labelled.code[5].d == 7);  // GOSUB sub: RETURN, now at index 7
  // By number, GOSUB 7 now calls END, and JMPVAR ... 2 jumps to the SET:
  // here the compiler happens to notice (the RETURN is left unreachable).
  const rs::diag::SourceFile numbered("jumps.rsp", "        DELAY 1\n" + kNumberedJumps);
  const rs::compiler::CompileResult r = rs::compiler::compile(numbered, rs::launch::defaultTarget());
  CHECK_FALSE(r.image);
  REQUIRE(!r.diagnostics.empty());
  CHECK(r.diagnostics[0].message == "RETURN that no GOSUB can reach");
}
