// Compile errors and warnings: every bad program below asserts the exact
// list of diagnostics (severity, line, column, message, in the order the
// compiler reports them), and whether the compile succeeds. Columns were
// counted by hand: 1-based, one per character, a tab counts as one.
//
// The default target is the paper's Rhino SCARA: motors E D C B A with the
// ranges E -1000..1000, D -550..550, C -350..350, B -700..700, A 0..120.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "diag/diagnostic.h"
#include "stdlib/default_robot.h"

namespace {

using rs::compiler::CompileResult;
using rs::diag::Diagnostic;
using rs::diag::Severity;
using rs::diag::SourceFile;
using rs::compiler::Target;

Target rhino() { return {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth}; }

// Two motors, X and Y, for arity messages that name a smaller table.
Target twoMotors() {
  return {"two",
          {{'X', rs::vm::JointKind::Revolute, 1.0, -10, 10, 10}, {'Y', rs::vm::JointKind::Prismatic, 1.0, 0, 5, 3}},
          rs::vm::kDefaultCallDepth};
}

struct Want {
  Severity severity;
  std::uint32_t line;
  std::uint32_t col;
  std::string message;
};

Want err(std::uint32_t line, std::uint32_t col, std::string message) { return {Severity::Error, line, col, std::move(message)}; }
Want warn(std::uint32_t line, std::uint32_t col, std::string message) {
  return {Severity::Warning, line, col, std::move(message)};
}

std::string severityText(Severity s) { return std::string(rs::diag::severityName(s)); }

// One line per diagnostic, "line:col: severity: message": comparing the
// whole list as text checks count, order and every field at once, and a
// failure shows both lists side by side. Diagnostics must come sorted by
// position (checked separately); the order of several at the SAME position
// is not specified, so lines are compared in (line, col, text) order.
struct Key {
  std::uint32_t line;
  std::uint32_t col;
  std::string text;
  bool operator<(const Key& o) const {
    return line != o.line ? line < o.line : col != o.col ? col < o.col : text < o.text;
  }
};

std::string describe(std::vector<Key> keys) {
  std::stable_sort(keys.begin(), keys.end());
  std::string out;
  for (const Key& k : keys) out += std::to_string(k.line) + ':' + std::to_string(k.col) + ": " + k.text + '\n';
  return out;
}

std::string describe(const std::vector<Diagnostic>& diags) {
  std::vector<Key> keys;
  for (const Diagnostic& d : diags) keys.push_back({d.pos.line, d.pos.col, severityText(d.severity) + ": " + d.message});
  return describe(keys);
}

std::string describe(const std::vector<Want>& wants) {
  std::vector<Key> keys;
  for (const Want& w : wants) keys.push_back({w.line, w.col, severityText(w.severity) + ": " + w.message});
  return describe(keys);
}

bool sortedByPosition(const std::vector<Diagnostic>& diags) {
  return std::is_sorted(diags.begin(), diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.col < b.pos.col;
  });
}

CompileResult compileText(const std::string& text, const Target& target = rhino()) {
  const SourceFile source("t.rsp", text);
  return rs::compiler::compile(source, target);
}

// Compiles `text` and requires exactly the diagnostics `wants`; the compile
// must fail if and only if one of them is an error.
void expectDiagnostics(const std::string& text, const std::vector<Want>& wants, const Target& target = rhino()) {
  INFO("program:\n" << text);
  const CompileResult r = compileText(text, target);
  CHECK(describe(r.diagnostics) == describe(wants));
  CHECK(sortedByPosition(r.diagnostics));
  bool anyError = false;
  for (const Want& w : wants) anyError = anyError || w.severity == Severity::Error;
  CHECK(r.ok() == !anyError);
  for (const Diagnostic& d : r.diagnostics) CHECK(d.file == "t.rsp");
}

}  // namespace

TEST_CASE("a correct program compiles without diagnostics", "[compiler]") {
  const CompileResult r = compileText("SET N -2147483648\nMOVETO -1000 550 -350 700 120\nDELAY +2\nEND\n");
  CHECK(r.diagnostics.empty());
  REQUIRE(r.ok());
  CHECK(r.image->code.size() == 4);
}

