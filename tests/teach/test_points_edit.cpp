// Lossless editing of the POINTS section (teach/points_edit.h) and the
// program file's guarded write (teach/program_file.h).
//
// Every expected text below was worked out by hand from the layout rule
// (the column arithmetic is in the comments), not copied from the
// program's output. The compile tests check with the compiler itself that
// an edit changes the image's points and nothing else.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/file_io.h"
#include "compiler/compiler.h"
#include "launch/program.h"
#include "teach/points_edit.h"
#include "teach/program_file.h"
#include "tests/cli/cli_support.h"

namespace {

using rs::teach::PointsText;

// Columns (0-based): HOME's values end at 11, 17, 23, 28, 33; so do PICK's
// (right-aligned, as in docs/language.md); PICK's comment starts at 36.
const std::string kProgram =
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
  const PointsText p(kProgram);
  CHECK(p.text() == kProgram);
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
  PointsText p(kProgram);
  REQUIRE(p.replace("pick", v({12, -3, 1500, 0, 90})).empty());
  // "PICK" + 5 spaces + "12" ends at 11; "-3" ends at 17 (4 spaces); "1500"
  // at 23 (2); "0" at 28 (4); "90" at 33 (3); the comment back at 36 (3).
  CHECK(p.text() == replaced(kProgram, "PICK    400  -200  -150  250    0   ; over the block",
                             "PICK     12    -3  1500    0   90   ; over the block"));
}

TEST_CASE("points: a taught point goes after the last one, aligned with it", "[teach]") {
  PointsText p(kProgram);
  REQUIRE(p.add("NEW", v({1, 2, 3, 4, 5})).empty());
  // "NEW" + 7 spaces + "1" ends at 11; then 5, 5, 4, 4 spaces.
  CHECK(p.text() == replaced(kProgram, "over the block\n", "over the block\nNEW       1     2     3    4    5\n"));
  // Too wide for its column: one space ("WIDE 12345678" is 13 wide), and
  // the next column catches up: "2" ends at 17 again (3 spaces).
  PointsText q(kProgram);
  REQUIRE(q.add("WIDE", v({12345678, 2, 3, 4, 5})).empty());
  CHECK(q.text() == replaced(kProgram, "over the block\n", "over the block\nWIDE 12345678   2     3    4    5\n"));
}

TEST_CASE("points: delete and rename touch one row", "[teach]") {
  PointsText p(kProgram);
  REQUIRE(p.remove("home").empty());
  CHECK(p.text() == replaced(kProgram, "HOME      0     0     0    0    0\n", ""));
  PointsText r(kProgram);
  REQUIRE(r.rename("PICK", "PK").empty());
  // "PK" + 6 spaces: 400 still ends at 11; the rest of the row as it was.
  CHECK(r.text() == replaced(kProgram, "PICK    400", "PK      400"));
  PointsText w(kProgram);
  REQUIRE(w.rename("PICK", "GRAB_BLOCK").empty());
  // "GRAB_BLOCK 400" is 14 wide: -200 and -150 get one space each (ends 19,
  // 24), 250 ends at 28 again (one space), 0 at 33 (4), the comment at 36.
  CHECK(w.text() == replaced(kProgram, "PICK    400  -200  -150  250    0",
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
  REQUIRE(q.remove("P2").empty());
  CHECK(q.text() == "MOVE 1 0 0 0 0\r\nEND\r\nPOINTS\r\nP1 0 1 2 3 4");
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
  PointsText p(kProgram);
  CHECK(p.add("home", v({0, 0, 0, 0, 0})) == "there is a point HOME already (line 7)");
  CHECK(p.add("moveto", v({0, 0, 0, 0, 0})) == "MOVETO is an instruction: it cannot name a point");
  CHECK(p.add("Points", v({0, 0, 0, 0, 0})) == "POINTS is a reserved word: it cannot name a point");
  CHECK(p.add("9lives", v({0, 0, 0, 0, 0})) == "a point name is letters, digits and '_', not starting with a digit");
  CHECK(p.add("", v({0, 0, 0, 0, 0})) == "a point needs a name");
  CHECK(p.rename("PICK", "home") == "there is a point HOME already (line 7)");
  CHECK(p.replace("NOPE", v({0, 0, 0, 0, 0})) == "there is no point NOPE");
  CHECK(p.remove("NOPE") == "there is no point NOPE");
  CHECK(p.text() == kProgram);
}

TEST_CASE("points: the compiled image differs in the changed points only", "[teach]") {
  const std::string program = replaced(kProgram, "MOVEP PICK", "MOVEP HOME");
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
  const std::string path = dir.write("p.rsp", kProgram);
  std::string error;
  std::optional<rs::teach::ProgramFile> f = rs::teach::ProgramFile::load(path, error);
  REQUIRE(f);
  CHECK(f->hash() == rs::teach::textHash(kProgram));
  REQUIRE(f->change([](PointsText& p) { return p.add("NEW", v({1, 2, 3, 4, 5})); }).empty());
  const std::string once = replaced(kProgram, "over the block\n", "over the block\nNEW       1     2     3    4    5\n");
  CHECK(*rs::base::readFile(path, 1 << 20).bytes == once);
  CHECK(*rs::base::readFile(path + ".bak", 1 << 20).bytes == kProgram);
  REQUIRE(f->change([](PointsText& p) { return p.remove("NEW"); }).empty());
  CHECK(*rs::base::readFile(path, 1 << 20).bytes == kProgram);
  CHECK(*rs::base::readFile(path + ".bak", 1 << 20).bytes == kProgram);  // the file as the session found it
  CHECK(!std::filesystem::exists(path + ".tmp"));
  // Someone edits the file: the next write is refused and their text stays.
  const std::string theirs = kProgram + "; edited elsewhere\n";
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
