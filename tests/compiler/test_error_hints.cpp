// Mistakes a student makes with the shape of a line, each with a message
// that names the mistake and a hint that shows the fix: point rows without
// their POINTS line, two-sign comparisons in JMPVAR (the grammar's CMP is
// one of <, > or =), a unit after DELAY's number. Expected texts and
// columns worked out by hand.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "diag/diagnostic.h"
#include "stdlib/default_robot.h"

namespace {

using rs::diag::Diagnostic;

rs::compiler::CompileResult compileForHints(const std::string& text) {
  const rs::diag::SourceFile source("t.rsp", text);
  return rs::compiler::compile(source, {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth});
}

// "line:col: message | hint" per diagnostic, in order.
std::vector<std::string> hintsDescribed(const std::vector<Diagnostic>& diags) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diags)
    out.push_back(std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": " + d.message + " | " + d.hint);
  return out;
}

std::vector<std::string> describedErrors(const std::string& text) {
  const auto r = compileForHints(text);
  CHECK_FALSE(r.ok());
  return hintsDescribed(r.diagnostics);
}

}  // namespace

TEST_CASE("hints: point rows after END without a POINTS line", "[compiler][hints]") {
  const std::string text =
      "MOVEP HOME\n"       // 1
      "MOVEP P1\n"         // 2
      "END\n"              // 3
      "\n"                 // 4
      "HOME 0 0 0 0 0\n"   // 5: reported once; this row and the next are read as points
      "P1 10 0 0 0 0\n";   // 6
  // One error: MOVEP HOME and MOVEP P1 find their points.
  CHECK(describedErrors(text) ==
        std::vector<std::string>{"5:1: 'HOME' is not an instruction: it looks like a taught point, but no POINTS "
                                 "line comes before it | points follow a line POINTS after the instructions: add "
                                 "POINTS on a line of its own after the END on line 3, before line 5"});
  // With the POINTS line the same file compiles, and the points hold the rows' values.
  const auto fixed = compileForHints("MOVEP HOME\nMOVEP P1\nEND\nPOINTS\nHOME 0 0 0 0 0\nP1 10 0 0 0 0\n");
  REQUIRE(fixed.ok());
  REQUIRE(fixed.image->points.size() == 2);
  CHECK(fixed.image->points[1].values == std::vector<std::int32_t>{10, 0, 0, 0, 0});
}

TEST_CASE("hints: not a point row", "[compiler][hints]") {
  // Before any END a word with numbers is an unknown instruction, and so is
  // a one-letter slip of a mnemonic after END.
  CHECK(describedErrors("HOME 0 0 0 0 0\nEND\n") ==
        std::vector<std::string>{"1:1: unknown instruction 'HOME' (did you mean MOVE?) | "});
  CHECK(describedErrors("END\nMOVX 1 2 3 4 5\n") ==
        std::vector<std::string>{"2:1: unknown instruction 'MOVX' (did you mean MOVE?) | "});
}

TEST_CASE("hints: JMPVAR with a comparison of two signs", "[compiler][hints]") {
  const std::string text =
      "SET N 0\n"               // 1
      "loop: ADD N 1\n"         // 2
      "JMPVAR N <= 3 loop\n"    // 3
      "JMPVAR N >= -2 loop\n"   // 4
      "JMPVAR N == 3 loop\n"    // 5
      "JMPVAR N <> 3 loop\n"    // 6
      "JMPVAR N => 7 loop\n"    // 7
      "JMPVAR N < = 3 loop\n"   // 8: signs apart: five operands
      "END\n";
  CHECK(describedErrors(text) ==
        std::vector<std::string>{
            "3:10: '<=' is not a comparison: JMPVAR compares with <, > or = (one sign) | values are whole numbers: "
            "N <= 3 is JMPVAR N < 4 loop",
            "4:10: '>=' is not a comparison: JMPVAR compares with <, > or = (one sign) | values are whole numbers: "
            "N >= -2 is JMPVAR N > -3 loop",
            "5:10: '==' is not a comparison: JMPVAR compares with <, > or = (one sign) | equality is one '=': "
            "JMPVAR N = 3 loop",
            "6:10: '<>' is not a comparison: JMPVAR compares with <, > or = (one sign) | there is no not-equal: "
            "jump with = past the instructions for the other case",
            "7:10: '=>' is not a comparison: JMPVAR compares with <, > or = (one sign) | values are whole numbers: "
            "N >= 7 is JMPVAR N > 6 loop",
            "8:16: JMPVAR expects 4 operands (JMPVAR <variable> <|>|= <value> <line>), found 5 | "});
  CHECK(describedErrors("SET N 1\nJMPVAR N != 3 1\nEND\n") ==
        std::vector<std::string>{"2:10: unexpected character '!' | JMPVAR compares with <, > or =; there is no "
                                 "not-equal: jump with = past the instructions for the other case"});
}

TEST_CASE("hints: DELAY with a unit", "[compiler][hints]") {
  const std::string text =
      "DELAY 1.5s\n"        // 1
      "DELAY 2 seconds\n"   // 2
      "DELAY 1500ms\n"      // 3
      "DELAY 250 ms\n"      // 4
      "DELAY 3000ms\n"      // 5
      "DELAY 2 minutes\n"   // 6: not a unit it knows: the operand count
      "END\n";
  CHECK(describedErrors(text) ==
        std::vector<std::string>{
            "1:10: 's' after DELAY's number: DELAY takes seconds as a bare number, without a unit | write DELAY 1.5",
            "2:9: 'seconds' after DELAY's number: DELAY takes seconds as a bare number, without a unit | write DELAY 2",
            "3:11: 'ms' after DELAY's number: DELAY takes seconds as a bare number, without a unit | write DELAY 1.5 "
            "(seconds)",
            "4:11: 'ms' after DELAY's number: DELAY takes seconds as a bare number, without a unit | write DELAY "
            "0.25 (seconds)",
            "5:11: 'ms' after DELAY's number: DELAY takes seconds as a bare number, without a unit | write DELAY 3 "
            "(seconds)",
            "6:9: DELAY expects 1 operand (DELAY <seconds>), found 2 | "});
}
