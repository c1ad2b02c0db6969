// Lossless editing of the POINTS section (tools/teach/points_edit.h) and the
// program file's guarded write (tools/teach/program_file.h).
//
// Every expected text below was worked out by hand from the layout rule
// (the column arithmetic is in the comments), not copied from the
// program's output. The compile tests check with the compiler itself that
// an edit changes the image's points and nothing else.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/file_io.h"
#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/teach/points_edit.h"
#include "tools/teach/program_file.h"

namespace {

using rs::teach::PointsText;

// Columns (0-based): HOME's values end at 11, 17, 23, 28, 33; so do PICK's
// (right-aligned, as in docs/language.md); PICK's comment starts at 36.
const std::string kPointsProgram =
    "; pick one block\n"
    "        MOVEP PICK              ; go\n"
    "        END\n"
    "\n"
    "POINTS                          ; taught\n"
    ";         E     D     C    B    A\n"
    "HOME      0     0     0    0    0\n"
    "PICK    400  -200  -150  250    0   ; over the block\n"
    "\n"
    "; the end\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::vector<std::int32_t> v(std::initializer_list<std::int32_t> l) { return l; }

rs::vm::Image compiled(const std::string& text) {
  const rs::diag::SourceFile source("p.rsp", text);
  rs::compiler::CompileResult r = rs::compiler::compile(source, rs::launch::defaultTarget());
  for (const auto& d : r.diagnostics) INFO(d.message);
  REQUIRE(r.image);
  return *r.image;
}

}  // namespace

TEST_CASE("points: reading the section keeps every byte", "[teach]") {
  const PointsText p(kPointsProgram);
  CHECK(p.text() == kPointsProgram);
  REQUIRE(p.pointsLine() == 4u);
  REQUIRE(p.points().size() == 2);
  CHECK(p.points()[0].name == "HOME");
  CHECK(p.points()[1].values == v({400, -200, -150, 250, 0}));
  CHECK(p.points()[1].line == 7u);
  CHECK(p.find("pick") == 1u);
  const std::string crlf = "END\r\npoints\r\nP1 +5 007 0 0 0\r\n";
  const PointsText q(crlf);
  CHECK(q.text() == crlf);
  REQUIRE(q.points().size() == 1);
  CHECK(q.points()[0].values == v({5, 7, 0, 0, 0}));
}

TEST_CASE("points: re-teaching a point rewrites its row in its columns, comment kept", "[teach]") {
  PointsText p(kPointsProgram);
  REQUIRE(p.replace("pick", v({12, -3, 1500, 0, 90})).empty());
  // "PICK" + 5 spaces + "12" ends at 11; "-3" ends at 17 (4 spaces); "1500"
  // at 23 (2); "0" at 28 (4); "90" at 33 (3); the comment back at 36 (3).
  CHECK(p.text() == replaced(kPointsProgram, "PICK    400  -200  -150  250    0   ; over the block",
                             "PICK     12    -3  1500    0   90   ; over the block"));
}

TEST_CASE("points: a taught point goes after the last one, aligned with it", "[teach]") {
  PointsText p(kPointsProgram);
  REQUIRE(p.add("NEW", v({1, 2, 3, 4, 5})).empty());
  // "NEW" + 7 spaces + "1" ends at 11; then 5, 5, 4, 4 spaces.
  CHECK(p.text() == replaced(kPointsProgram, "over the block\n", "over the block\nNEW       1     2     3    4    5\n"));
  // Too wide for its column: one space ("WIDE 12345678" is 13 wide), and
  // the next column catches up: "2" ends at 17 again (3 spaces).
  PointsText q(kPointsProgram);
  REQUIRE(q.add("WIDE", v({12345678, 2, 3, 4, 5})).empty());
  CHECK(q.text() == replaced(kPointsProgram, "over the block\n", "over the block\nWIDE 12345678   2     3    4    5\n"));
}