TEST_CASE("unknown instructions, with and without a suggestion", "[compiler]") {
  expectDiagnostics("MOVX 1 2 3 4 5\nEND\n", {err(1, 1, "unknown instruction 'MOVX' (did you mean MOVE?)")});
  expectDiagnostics("movto 1 2 3 4 5\nEND\n", {err(1, 1, "unknown instruction 'movto' (did you mean MOVETO?)")});
  expectDiagnostics("END\n  FROBNICATE\n", {err(2, 3, "unknown instruction 'FROBNICATE'")});
}

TEST_CASE("wrong operand counts", "[compiler]") {
  // Too few operands: reported at the mnemonic.
  expectDiagnostics("GOTO\n", {err(1, 1, "GOTO expects 1 operand (GOTO <line>), found 0")});
  expectDiagnostics("OUTSIG 1\nEND\n", {err(1, 1, "OUTSIG expects 2 operands (OUTSIG <output> ON|OFF), found 1")});
  expectDiagnostics("SET N 1\nJMPVAR N < 1\nEND\n",
                    {err(2, 1, "JMPVAR expects 4 operands (JMPVAR <variable> <|>|= <value> <line>), found 3")});
  expectDiagnostics("WINDOW 1 2\nEND\n", {err(1, 1, "WINDOW expects 3 operands (WINDOW <x> <y> <z>), found 2")});
  // Too many: reported at the first operand too many.
  expectDiagnostics("GOTO 1 2\n", {err(1, 8, "GOTO expects 1 operand (GOTO <line>), found 2")});
  expectDiagnostics("OUTSIG 1 ON\tOFF\nEND\n",
                    {err(1, 13, "OUTSIG expects 2 operands (OUTSIG <output> ON|OFF), found 3")});
  expectDiagnostics("END 5\n", {err(1, 5, "END takes no operands, found 1")});
}

TEST_CASE("wrong operand types", "[compiler]") {
  expectDiagnostics("SET 5 5\nEND\n", {err(1, 5, "expected a variable name, found '5'")});
  expectDiagnostics("SET N X\nEND\n", {err(1, 7, "expected a value, found 'X'")});
  expectDiagnostics("MOVEP 5\nEND\n", {err(1, 7, "expected a point name, found '5'")});
  expectDiagnostics("VIEW 1 2 x\nEND\n", {err(1, 10, "expected a number, found 'x'")});
  expectDiagnostics("DELAY x\nEND\n", {err(1, 7, "expected a number of seconds, found 'x'")});
  // ON / OFF
  expectDiagnostics("OUTSIG 1 MAYBE\nEND\n", {err(1, 10, "expected ON or OFF, found 'MAYBE'")});
  expectDiagnostics("JMPIN 1 YES 2\nEND\n", {err(1, 9, "expected ON or OFF, found 'YES'")});
  // Comparison
  expectDiagnostics("SET N 1\nJMPVAR N 5 3 1\nEND\n", {err(2, 10, "expected a comparison <, > or =, found '5'")});
  // Several bad operands on one line are all reported.
  expectDiagnostics("SET N 1\nJMPVAR 5 ! x 2.5\nEND\n",
                    {err(2, 1, "JMPVAR expects 4 operands (JMPVAR <variable> <|>|= <value> <line>), found 3"),
                     err(2, 10, "unexpected character '!'")});
  expectDiagnostics("SET N 1\nJMPVAR 5 < x 2.5\nEND\n",
                    {err(2, 8, "expected a variable name, found '5'"), err(2, 12, "expected a value, found 'x'"),
                     err(2, 14, "expected a line number or label (a whole number), found '2.5'")});
}

// Regression (a bug these tests found, fixed since): an input/output operand that is not a whole number is
// reported twice: once as what it is, then again as "input 0 is outside
// 1..8" at the same position (the failed operand is checked as if it were
// 0). The same happens to a bad MOVETO value when 0 is outside the motor's
// range.
TEST_CASE("a malformed operand is reported once", "[compiler]") {
  expectDiagnostics("OUTSIG x ON\nEND\n", {err(1, 8, "expected an output number, found 'x'")});
  expectDiagnostics("WAITFOR 1.5 ON\nEND\n", {err(1, 9, "expected an input number (a whole number), found '1.5'")});
  expectDiagnostics("JMPIN x MAYBE 2\nEND\n",
                    {err(1, 7, "expected an input number, found 'x'"), err(1, 9, "expected ON or OFF, found 'MAYBE'")});
  const Target offset{"offset", {{'Z', rs::vm::JointKind::Prismatic, 1.0, 5, 10, 10}}, rs::vm::kDefaultCallDepth};
  expectDiagnostics("MOVETO x\nEND\n", {err(1, 8, "expected an encoder value, found 'x'")}, offset);
}

