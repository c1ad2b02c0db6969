// "Did you mean ...?" hints: an undefined label, point or variable of a
// program is compared with the names the file defines; a misspelled
// keyword of a description (.rsd) with the keywords the error message
// lists. Each expected hint was chosen by hand: the intended name is one or
// two edits away, and a name too far away gets no hint at all.
#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "compiler/description/description.h"
#include "diag/diagnostic.h"
#include "stdlib/default_robot.h"

namespace {

using rs::diag::Diagnostic;
using rs::diag::Severity;
using rs::diag::SourceFile;

std::vector<Diagnostic> compileDiagnostics(const std::string& text) {
  const SourceFile source("t.rsp", text);
  return rs::compiler::compile(source, {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth})
      .diagnostics;
}

// "line:col: message | hint" per diagnostic, in order.
std::vector<std::string> described(const std::vector<Diagnostic>& diags) {
  std::vector<std::string> out;
  for (const Diagnostic& d : diags)
    out.push_back(std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": " +
                  (d.severity == Severity::Error ? "" : "warning: ") + d.message + " | " + d.hint);
  return out;
}

std::vector<Diagnostic> descriptionDiagnostics(const std::string& text) {
  rs::diag::Diagnostics d("t.rsd");
  rs::compiler::parseDescription(std::make_unique<SourceFile>("t.rsd", text), d);
  return d.sorted();
}

}  // namespace

TEST_CASE("did you mean: an undefined label names the nearest label of the file", "[compiler][hints]") {
  const std::string text =
      "PICK: MOVE 10 0 0 0 0\n"   // 1
      "place: MOVE -10 0 0 0 0\n" // 2
      "GOTO PIKC\n"               // 3: two edits from PICK (a swap)
      "JMPIN 1 ON plce\n"         // 4: one edit from place
      "GOSUB faraway\n"           // 5: nothing near
      "END\n";
  CHECK(described(compileDiagnostics(text)) ==
        std::vector<std::string>{"3:6: undefined label 'PIKC' | did you mean 'PICK'?",
                                 "4:12: undefined label 'plce' | did you mean 'place'?",
                                 "5:7: undefined label 'faraway' | "});
}

TEST_CASE("did you mean: an undefined point names the nearest point", "[compiler][hints]") {
  const std::string text =
      "MOVEP HOEM\n"  // 1
      "MOVEP Q9\n"    // 2: two edits from P1, too many for a two-letter name
      "MOVEP P2\n"    // 3: one edit from P1
      "END\n"
      "POINTS\n"
      "HOME 0 0 0 0 0\n"
      "P1 10 0 0 0 0\n";
  CHECK(described(compileDiagnostics(text)) ==
        std::vector<std::string>{"1:7: undefined point 'HOEM' | did you mean 'HOME'?", "2:7: undefined point 'Q9' | ",
                                 "3:7: undefined point 'P2' | did you mean 'P1'?"});
}

TEST_CASE("did you mean: a variable only read names the nearest variable that is set", "[compiler][hints]") {
  const std::string text =
      "SET COUNT 0\n"          // 1
      "loop: ADD COUNT 1\n"    // 2
      "JMPVAR CUONT < 3 loop\n"  // 3: never assigned; two edits from COUNT
      "JMPVAR TOTAL > 3 loop\n"  // 4: never assigned; nothing near
      "END\n";
  CHECK(described(compileDiagnostics(text)) ==
        std::vector<std::string>{
            "3:8: warning: variable 'CUONT' is never assigned by SET or ADD; it is always 0 | did you mean 'COUNT'?",
            "4:8: warning: variable 'TOTAL' is never assigned by SET or ADD; it is always 0 | "});
}

TEST_CASE("did you mean: the hint is printed on its own line", "[compiler][hints]") {
  const std::vector<Diagnostic> d = compileDiagnostics("PICK: END\nGOTO PICKK\n");
  REQUIRE(d.size() == 1);
  const SourceFile source("t.rsp", "PICK: END\nGOTO PICKK\n");
  CHECK(rs::diag::render(d[0], &source) ==
        "t.rsp:2:6: error: undefined label 'PICKK'\n"
        "  GOTO PICKK\n"
        "       ^\n"
        "  hint: did you mean 'PICK'?\n");
}

TEST_CASE("did you mean: misspelled description keywords", "[compiler][hints][models]") {
  const std::string text =
      "LIEN top\n"                        // 1: a block kind: LINK
      "LINK b\n"                          // 2
      "  LIEN 0 0 0 1 1 1\n"              // 3: a shape statement: LINE
      "  BOX 1 2 3 4 5 6 COLOUR RED\n"    // 4: COLOR
      "  COLOR LIGHTGREY\n"               // 5: a colour name: LIGHTGRAY
      "  SPIN Z 90\n"                     // 6: nothing near
      "END\n"                             // 7
      "ROBOT r\n"                         // 8
      "  LINK b FRAME ORIGN 0 0 0\n"      // 9: ORIGIN
      "  JOINT 1 REVOLUT\n"               // 10: REVOLUTE
      "  JOINT 2 PRISMATIC LETTR C\n"     // 11: LETTER
      "END\n"
      "WORKCELL w\n"                      // 13
      "  ROBOTT r\n"                      // 14: ROBOT
      "END\n";
  CHECK(described(descriptionDiagnostics(text)) ==
        std::vector<std::string>{
            "1:1: expected LINK, OBJECT, GRIPPER, ROBOT or WORKCELL, found 'LIEN' | did you mean 'LINK'?",
            "3:3: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'LIEN' | did you mean 'LINE'?",
            "4:19: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'COLOUR' | did you mean 'COLOR'?",
            "5:9: expected a colour: one of the 16 EGA colour names (BLACK .. WHITE) or a number 0..15, found "
            "'LIGHTGREY' | did you mean 'LIGHTGRAY'?",
            "6:3: expected LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END, found 'SPIN' | ",
            "9:16: expected LINK, FRAME, ORIGIN, XAXIS, ZAXIS, TOOL, JOINT, LETTER, PRECISION, RANGE, COUPLING, "
            "SPEED, ACCELERATION, GRIPPER or END, found 'ORIGN' | did you mean 'ORIGIN'?",
            "10:11: expected REVOLUTE or PRISMATIC, found 'REVOLUT' | did you mean 'REVOLUTE'?",
            "11:21: expected LINK, FRAME, ORIGIN, XAXIS, ZAXIS, TOOL, JOINT, LETTER, PRECISION, RANGE, COUPLING, "
            "SPEED, ACCELERATION, GRIPPER or END, found 'LETTR' | did you mean 'LETTER'?",
            "14:3: expected ROBOT, OBJECT, FLOOR, CONVEYOR, FEEDER, SENSOR, SINK, WIRE or END, found 'ROBOTT' | did you "
            "mean 'ROBOT'?"});
}