TEST_CASE("points: delete and rename touch one row", "[teach]") {
  PointsText p(kPointsProgram);
  REQUIRE(p.remove("home").empty());
  CHECK(p.text() == replaced(kPointsProgram, "HOME      0     0     0    0    0\n", ""));
  PointsText r(kPointsProgram);
  REQUIRE(r.rename("PICK", "PK").empty());
  // "PK" + 6 spaces: 400 still ends at 11; the rest of the row as it was.
  CHECK(r.text() == replaced(kPointsProgram, "PICK    400", "PK      400"));
  PointsText w(kPointsProgram);
  REQUIRE(w.rename("PICK", "GRAB_BLOCK").empty());
  // "GRAB_BLOCK 400" is 14 wide: -200 and -150 get one space each (ends 19,
  // 24), 250 ends at 28 again (one space), 0 at 33 (4), the comment at 36.
  CHECK(w.text() == replaced(kPointsProgram, "PICK    400  -200  -150  250    0",
                             "GRAB_BLOCK 400 -200 -150 250    0"));
}

TEST_CASE("points: a missing POINTS line is added after the last line", "[teach]") {
  PointsText p("MOVE 1 0 0 0 0\nEND\n");
  REQUIRE(p.add("P1", v({0, 1, 2, 3, 4})).empty());
  CHECK(p.text() == "MOVE 1 0 0 0 0\nEND\nPOINTS\nP1 0 1 2 3 4\n");
  PointsText q("MOVE 1 0 0 0 0\r\nEND");  // CR LF, no final line end
  REQUIRE(q.add("P1", v({0, 1, 2, 3, 4})).empty());
  CHECK(q.text() == "MOVE 1 0 0 0 0\r\nEND\r\nPOINTS\r\nP1 0 1 2 3 4");
  REQUIRE(q.add("P2", v({5, 6, 7, 8, 9})).empty());
  CHECK(q.text() == "MOVE 1 0 0 0 0\r\nEND\r\nPOINTS\r\nP1 0 1 2 3 4\r\nP2 5 6 7 8 9");
  REQUIRE(q.remove("P2").empty());  // P1 keeps the line end it got when P2 came
  CHECK(q.text() == "MOVE 1 0 0 0 0\r\nEND\r\nPOINTS\r\nP1 0 1 2 3 4\r\n");
  PointsText e("END\nPOINTS ; none yet\n\n; trailing comment\n");  // empty section: right after POINTS
  REQUIRE(e.add("A1", v({1, 2, 3, 4, 5})).empty());
  CHECK(e.text() == "END\nPOINTS ; none yet\nA1 1 2 3 4 5\n\n; trailing comment\n");
}

TEST_CASE("points: tab-separated rows keep their tabs, left-aligned columns stay left", "[teach]") {
  PointsText t("END\nPOINTS\nP1\t0\t0\t0\t0\t0\t; c\n");
  REQUIRE(t.replace("P1", v({1, -2, 3, 4, 5})).empty());
  CHECK(t.text() == "END\nPOINTS\nP1\t1\t-2\t3\t4\t5\t; c\n");
  // Field 1 starts at 4 in both rows and ends at 5 and 7: left at 4; field
  // 2 likewise left at 9; field 3 ends at 15 in both: right at 15; field 4
  // starts at 19 in both, ends differ: left; field 5 ends at 25: right.
  PointsText l("END\nPOINTS\nA   0    0    0    0    0\nBB  400  -200 0    12   0\n");
  REQUIRE(l.add("C", v({1000, 5, 77, 3, 1})).empty());
  CHECK(l.text() == "END\nPOINTS\nA   0    0    0    0    0\nBB  400  -200 0    12   0\nC   1000 5   77    3    1\n");
}