TEST_CASE("whole numbers and 32-bit range", "[compiler]") {
  expectDiagnostics("SET N 1.5\nEND\n", {err(1, 7, "expected a value (a whole number), found '1.5'")});
  expectDiagnostics("SET N 1\nJMPVAR N = 1 2.5\nEND\n",
                    {err(2, 14, "expected a line number or label (a whole number), found '2.5'")});
  expectDiagnostics("END\nPOINTS\nP1 0 0 1.5 0 0\n",
                    {err(3, 8, "expected an encoder value (a whole number), found '1.5'")});
  expectDiagnostics("SET N 2147483648\nEND\n",
                    {err(1, 7, "'2147483648' does not fit in a 32-bit integer (-2147483648..2147483647)")});
  expectDiagnostics("SET N -2147483649\nEND\n",
                    {err(1, 7, "'-2147483649' does not fit in a 32-bit integer (-2147483648..2147483647)")});
  expectDiagnostics("ADD N 99999999999999999999999\nEND\n",
                    {err(1, 7, "'99999999999999999999999' does not fit in a 32-bit integer (-2147483648..2147483647)")});
  // The limits themselves are fine.
  expectDiagnostics("SET N -2147483648\nADD N +2147483647\nEND\n", {});
}

TEST_CASE("jump targets: missing line numbers, line 0, labels", "[compiler]") {
  expectDiagnostics("GOTO 5\nEND\n", {err(1, 6, "line number 5 does not exist (the program has 2 instructions)")});
  expectDiagnostics("GOTO 9\n", {err(1, 6, "line number 9 does not exist (the program has 1 instruction)")});
  expectDiagnostics("GOTO 0\nEND\n", {err(1, 6, "line numbers start at 1, found 0")});
  expectDiagnostics("JMPIN 1 ON 0\nEND\n", {err(1, 12, "line numbers start at 1, found 0")});
  expectDiagnostics("GOTO -3\nEND\n", {err(1, 6, "line numbers start at 1, found -3")});
  expectDiagnostics("GOTO nowhere\nEND\n", {err(1, 6, "undefined label 'nowhere'")});
  expectDiagnostics("SET N 1\nGOSUB sub\nEND\n", {err(2, 7, "undefined label 'sub'")});
  // Blank and comment lines do not count as instructions.
  expectDiagnostics("; header\n\nGOTO 3\n\nEND\n",
                    {err(3, 6, "line number 3 does not exist (the program has 2 instructions)")});
}

TEST_CASE("duplicate labels and points, undefined points", "[compiler]") {
  expectDiagnostics("a: SET N 1\na: END\n", {err(2, 1, "label 'a' is already defined on line 1")});
  // Names are case-insensitive.
  expectDiagnostics("Loop: SET N 1\n  LOOP: END\n", {err(2, 3, "label 'LOOP' is already defined on line 1")});
  expectDiagnostics("MOVEP P1\nEND\nPOINTS\nP1 0 0 0 0 0\np1 1 1 1 1 1\n",
                    {err(5, 1, "point 'p1' is already defined on line 4")});
  expectDiagnostics("MOVEP P2\nEND\nPOINTS\nP1 0 0 0 0 0\n", {err(1, 7, "undefined point 'P2'")});
  expectDiagnostics("MOVEP P1\nEND\n", {err(1, 7, "undefined point 'P1'")});
}

