// The "; cell: NAME" directive: read by launch/ for every command, so the
// CLI and the language server check a program against the same robot;
// --cell on the command line wins over it.
#include <catch2/catch.hpp>

#include "launch/cell_directive.h"
#include "tools/lsp/uri.h"
#include "tests/lsp/lsp_session.h"
#include "tests/cli/cli_support.h"

using rs::launch::findCellDirective;

TEST_CASE("findCellDirective: the first whole-line cell directive comment", "[lsp][cell]") {
  const auto d = findCellDirective("        END\n  ;  CELL:   gantry-cell   trailing words\n; cell: other\n");
  REQUIRE(d);
  CHECK(d->name == "gantry-cell");
  CHECK(d->pos == rs::diag::Pos{2, 14});
  CHECK_FALSE(findCellDirective("END ; cell: x\n"));              // not a whole-line comment
  CHECK_FALSE(findCellDirective("; test: cell gantry-cell\n"));  // robotsim test's line, not this
  CHECK_FALSE(findCellDirective("; cell:\n"));
}

namespace {

// A program for the gantry (four motors X Z Y A): on the default robot
// (five motors) its MOVETO has the wrong number of values.
const std::string kGantryProgram = "; cell: gantry-cell\n        MOVETO -2800 2800 0 0\n        END\n";

}  // namespace

TEST_CASE("the CLI compiles for the cell the directive names", "[lsp][cell][cli]") {
  rs::testing::TempDir dir;
  const std::string f = dir.write("g.rsp", kGantryProgram);
  const auto r = rs::testing::runCli({"run", f});
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  // -2800/10 + 500 = 220, 2800/10 + 400 = 680: the gantry's tool centre point formula (examples/gantry_pick.rsp).
  CHECK(r.out.find("220") != std::string::npos);
}

TEST_CASE("the command line's --cell wins over the directive", "[lsp][cell][cli]") {
  rs::testing::TempDir dir;
  const std::string f = dir.write("g.rsp", kGantryProgram);
  const auto r = rs::testing::runCli({"check", f, "--cell", "scara-pick"});
  CHECK(r.code == 2);
  CHECK(r.err.find("MOVETO expects 5 values (one per motor: E D C B A), found 4") != std::string::npos);
}

TEST_CASE("a directive naming a description file beside the program", "[lsp][cell][cli]") {
  rs::testing::TempDir dir;
  const std::string robot = rs::testing::readBytes(std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/robots/gantry.rsd");
  dir.write("mine.rsd", robot);
  const std::string f = dir.write("g.rsp", "; cell: mine.rsd\n        MOVETO 0 0 0 0\n        END\n");
  const auto r = rs::testing::runCli({"check", f});
  CHECK(r.code == 0);
  CHECK(r.err.empty());
}

TEST_CASE("a directive naming an unknown cell is an error", "[lsp][cell][cli]") {
  rs::testing::TempDir dir;
  const std::string f = dir.write("g.rsp", "; cell: no-such-cell\n        END\n");
  const auto r = rs::testing::runCli({"check", f});
  CHECK(r.code == 2);
  CHECK(r.err.find("no-such-cell") != std::string::npos);
}

TEST_CASE("robotsim lsp --help explains the server", "[lsp][cli]") {
  const auto r = rs::testing::runCli({"lsp", "--help"});
  CHECK(r.code == 0);
  CHECK(r.out.find("Speaks the Language Server Protocol 3.17 over stdin and stdout") != std::string::npos);
  CHECK(r.out.find("--stdio") != std::string::npos);
}

TEST_CASE("lsp: go to definition of a directive's file gives a normal URI", "[lsp][cell]") {
  // Issue 26: "; cell: ../cell.rsd" in sub/ went to ".../sub/../cell.rsd".
  rs::testing::TempDir dir;
  std::filesystem::create_directories(dir.path() / "sub");
  dir.write("cell.rsd", "WORKCELL mine\n  ROBOT rhino-scara AT 0 0 0\nEND\n");
  const std::string program = dir.write("sub/prog.rsp", "; cell: ../cell.rsd\n        END\n");
  rs::testing::LspSession s;
  s.initialize();
  const std::string uri = rs::lsp::uriOfPath(program);
  s.open(uri, rs::testing::readBytes(program));
  s.idle();
  CHECK(s.diagnostics(uri) == rs::lsp::Json::array());  // the cell was found and loaded
  const rs::lsp::Json d = s.result("textDocument/definition", rs::testing::LspSession::at(uri, 0, 10));
  REQUIRE(d.is_object());
  CHECK(d["uri"] == "file://" + (dir.path() / "cell.rsd").lexically_normal().string());
  CHECK(d["uri"].get<std::string>().find("/..") == std::string::npos);
  // On the workcell's name, the one the file defines (line 1: "WORKCELL mine"), not the file's top.
  CHECK(d["range"] == rs::testing::LspSession::range(0, 9, 0, 13));
  // Made absolute and normal whatever the path: one file, one URI.
  CHECK(rs::lsp::uriOfPath("/a/b/../c/./d.rsd") == "file:///a/c/d.rsd");
  CHECK(rs::lsp::uriOfPath("/a b/%.rsd") == "file:///a%20b/%25.rsd");
}