TEST_CASE("points: names the language refuses are refused, the text unchanged", "[teach]") {
  PointsText p(kPointsProgram);
  CHECK(p.add("home", v({0, 0, 0, 0, 0})) == "there is a point HOME already (line 7)");
  CHECK(p.add("moveto", v({0, 0, 0, 0, 0})) == "MOVETO is an instruction: it cannot name a point");
  CHECK(p.add("Points", v({0, 0, 0, 0, 0})) == "POINTS is a reserved word: it cannot name a point");
  CHECK(p.add("9lives", v({0, 0, 0, 0, 0})) == "a point name is letters, digits and '_', not starting with a digit");
  CHECK(p.add("", v({0, 0, 0, 0, 0})) == "a point needs a name");
  CHECK(p.rename("PICK", "home") == "there is a point HOME already (line 7)");
  CHECK(p.replace("NOPE", v({0, 0, 0, 0, 0})) == "there is no point NOPE");
  CHECK(p.remove("NOPE") == "there is no point NOPE");
  CHECK(p.text() == kPointsProgram);
}

TEST_CASE("points: the compiled image differs in the changed points only", "[teach]") {
  const std::string program = replaced(kPointsProgram, "MOVEP PICK", "MOVEP HOME");
  const rs::vm::Image before = compiled(program);
  REQUIRE(before.points.size() == 2);
  PointsText p(program);
  REQUIRE(p.add("NEW", v({1, 2, 3, 4, 5})).empty());
  REQUIRE(p.replace("HOME", v({-10, 20, -30, 40, 50})).empty());
  REQUIRE(p.rename("PICK", "GRAB").empty());
  rs::vm::Image expected = before;
  expected.points = {{"HOME", v({-10, 20, -30, 40, 50})}, {"GRAB", v({400, -200, -150, 250, 0})},
                     {"NEW", v({1, 2, 3, 4, 5})}};
  CHECK(compiled(p.text()) == expected);
  REQUIRE(p.remove("NEW").empty());
  expected.points.pop_back();
  CHECK(compiled(p.text()) == expected);
}

TEST_CASE("program file: written atomically with a .bak, refused after an edit on disk", "[teach]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", kPointsProgram);
  rs::diag::Result<rs::teach::ProgramFile> f = rs::teach::ProgramFile::load(path);
  REQUIRE(f);
  CHECK(f->hash() == rs::teach::textHash(kPointsProgram));
  REQUIRE(f->change([](PointsText& p) { return p.add("NEW", v({1, 2, 3, 4, 5})); }).empty());
  const std::string once = replaced(kPointsProgram, "over the block\n", "over the block\nNEW       1     2     3    4    5\n");
  CHECK(*rs::base::readFile(path, 1 << 20).bytes == once);
  CHECK(*rs::base::readFile(path + ".bak", 1 << 20).bytes == kPointsProgram);
  REQUIRE(f->change([](PointsText& p) { return p.remove("NEW"); }).empty());
  CHECK(*rs::base::readFile(path, 1 << 20).bytes == kPointsProgram);
  CHECK(*rs::base::readFile(path + ".bak", 1 << 20).bytes == kPointsProgram);  // the file as the session found it
  CHECK(!std::filesystem::exists(path + ".tmp"));
  // Someone edits the file: the next write is refused and their text stays.
  const std::string theirs = kPointsProgram + "; edited elsewhere\n";
  dir.write("p.rsp", theirs);
  const std::string why = f->change([](PointsText& p) { return p.add("X", v({0, 0, 0, 0, 0})); });
  CHECK(why.find("changed on disk since teach read it (someone edited it)") != std::string::npos);
  CHECK(*rs::base::readFile(path, 1 << 20).bytes == theirs);
  // Reloading takes their text; the next write goes on top of it.
  REQUIRE(f->reload().empty());
  REQUIRE(f->change([](PointsText& p) { return p.add("X", v({0, 0, 0, 0, 0})); }).empty());
  CHECK(*rs::base::readFile(path, 1 << 20).bytes ==
        replaced(theirs, "over the block\n", "over the block\nX         0     0     0    0    0\n"));
  // An edit the points refuse writes nothing.
  CHECK(f->change([](PointsText& p) { return p.add("x", v({0, 0, 0, 0, 0})); }) == "there is a point X already (line 9)");
}

namespace {

// The text's lines, each with its line end.
std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t nl = text.find('\n', pos);
    const std::size_t end = nl == std::string::npos ? text.size() : nl + 1;
    lines.push_back(text.substr(pos, end - pos));
    pos = end;
  }
  return lines;
}