TEST_CASE("inputs and outputs outside 1..8", "[compiler]") {
  expectDiagnostics("OUTSIG 9 ON\nEND\n", {err(1, 8, "output 9 is outside 1..8")});
  expectDiagnostics("OUTSIG 0 OFF\nEND\n", {err(1, 8, "output 0 is outside 1..8")});
  expectDiagnostics("JMPIN 9 ON 1\nEND\n", {err(1, 7, "input 9 is outside 1..8")});
  expectDiagnostics("WAITFOR 0 ON\nEND\n", {err(1, 9, "input 0 is outside 1..8")});
  expectDiagnostics("WAITFOR -1 OFF\nEND\n", {err(1, 9, "input -1 is outside 1..8")});
  // 1 and 8 are fine.
  expectDiagnostics("OUTSIG 1 ON\nOUTSIG 8 OFF\nJMPIN 8 ON 4\nWAITFOR 1 OFF\nEND\n", {});
}

TEST_CASE("RETURN without a GOSUB", "[compiler]") {
  expectDiagnostics("RETURN\n", {err(1, 1, "RETURN without any GOSUB in the program")});
  expectDiagnostics("SET N 1\nEND\nRETURN\n",
                    {warn(3, 1, "unreachable code: nothing jumps here and END on line 2 does not continue"),
                     err(3, 1, "RETURN without any GOSUB in the program")});
  // GOSUB 3 lands on END: the RETURN on line 4 is reachable from no GOSUB.
  expectDiagnostics("GOSUB 3\nEND\nEND\nRETURN\n",
                    {warn(4, 1, "unreachable code: nothing jumps here and END on line 3 does not continue"),
                     err(4, 1, "RETURN that no GOSUB can reach")});
  // A RETURN inside a subroutine is fine.
  expectDiagnostics("GOSUB sub\nEND\nsub: RETURN\n", {});
}

TEST_CASE("unreachable code is a warning, not an error", "[compiler]") {
  expectDiagnostics("END\nSET N 1\n", {warn(2, 1, "unreachable code: nothing jumps here and END on line 1 does not continue")});
  expectDiagnostics("GOTO 3\n  SET N 1\nEND\n",
                    {warn(2, 3, "unreachable code: nothing jumps here and GOTO on line 1 does not continue")});
  // Only the first instruction of an unreachable run is reported.
  expectDiagnostics("END\nSET N 1\nSET N 2\n",
                    {warn(2, 1, "unreachable code: nothing jumps here and END on line 1 does not continue")});
  // A jump target after END is reachable.
  expectDiagnostics("GOTO 3\nEND\nEND\n",
                    {warn(2, 1, "unreachable code: nothing jumps here and GOTO on line 1 does not continue")});
}

TEST_CASE("motor vectors and points must have one value per motor", "[compiler]") {
  expectDiagnostics("MOVE 1 2 3\nEND\n", {err(1, 1, "MOVE expects 5 values (one per motor: E D C B A), found 3")});
  expectDiagnostics("MOVETO 1 2 3 4 5 6\nEND\n",
                    {err(1, 1, "MOVETO expects 5 values (one per motor: E D C B A), found 6")});
  expectDiagnostics("SETSOFT 1\nEND\n", {err(1, 1, "SETSOFT expects 5 values (one per motor: E D C B A), found 1")});
  expectDiagnostics("MOVEP P1\nEND\nPOINTS\nP1 0 0 0\n",
                    {err(4, 1, "point P1 has 3 values, expected 5 (one per motor: E D C B A)")});
  expectDiagnostics("END\nPOINTS\nP1 0 0 x 0 0\n", {err(3, 8, "expected an encoder value, found 'x'")});
  // With another motor table the count and the letters follow it.
  expectDiagnostics("MOVE 1 2 3\nEND\n", {err(1, 1, "MOVE expects 2 values (one per motor: X Y), found 3")}, twoMotors());
  expectDiagnostics("MOVE 1 2\nEND\nPOINTS\nQ 1\n",
                    {err(4, 1, "point Q has 1 values, expected 2 (one per motor: X Y)")}, twoMotors());
}

