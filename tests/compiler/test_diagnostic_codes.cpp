// Every compile diagnostic carries a stable code, and the ones that know
// another place (the first definition of a name defined twice) carry it as
// a related location, which the CLI prints as a note.
#include <catch2/catch.hpp>

#include "compiler/program/compiler.h"
#include "stdlib/default_robot.h"
#include "tests/cli/cli_support.h"

namespace {

rs::compiler::CompileResult compileForCodes(const std::string& text) {
  const rs::diag::SourceFile source("p.rsp", text);
  return rs::compiler::compile(source, {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth});
}

std::string codeOf(const std::string& text) {
  const auto r = compileForCodes(text);
  REQUIRE_FALSE(r.diagnostics.empty());
  return std::string(r.diagnostics.front().code);
}

}  // namespace

TEST_CASE("compile diagnostics have stable codes", "[compiler][codes]") {
  CHECK(codeOf("MOVX 1 2 3 4 5\n") == "unknown-instruction");
  CHECK(codeOf("GOTO nowhere\n") == "undefined-label");
  CHECK(codeOf("MOVEP P\n") == "undefined-point");
  CHECK(codeOf("GOTO 9\n") == "undefined-line-number");
  CHECK(codeOf("MOVE 1 2\n") == "operand-count");
  CHECK(codeOf("OUTSIG 9 ON\n") == "io-out-of-range");
  CHECK(codeOf("MOVETO 5000 0 0 0 0\n") == "value-out-of-range");
  CHECK(codeOf("OUTSIG 1 MAYBE\n") == "bad-operand");
  CHECK(codeOf("a: END\na: END\n") == "duplicate-label");
  CHECK(codeOf("END\nPOINTS\np 0 0 0 0 0\np 0 0 0 0 0\n") == "duplicate-point");
  CHECK(codeOf("END\nSET N 1\n") == "unreachable-code");
  CHECK(codeOf("RETURN\n") == "unmatched-return");
  CHECK(codeOf("MOVE 1 2 3 4 5 $\n") == "bad-character");
  CHECK(codeOf("SET END 1\n") == "reserved-word");
  CHECK(codeOf("DELAY -1\n") == "bad-delay");
  CHECK(codeOf("") == "empty-program");
  CHECK(codeOf("END\xFF\n") == "invalid-utf8");
}

TEST_CASE("a duplicate label and point name their first definition as a related place", "[compiler][codes]") {
  const auto labels = compileForCodes("loop: SET N 1\n  LOOP: END\n");
  REQUIRE(labels.diagnostics.size() == 1);
  REQUIRE(labels.diagnostics[0].related.size() == 1);
  CHECK(labels.diagnostics[0].related[0] == rs::diag::Related{"p.rsp", {1, 1}, "'LOOP' is first defined here"});
  const auto points = compileForCodes("END\nPOINTS\n  p 0 0 0 0 0\np 0 0 0 0 0\n");
  REQUIRE(points.diagnostics.size() == 1);
  REQUIRE(points.diagnostics[0].related.size() == 1);
  CHECK(points.diagnostics[0].related[0] == rs::diag::Related{"p.rsp", {3, 3}, "'p' is first defined here"});
}

TEST_CASE("the CLI prints a related place as a note line", "[compiler][codes][cli]") {
  rs::testing::TempDir dir;
  const std::string f = dir.write("dup.rsp", "a: SET N 1\na: END\n");
  const auto r = rs::testing::runCli({"check", f});
  CHECK(r.err == f + ":2:1: error: label 'a' is already defined on line 1\n  a: END\n  ^\n" + f +
                     ":1:1: note: 'a' is first defined here\n");
}