std::string withoutEnd(std::string line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line;
}

}  // namespace

TEST_CASE("points: on generated programs an edit changes its one row and no other byte", "[teach]") {
  // Programs made of instructions, comments (some with Unicode), blank
  // lines, tabs, CR LF or LF, with or without a POINTS line and a final
  // line end; then every edit. Checked line by line, independently of the
  // layout rule: after an add, removing the new row gives the original
  // back (but for the line end the old last line gains); after a replace
  // or a rename only that row differs; after a delete only it is gone,
  // every other line as it was, line end included.
  std::uint64_t seed = 42;
  const auto next = [&seed] { return seed = seed * 6364136223846793005ULL + 1442695040888963407ULL, seed >> 33; };
  const std::vector<std::string> pieces = {"        MOVE 1 0 0 0 0", "; a comment ; with ; semicolons", "",
                                           "\t\tEND\t; tabbed", "loop:   GOTO loop", "; café ≠ ☃", "   "};
  for (int n = 0; n < 300; ++n) {
    const std::string eol = next() % 3 == 0 ? "\r\n" : "\n";
    std::string text;
    for (std::uint64_t k = next() % 5; k > 0; --k) text += pieces[next() % pieces.size()] + eol;
    text += "END" + eol;
    const bool section = next() % 4 != 0;
    int rows = 0;
    if (section) {
      text += (next() % 2 ? "POINTS" : "points   ; taught") + eol;
      for (std::uint64_t k = next() % 6; k > 0; --k) {
        if (next() % 3 == 0) text += pieces[1 + next() % 2] + eol;  // a comment or a blank line among the rows
        std::string row = "P" + std::to_string(rows++);
        for (int v = 0; v < 5; ++v) row += std::string(1 + next() % 3, next() % 5 == 0 ? '\t' : ' ') +
                                           std::to_string(static_cast<int>(next() % 2001) - 1000);
        if (next() % 3 == 0) row += "   ; note";
        text += row + eol;
      }
    }
    if (next() % 3 == 0 && text.ends_with(eol)) text.resize(text.size() - eol.size());  // no final line end
    INFO(text);
    const std::vector<std::string> before = linesOf(text);
    const std::vector<std::int32_t> values{7, -7, 77, -777, 7777};

    PointsText added(text);
    REQUIRE(added.add("NEW", values).empty());
    std::vector<std::string> after = linesOf(added.text());
    const std::size_t at = added.points().back().line;
    CHECK(added.points().back().values == values);
    after.erase(after.begin() + static_cast<std::ptrdiff_t>(at));
    if (!section) after.erase(after.begin() + static_cast<std::ptrdiff_t>(at) - 1);  // the POINTS line added
    REQUIRE(after.size() == before.size());
    for (std::size_t i = 0; i < before.size(); ++i) CHECK(withoutEnd(after[i]) == withoutEnd(before[i]));
    for (std::size_t i = 0; i + 1 < before.size(); ++i) CHECK(after[i] == before[i]);

    if (rows == 0) continue;
    const std::string name = "P" + std::to_string(next() % rows);
    PointsText replacedText(text), renamed(text), deleted(text);
    const std::size_t row = replacedText.points()[*replacedText.find(name)].line;
    REQUIRE(replacedText.replace(name, values).empty());
    REQUIRE(renamed.rename(name, "RENAMED_" + name).empty());
    REQUIRE(deleted.remove(name).empty());
    CHECK(replacedText.points()[*replacedText.find(name)].values == values);
    for (const PointsText* edited : {&replacedText, &renamed}) {
      const std::vector<std::string> lines = linesOf(edited->text());
      REQUIRE(lines.size() == before.size());
      for (std::size_t i = 0; i < before.size(); ++i)
        if (i != row) CHECK(lines[i] == before[i]);
    }
    std::vector<std::string> shorter = linesOf(deleted.text()), expected = before;
    expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(row));
    REQUIRE(shorter.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) CHECK(shorter[i] == expected[i]);
  }
}