TEST_CASE("constant targets outside a motor's encoder range", "[compiler]") {
  expectDiagnostics("MOVETO 1001 0 0 0 0\nEND\n",
                    {err(1, 8, "MOVETO target 1001 for motor E is outside its range -1000..1000")});
  expectDiagnostics("MOVETO 0 -551 0 0 0\nEND\n",
                    {err(1, 10, "MOVETO target -551 for motor D is outside its range -550..550")});
  expectDiagnostics("SETSOFT 0 0 0 0 121\nEND\n",
                    {err(1, 17, "SETSOFT target 121 for motor A is outside its range 0..120")});
  expectDiagnostics("MOVEP P1\nEND\nPOINTS\nP1 0 0 0 0 -1\n",
                    {err(4, 12, "point P1: value -1 for motor A is outside its range 0..120")});
  // Every bad value of one instruction is reported.
  expectDiagnostics("MOVETO 0 0 351 701 0\nEND\n",
                    {err(1, 12, "MOVETO target 351 for motor C is outside its range -350..350"),
                     err(1, 16, "MOVETO target 701 for motor B is outside its range -700..700")});
  // A relative MOVE larger than the whole span can never succeed; one
  // exactly as large as the span can (from one end to the other).
  expectDiagnostics("MOVE 2001 0 0 0 0\nEND\n",
                    {err(1, 6, "MOVE by 2001 can never keep motor E within its range -1000..1000")});
  expectDiagnostics("MOVE 0 0 0 0 -121\nEND\n",
                    {err(1, 14, "MOVE by -121 can never keep motor A within its range 0..120")});
  expectDiagnostics("MOVE 2000 1100 700 1400 120\nEND\n", {});
}

TEST_CASE("DELAY operands", "[compiler]") {
  expectDiagnostics("DELAY -1\nEND\n", {err(1, 7, "DELAY cannot be negative, found '-1'")});
  expectDiagnostics("DELAY 1.2345\nEND\n", {err(1, 7, "DELAY counts milliseconds: at most 3 decimals, found '1.2345'")});
  expectDiagnostics("DELAY 86401\nEND\n", {err(1, 7, "DELAY is at most 86400 seconds, found '86401'")});
  expectDiagnostics("DELAY 86400.001\nEND\n", {err(1, 7, "DELAY is at most 86400 seconds, found '86400.001'")});
  expectDiagnostics("DELAY 99999999999999999999999\nEND\n",
                    {err(1, 7, "DELAY is at most 86400 seconds, found '99999999999999999999999'")});
  expectDiagnostics("DELAY 86400\nDELAY 0.001\nDELAY +2\nEND\n", {});
}

TEST_CASE("labels: reserved words, dangling labels, two labels", "[compiler]") {
  expectDiagnostics("GOTO: END\n", {err(1, 1, "'GOTO' is a reserved word and cannot name a label")});
  expectDiagnostics("on: END\n", {err(1, 1, "'on' is a reserved word and cannot name a label")});
  expectDiagnostics("points: END\n", {err(1, 1, "'points' is a reserved word and cannot name a label")});
  expectDiagnostics("GOTO END\nEND\n", {err(1, 6, "'END' is a reserved word and cannot name a label")});
  expectDiagnostics("END\nx:\n", {err(2, 1, "label 'x' is not followed by an instruction")});
  // A label before POINTS is dangling too.
  expectDiagnostics("END\ndone:\nPOINTS\nP1 0 0 0 0 0\n", {err(2, 1, "label 'done' is not followed by an instruction")});
  expectDiagnostics("a:\nb: END\n", {err(2, 1, "label 'b' follows label 'a': an instruction can have only one label")});
  // A label on a line of its own names the next instruction.
  expectDiagnostics("GOTO done\ndone:\n\n  END\n", {});
}

TEST_CASE("the POINTS section", "[compiler]") {
  expectDiagnostics("END\nPOINTS\nP1 0 0 0 0 0\nPOINTS\n", {err(4, 1, "POINTS appears twice (the section began on line 2)")});
  expectDiagnostics("END\npoints\nMOVE 0 0 0 0 0\n",
                    {err(3, 1, "instruction MOVE after POINTS: instructions come before the POINTS line (line 2)")});
  expectDiagnostics("END\nPOINTS\nlbl: P1 0 0 0 0 0\n", {err(3, 1, "points cannot have labels: labels name instructions")});
  expectDiagnostics("MOVEP P1\nEND\nPOINTS\n  ; taught by hand\n\nP1 0 0 0 0 0\n", {});
}

