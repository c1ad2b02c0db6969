// Golden tests: `robotsim disasm`, `tokens` and `ast` of the programs in
// tests/golden/*.rsp must print exactly tests/golden/NAME.{disasm,tokens,ast}
// (file names in the output are shown relative to tests/golden/).
//
// Every golden file was checked by hand against its program:
//
// handshake.rsp (16 instructions on lines 4..20, points on 23..24):
//   disasm - header counts (16 instructions, 5 constants: the MOVE's only,
//     1 variable, 2 points) and the motor ranges E D C B A; each row's
//     instruction number and source line; labels start/loop/done/place on
//     instructions 1, 2, 13, 14; resolved targets: JMPIN 3 ON 12 -> 12
//     (line 15, HRDHOME, no label), GOSUB place -> 14 (line 18, place),
//     JMPVAR ... loop -> 2 (line 5, loop), GOTO done -> 13 (line 16, done);
//     MOVEP comments show the point values; DELAY 0.25; points and the one
//     variable slot listed at the end.
//   tokens - every token's line:column counted by hand (labels at column 1,
//     mnemonics at 9, signed numbers such as -50 one token), a NEWLINE per
//     line including comment-only and blank lines, EOF at 25:1. A NEWLINE
//     after a comment is at the column of the line break itself (e.g. 7:50,
//     after "; ask for a part" which starts at 7:34).
//   ast - mnemonic positions (all at column 9), labels, operands as typed
//     values (JMPIN target=(line 12), GOSUB target=(label place)), DELAY as
//     250 milliseconds, the POINTS header at 22:1 and both points.
//
// motion.rsp (lower-case mnemonics, a tab, +10, no points):
//   disasm - 21 constants (5+5+5+3+3), mnemonics upper-cased, +10 shown as
//     10, DELAY 1.5 and 0.005, label again on instruction 11, JMPVAR -> 11
//     (line 12, again), GOTO 1 -> 1 (line 2), the variable keeps its
//     spelling n, no points section.
//   tokens - the tab counts as one column (+10 at 3:6), the comment on line
//     1 ends at column 65 so its NEWLINE is 1:66.
//   ast - positions, milliseconds=1500 and 5, xyz triples, GOTO (line 1).
//
// To regenerate after an intended change, run with ROBOTSIM_UPDATE_GOLDEN=1
// and check the new files by hand again before committing them.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "tests/cli/cli_support.h"

namespace {

const std::string kGoldenDir = std::string(ROBOTSIM_SOURCE_DIR) + "/tests/golden/";

std::string relative(std::string text) {
  for (std::size_t at = text.find(kGoldenDir); at != std::string::npos; at = text.find(kGoldenDir, at))
    text.erase(at, kGoldenDir.size());
  return text;
}

void checkGolden(const std::string& program, const std::string& view) {
  const rs::testing::CliResult r = rs::testing::runCli({view, kGoldenDir + program + ".rsp"});
  INFO(view << " " << program << ".rsp");
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  const std::string expectedPath = kGoldenDir + program + "." + view;
  const std::string actual = relative(r.out);
  if (rs::testing::rewriteGolden(expectedPath, actual)) return;
  const std::string expected = rs::testing::readBytes(expectedPath);
  REQUIRE(!expected.empty());
  CHECK(actual == expected);
}

}  // namespace

TEST_CASE("golden: disasm", "[golden]") {
  checkGolden("handshake", "disasm");
  checkGolden("motion", "disasm");
}

TEST_CASE("golden: ast", "[golden]") {
  checkGolden("handshake", "ast");
  checkGolden("motion", "ast");
}

// Regression: the NEWLINE after a comment once reported the comment's
// column; every token's position is checked.
TEST_CASE("golden: tokens", "[golden]") {
  checkGolden("handshake", "tokens");
  checkGolden("motion", "tokens");
}

TEST_CASE("golden: disasm of the compiled image equals disasm of the source", "[golden]") {
  rs::testing::TempDir dir;
  const std::string image = dir.file("handshake.rsb");
  REQUIRE(rs::testing::runCli({"compile", kGoldenDir + "handshake.rsp", "-o", image}).code == 0);
  const rs::testing::CliResult r = rs::testing::runCli({"disasm", image});
  CHECK(r.code == 0);
  CHECK(relative(r.out) == rs::testing::readBytes(kGoldenDir + "handshake.disasm"));
}

// Regression (a bug these tests found, fixed since): the lexer does not advance the column over a comment, so
// the NEWLINE that ends a commented line is reported at the column where
// the comment starts (here 1:5 instead of 1:9).
TEST_CASE("tokens: the NEWLINE after a comment is at the line break", "[golden]") {
  const rs::diag::SourceFile source("c.rsp", "END ; hi\nEND\n");
  rs::diag::Diagnostics diags("c.rsp");
  CHECK(rs::compiler::dumpTokens(source, diags) ==
        "1:1      IDENT    END\n"
        "1:9      NEWLINE\n"
        "2:1      IDENT    END\n"
        "2:4      NEWLINE\n"
        "3:1      EOF\n");
  CHECK(diags.all().empty());
}
