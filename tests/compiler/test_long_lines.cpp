// Long lines and many errors ("linear time on any input"): the source line
// shown under a diagnostic is an excerpt around the column, found without
// counting columns from the start of the line; a message quotes at most 64
// characters of a word; a line gives the parser at most kMaxLineWords
// words; a collector with a limit keeps the first diagnostics by position
// and counts the others. Sizes are asserted here, never times (the
// benchmark `robotsim_bench --only errors` times them).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "compiler/program/lexer.h"
#include "diag/diagnostic.h"
#include "stdlib/default_robot.h"

namespace {

using rs::diag::Diagnostic;
using rs::diag::Diagnostics;
using rs::diag::Pos;
using rs::diag::Severity;
using rs::diag::SourceFile;

rs::compiler::Target longLinesTarget() { return {"rhino-scara", rs::stdlib::rhinoScaraMotors(), rs::vm::kDefaultCallDepth}; }

// The byte offset of column `col` of `line`, counted from the line's start
// one character at a time (a byte that is not UTF-8 is one character).
std::size_t naiveOffset(std::string_view line, std::uint32_t col) {
  std::size_t i = 0;
  for (std::uint32_t c = 1; c < col && i < line.size(); ++c)
    i += std::max<std::size_t>(rs::diag::utf8SequenceLength(line, i), 1);
  return i;
}

// Columns of `s`, counted as the display does: "…" is one.
std::size_t columns(std::string_view s) {
  std::size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

}  // namespace

TEST_CASE("SourceFile::line: the line without its break, however the file ends", "[diag]") {
  const SourceFile a("a", "one\r\ntwo\nthree");
  CHECK(a.lineCount() == 3);
  CHECK(a.line(1) == "one");
  CHECK(a.line(2) == "two");
  CHECK(a.line(3) == "three");
  CHECK(a.line(4).empty());
  const SourceFile b("b", "one\ntwo\r\n");
  CHECK(b.lineCount() == 2);
  CHECK(b.line(2) == "two");
  const SourceFile c("c", "\n\n");
  CHECK(c.lineCount() == 2);
  CHECK(c.line(1).empty());
  CHECK(c.line(2).empty());
}

TEST_CASE("SourceFile::offsetOf agrees with counting from the line's start", "[diag]") {
  // Long lines (past the checkpoint stride) of ASCII, two-, three- and
  // four-byte characters, bytes that are not UTF-8 and tabs.
  std::string line;
  for (int i = 0; i < 6000; ++i) {
    switch (i % 7) {
      case 0: line += "ab"; break;
      case 1: line += "\xC3\xA9"; break;          // é
      case 2: line += "\xE2\x82\xAC"; break;      // €
      case 3: line += "\xF0\x9F\x98\x80"; break;  // 😀
      case 4: line += '\xFF'; break;              // not UTF-8
      case 5: line += '\t'; break;
      default: line += "xyz"; break;
    }
  }
  const std::string text = "short\n" + line + "\n" + line + "\r\nlast";
  const SourceFile source("s", text);
  REQUIRE(source.lineCount() == 4);
  for (std::uint32_t n = 1; n <= 4; ++n) {
    const std::string_view l = source.line(n);
    const auto start = static_cast<std::size_t>(l.data() - source.text().data());
    for (std::uint32_t col : {1u, 2u, 3u, 100u, 4095u, 4096u, 4097u, 5000u, 10000u, 12345u, 15000u, 20000u, 99999u}) {
      INFO("line " << n << ", column " << col);
      CHECK(source.offsetOf({n, col}) == start + naiveOffset(l, col));
    }
  }
  CHECK(source.offsetOf({0, 1}) == text.size());
  CHECK(source.offsetOf({5, 1}) == text.size());
  CHECK(rs::diag::displayLine(source, {5, 1}).text.empty());
}

TEST_CASE("the source line under a diagnostic is an excerpt around the column", "[diag]") {
  // 1,000,000 characters: '@' at column 500,001, digits elsewhere.
  std::string line(1'000'000, '7');
  line[500'000] = '@';
  const SourceFile source("long.rsp", "END\n" + line + "\n");
  const Diagnostic d{"long.rsp", {2, 500'001}, Severity::Error, "unexpected character '@'"};
  const std::string shown = rs::diag::render(d, &source);
  const std::string header = "long.rsp:2:500001: error: unexpected character '@'\n";
  REQUIRE(shown.starts_with(header));
  CHECK(shown.size() < header.size() + 400);
  // "…", 50 columns before the caret, the caret's column, 49 after, "…".
  const std::string excerpt = "\xE2\x80\xA6" + std::string(50, '7') + "@" + std::string(49, '7') + "\xE2\x80\xA6";
  CHECK(shown == header + "  " + excerpt + "\n  " + std::string(51, ' ') + "^\n");
  // At the start of the line nothing is cut before; at its end nothing after.
  const rs::diag::DisplayLine start = rs::diag::displayLine(source, {2, 3});
  CHECK(start.text == std::string(100, '7') + "\xE2\x80\xA6");
  CHECK(start.caretIndent == "  ");
  const rs::diag::DisplayLine end = rs::diag::displayLine(source, {2, 1'000'000});
  CHECK(end.text == "\xE2\x80\xA6" + std::string(51, '7'));
  CHECK(columns(end.caretIndent) == 51);
  const rs::diag::DisplayLine whole = rs::diag::displayLine(source, {1, 2});
  CHECK(whole.text == "END");
  CHECK(whole.caretIndent == " ");
}

TEST_CASE("a message quotes at most 64 characters of a word", "[compiler]") {
  const std::string word(100'000, 'x');
  const SourceFile source("w.rsp", "MOVE " + word + " 0 0 0 0\n" + word + "\nEND\n");
  const rs::compiler::CompileResult r = rs::compiler::compile(source, longLinesTarget());
  REQUIRE(r.diagnostics.size() == 2);
  const std::string quoted = std::string(64, 'x') + "\xE2\x80\xA6";
  CHECK(r.diagnostics[0].message == "expected an encoder value, found '" + quoted + "'");
  CHECK(r.diagnostics[1].message == "unknown instruction '" + quoted + "'");
  // A name of 64 characters is quoted whole.
  CHECK(rs::diag::excerpt(std::string(64, 'n')) == std::string(64, 'n'));
  CHECK(rs::diag::excerpt("\xC3\xA9\xC3\xA9\xC3\xA9", 2) == "\xC3\xA9\xC3\xA9\xE2\x80\xA6");
}

TEST_CASE("a line gives the parser at most kMaxLineWords words", "[compiler]") {
  using rs::compiler::kMaxLineWords;
  // MOVE and a million operands: one error for each of the first 63, one
  // for the line; the words beyond are never tokens.
  std::string text = "MOVE";
  for (int i = 0; i < 1'000'000; ++i) text += " x";
  text += " ; comment\r\nEND\n";
  const SourceFile source("m.rsp", text);
  const rs::compiler::CompileResult r = rs::compiler::compile(source, longLinesTarget());
  REQUIRE(r.diagnostics.size() == kMaxLineWords);
  for (std::uint32_t i = 0; i + 1 < kMaxLineWords; ++i) {
    CHECK(r.diagnostics[i].pos == Pos{1, 6 + 2 * i});
    CHECK(r.diagnostics[i].message == "expected an encoder value, found 'x'");
  }
  CHECK(r.diagnostics.back().pos == Pos{1, 4 + 2 * kMaxLineWords});
  CHECK(r.diagnostics.back().message == "more than 64 words on one line: the rest of the line is skipped");
  // The line break after the skipped words is where it is.
  Diagnostics d("m.rsp");
  const std::string tokens = rs::compiler::dumpTokens(source, d);
  CHECK(tokens.ends_with("1:2000015 NEWLINE\n2:1      IDENT    END\n2:4      NEWLINE\n3:1      EOF\n"));
  CHECK(std::count(tokens.begin(), tokens.end(), '\n') == kMaxLineWords + 4);
  // 64 words are fine.
  std::string full = "P1";
  for (std::uint32_t i = 1; i < kMaxLineWords; ++i) full += " 0";
  CHECK(rs::compiler::compile(SourceFile("f.rsp", "END\nPOINTS\n" + full + "\n"), longLinesTarget()).diagnostics.size() == 1);
}

TEST_CASE("a collector with a limit keeps the first diagnostics by position", "[diag]") {
  // Reported out of order (as the lexer, the AST builder and the checks
  // report them): line i * 7919 mod 10007 + 1, an error for odd i, a
  // warning for even i; and two more on line 1, after the first there.
  constexpr std::size_t kCount = 10007;
  Diagnostics all("f"), first("f", 10);
  for (std::size_t i = 0; i < kCount; ++i) {
    const Pos pos{static_cast<std::uint32_t>(i * 7919 % kCount + 1), 1};
    const Severity s = i % 2 ? Severity::Error : Severity::Warning;
    for (Diagnostics* d : {&all, &first}) {
      d->add(pos, s, std::to_string(i));
      if (i == 5000) d->error({1, 1}, "second on line 1");
      if (i == 6000) d->error({1, 1}, "third on line 1");
    }
  }
  const std::vector<Diagnostic> everything = all.sorted();
  const std::vector<Diagnostic> kept = first.sorted();
  REQUIRE(kept.size() == 10);
  CHECK(kept[0].message == "0");
  CHECK(kept[1].message == "second on line 1");
  CHECK(kept[2].message == "third on line 1");
  std::size_t errors = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    CHECK(kept[i].message == everything[i].message);
    CHECK(kept[i].pos == everything[i].pos);
    errors += kept[i].severity == Severity::Error;
  }
  CHECK(first.errorCount() == all.errorCount());
  CHECK(first.omitted().errors == all.errorCount() - errors);
  CHECK(first.omitted().errors + first.omitted().warnings == kCount + 2 - 10);
  CHECK(!all.omitted().any());
}

TEST_CASE("compile keeps the first diagnostics when asked, and counts the others", "[compiler]") {
  // 1,000 lines with an unknown instruction, one with two errors.
  std::string text;
  for (int i = 0; i < 1000; ++i) text += i == 500 ? "OUTSIG 9 @\n" : "FOO\n";
  const SourceFile source("k.rsp", text);
  const rs::compiler::CompileResult all = rs::compiler::compile(source, longLinesTarget());
  const rs::compiler::CompileResult some = rs::compiler::compile(source, longLinesTarget(), 5);
  REQUIRE(all.diagnostics.size() == 1001);
  CHECK(all.omitted.errors == 0);
  REQUIRE(some.diagnostics.size() == 5);
  for (std::size_t i = 0; i < 5; ++i) CHECK(some.diagnostics[i].message == all.diagnostics[i].message);
  CHECK(some.omitted.errors == 996);
  CHECK(some.omitted.warnings == 0);
}