TEST_CASE("lexical errors: stray characters and signs", "[compiler]") {
  expectDiagnostics("END @\n", {err(1, 5, "unexpected character '@'")});
  expectDiagnostics("SET N 1 $\nEND\n", {err(1, 9, "unexpected character '$'")});
  expectDiagnostics("MOVE 1 -x 2 3 4\nEND\n",
                    {err(1, 8, "a sign must be followed by digits, found '-'"), err(1, 9, "expected an encoder value, found 'x'")});
  // The stray sign is dropped, so the MOVE has only four values.
  expectDiagnostics("MOVE 1 + 2 3 4\nEND\n", {err(1, 1, "MOVE expects 5 values (one per motor: E D C B A), found 4"),
                                              err(1, 8, "a sign must be followed by digits, found '+'")});
  // A non-ASCII character counts as one column.
  expectDiagnostics("END \xC3\xA9 !\n", {err(1, 5, "unexpected character '\xC3\xA9'"), err(1, 7, "unexpected character '!'")});
}

// BUG (reported): docs/language.md says a lone CR is a blank, not a line
// end, so a comment runs on to the LF. The lexer ends the comment at the
// lone CR and compiles what follows it: here "END ; old\rGOTO 1" gives
// "END takes no operands, found 2".
TEST_CASE("a lone CR is refused where it is, in a comment or between words", "[compiler]") {
  // Old Mac line ends would otherwise run every line into the first one's
  // comment, or make one long line of words: neither is what the author meant.
  const std::string message = "a carriage return without a line feed (old Mac line ends?): lines end in LF or CR LF";
  expectDiagnostics("END ; old\rGOTO 1\n", {err(1, 10, message)});
  expectDiagnostics("SET N\r1\nEND\n", {err(1, 6, message)});
  expectDiagnostics("SET N 1\r\nEND ; \xC3\xA9t\xC3\xA9\r\r\n", {err(2, 10, message)});  // columns count characters
}

TEST_CASE("syntax errors: a line must start with a name", "[compiler]") {
  expectDiagnostics("END\n10 MOVE 0 0 0 0 0\n",
                    {err(2, 1, "unexpected '10': a line starts with an instruction, a label or a point name")});
  expectDiagnostics("END\n< END\n", {err(2, 1, "unexpected '<': a line starts with an instruction, a label or a point name")});
  // docs/language.md: a ':' that starts a line gets the first message, a
  // ':' after the first word of the instruction the second.
  expectDiagnostics("END\n: END\n", {err(2, 1, "unexpected ':': a line starts with an instruction, a label or a point name")});
  expectDiagnostics("END\nSET N : 3\n", {err(2, 7, "unexpected ':': a label is a name followed by ':' at the start of a line")});
  expectDiagnostics("END\nPOINTS\n5 0 0\n", {err(3, 1, "unexpected '5': a line starts with an instruction, a label or a point name")});
}

// Regression (a bug these tests found, fixed since): a syntax error on the FIRST line makes the parser drop the
// whole file. The compiler then reports "the program has no instructions"
// (false: line 3 is END) and misses the error on line 2.
TEST_CASE("a syntax error on the first line does not hide the rest of the file", "[compiler]") {
  expectDiagnostics("10 MOVE 0 0 0 0 0\nFOO\nEND\n",
                    {err(1, 1, "unexpected '10': a line starts with an instruction, a label or a point name"),
                     err(2, 1, "unknown instruction 'FOO' (did you mean GOTO?)")});
}

TEST_CASE("empty programs", "[compiler]") {
  expectDiagnostics("", {err(1, 1, "the program has no instructions")});
  expectDiagnostics("; only a comment\n\n   \n", {err(1, 1, "the program has no instructions")});
  expectDiagnostics("END\nPOINTS\n", {});
  expectDiagnostics("POINTS\nP1 0 0 0 0 0\n", {err(1, 1, "the program has no instructions")});
}

TEST_CASE("invalid UTF-8 is reported at the bad byte", "[compiler]") {
  expectDiagnostics("END\n\xFF\n", {err(2, 1, "invalid UTF-8 (byte 0xFF): programs are UTF-8 text")});
  // "END ; caf" is 9 characters, the é (2 bytes) is column 10, the blank 11.
  expectDiagnostics("END ; caf\xC3\xA9 \xE9\n", {err(1, 12, "invalid UTF-8 (byte 0xE9): programs are UTF-8 text")});
  // Overlong encoding of '/', a UTF-16 surrogate, a truncated sequence.
  expectDiagnostics("END ;\xC0\xAF\n", {err(1, 6, "invalid UTF-8 (byte 0xC0): programs are UTF-8 text")});
  expectDiagnostics("END\n;\xED\xA0\x80\n", {err(2, 2, "invalid UTF-8 (byte 0xED): programs are UTF-8 text")});
  expectDiagnostics("END ;\xE2\x82", {err(1, 6, "invalid UTF-8 (byte 0xE2): programs are UTF-8 text")});
}

TEST_CASE("a variable that is only read gets a warning", "[compiler]") {
  expectDiagnostics("JMPVAR M = 0 3\nEND\nEND\n", {warn(1, 8, "variable 'M' is never assigned by SET or ADD; it is always 0")});
  // Reported once, at the first read, whatever the spelling.
  expectDiagnostics("JMPVAR m > 0 4\nJMPVAR M < 0 4\nEND\nEND\n",
                    {warn(1, 8, "variable 'm' is never assigned by SET or ADD; it is always 0")});
  // ADD counts as an assignment.
  expectDiagnostics("ADD K 1\nJMPVAR K = 1 3\nEND\n", {});
}

TEST_CASE("many errors in one file are all reported, sorted by position", "[compiler]") {
  const std::string text =
      "MOVX 1 2 3 4 5\n"       // 1:1 unknown instruction
      "OUTSIG 9 ON\n"          // 2:8 output outside 1..8
      "GOTO nowhere\n"         // 3:6 undefined label
      "MOVETO 0 0 0 0 500\n"   // 4:16 out of range
      "SET N 1.5 ; comment\n"  // 4 values wrong type: 5:7
      "DELAY -2\n"             // 6:7
      "MOVEP P9\n"             // 7:7 undefined point
      "END\n"
      "POINTS\n"
      "P1 0 0 0\n"             // 10:1 arity
      "P1 0 0 0 0 0\n";        // 11:1 duplicate
  expectDiagnostics(text, {err(1, 1, "unknown instruction 'MOVX' (did you mean MOVE?)"),
                           err(2, 8, "output 9 is outside 1..8"),
                           err(3, 6, "undefined label 'nowhere'"),
                           err(4, 16, "MOVETO target 500 for motor A is outside its range 0..120"),
                           err(5, 7, "expected a value (a whole number), found '1.5'"),
                           err(6, 7, "DELAY cannot be negative, found '-2'"),
                           err(7, 7, "undefined point 'P9'"),
                           err(10, 1, "point P1 has 3 values, expected 5 (one per motor: E D C B A)"),
                           err(11, 1, "point 'P1' is already defined on line 10")});
}

// Regression (a bug these tests found, fixed since): the control-flow checks are skipped as soon as any other
// error exists, so a RETURN in a program that has no GOSUB at all (which
// needs no resolved jump target to see) is only reported once the other
// errors are fixed.
TEST_CASE("RETURN without any GOSUB is reported alongside other errors", "[compiler]") {
  expectDiagnostics("FOO\nRETURN\n", {err(1, 1, "unknown instruction 'FOO' (did you mean GOTO?)"),
                                      err(2, 1, "RETURN without any GOSUB in the program")});
}

// After the first error the compile keeps no code (no image will be made):
// the checks that follow still see every instruction, those before the
// error from the code and those after from what is kept apart.
TEST_CASE("checks after the first error see every instruction", "[compiler]") {
  expectDiagnostics("RETURN\nFOO\nRETURN\nGOTO 6\nGOTO nowhere\n",
                    {err(1, 1, "RETURN without any GOSUB in the program"),
                     err(2, 1, "unknown instruction 'FOO' (did you mean GOTO?)"),
                     err(3, 1, "RETURN without any GOSUB in the program"),
                     err(4, 6, "line number 6 does not exist (the program has 5 instructions)"),
                     err(5, 6, "undefined label 'nowhere'")});
  // A GOSUB after the error still counts: a RETURN may then be reachable.
  expectDiagnostics("RETURN\nFOO\nGOSUB 1\n", {err(2, 1, "unknown instruction 'FOO' (did you mean GOTO?)")});
}

TEST_CASE("render: GNU format, the source line and a caret", "[compiler]") {
  using rs::diag::render;
  {
    const SourceFile source("prog.rsp", "END\nGOTO 9\n");
    const CompileResult r = rs::compiler::compile(source, rhino());
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(render(r.diagnostics[0], &source) ==
          "prog.rsp:2:6: error: line number 9 does not exist (the program has 2 instructions)\n"
          "  GOTO 9\n"
          "       ^\n");
    // Without the source only the first line is printed.
    CHECK(render(r.diagnostics[0], nullptr) ==
          "prog.rsp:2:6: error: line number 9 does not exist (the program has 2 instructions)\n");
  }
  {
    // A tab before the error is copied into the caret line so the caret
    // lines up in any tab width; the tab counts as one column (col 7).
    const SourceFile source("tab.rsp", "\tGOTO 9\r\n");
    const CompileResult r = rs::compiler::compile(source, rhino());
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].pos == rs::diag::Pos{1, 7});
    CHECK(render(r.diagnostics[0], &source) ==
          "tab.rsp:1:7: error: line number 9 does not exist (the program has 1 instruction)\n"
          "  \tGOTO 9\n"
          "  \t     ^\n");
  }
  {
    // A two-byte character before the error takes one caret column.
    const SourceFile source("u.rsp", "END \xC3\xA9 @\n");
    const CompileResult r = rs::compiler::compile(source, rhino());
    REQUIRE(r.diagnostics.size() == 2);
    CHECK(render(r.diagnostics[1], &source) ==
          "u.rsp:1:7: error: unexpected character '@'\n"
          "  END \xC3\xA9 @\n"
          "        ^\n");
  }
  {
    // Warnings say "warning"; a diagnostic without a position has no line.
    const SourceFile source("w.rsp", "END\nEND\n");
    const CompileResult r = rs::compiler::compile(source, rhino());
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(render(r.diagnostics[0], &source) ==
          "w.rsp:2:1: warning: unreachable code: nothing jumps here and END on line 1 does not continue\n"
          "  END\n"
          "  ^\n");
    const Diagnostic whole{"w.rsp", {}, Severity::Error, "cannot read file: is a directory"};
    CHECK(render(whole, &source) == "w.rsp: error: cannot read file: is a directory\n");
  }
}

TEST_CASE("a straight-line move needs the robot's kinematics, and APPRO and DEPART a positive length",
          "[compiler][straight]") {
  const std::string needs =
      " moves the tool along a straight line, which needs the robot's kinematics: this program is compiled for "
      "motors alone";
  expectDiagnostics("MOVES P\nAPPRO 5\nDEPART 5\nEND\nPOINTS\nP 0 0 0 0 0\n",
                    {err(1, 1, "MOVES" + needs), err(2, 1, "APPRO" + needs), err(3, 1, "DEPART" + needs)});
  expectDiagnostics("APPRO 0\nDEPART -5\nAPPRO 100001\nEND\n",
                    {err(1, 7, "APPRO goes 1 to 100000 length units, found 0"),
                     err(1, 1, "APPRO" + needs),
                     err(2, 8, "DEPART goes 1 to 100000 length units, found -5"),
                     err(2, 1, "DEPART" + needs),
                     err(3, 7, "APPRO goes 1 to 100000 length units, found 100001"),
                     err(3, 1, "APPRO" + needs)});
  expectDiagnostics("APPRO\nEND\n",
                    {err(1, 1, "APPRO expects 1 operand (APPRO <length>), found 0"), err(1, 1, "APPRO" + needs)});
  expectDiagnostics("DEPART UP\nEND\n",
                    {err(1, 8, "expected a distance in length units, found 'UP'"), err(1, 1, "DEPART" + needs)});
  const CompileResult r = compileText("DEPART -5\nEND\n");
  bool hinted = false;
  for (const Diagnostic& d : r.diagnostics) hinted = hinted || d.hint.find("use the other one") != std::string::npos;
  CHECK(hinted);
}
