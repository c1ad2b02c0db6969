// Descriptions (.rsd) and stimuli (.stim) in the language server: symbols,
// hover (a colour, a robot link's D-H row), definition across files,
// diagnostics.
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

namespace {

const std::string kStdlibRoot = std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib";

unsigned lineOf(const std::string& text, const std::string& start) { return LspSession::lineOf(text, start); }

struct OpenFile {
  LspSession s;
  std::string uri, text;
  OpenFile(const std::string& path, const std::string& languageId) : uri(rs::lsp::uriOfPath(path)), text(rs::testing::readBytes(path)) {
    s.initialize();
    s.open(uri, text, languageId);
    s.idle();
  }
  Json hover(unsigned line, unsigned character) {
    const Json h = s.result("textDocument/hover", LspSession::at(uri, line, character));
    return h.is_null() ? h : h["contents"]["value"];
  }
};

}  // namespace

TEST_CASE("rsd: a workcell's robot goes to its file on the library path", "[lsp][rsd]") {
  OpenFile f(kStdlibRoot + "/workcells/scara-pick.rsd", "robotsim-description");
  CHECK(f.s.diagnostics(f.uri) == Json::array());
  const unsigned line = lineOf(f.text, "  ROBOT rhino-scara");
  // On the robot's definition in that file, "ROBOT rhino-scara": the name's range, not the file's top.
  const std::string robotFile = kStdlibRoot + "/robots/rhino-scara.rsd";
  const unsigned robotLine = lineOf(rs::testing::readBytes(robotFile), "ROBOT rhino-scara");
  CHECK(robotLine > 100);
  CHECK(f.s.result("textDocument/definition", LspSession::at(f.uri, line, 10)) ==
        Json({{"uri", rs::lsp::uriOfPath(robotFile)}, {"range", LspSession::range(robotLine, 6, robotLine, 17)}}));
  const Json symbols = f.s.result("textDocument/documentSymbol", {{"textDocument", {{"uri", f.uri}}}});
  REQUIRE(symbols.size() == 1);
  CHECK(symbols[0]["name"] == "scara-pick");
  CHECK(symbols[0]["detail"] == "workcell");
  CHECK(symbols[0]["selectionRange"] == LspSession::range(lineOf(f.text, "WORKCELL"), 9, lineOf(f.text, "WORKCELL"), 19));
}

TEST_CASE("rsd: hover names a colour and shows a link's D-H row", "[lsp][rsd]") {
  OpenFile f(kStdlibRoot + "/robots/rhino-scara.rsd", "robotsim-description");
  CHECK(f.s.diagnostics(f.uri) == Json::array());
  // BROWN is EGA colour 6.
  CHECK(f.hover(lineOf(f.text, "  COLOR BROWN"), 10) == "colour **BROWN** (EGA colour 6)");
  // Rows 1 and 2 of the table the file's header derives by hand: 1 revolute
  // th1 alpha 0 a 105 d 200; 2 revolute th2 alpha 180 a 120 d 0.
  CHECK(f.hover(lineOf(f.text, "  LINK rhino_scara_link1"), 10) ==
        "link `rhino_scara_link1`: link 1 of rhino-scara\n\n"
        "D-H row 1 (revolute): theta = theta1, alpha = 0, a = 105, d = 200 (home 0)");
  CHECK(f.hover(lineOf(f.text, "  LINK rhino_scara_link2"), 10) ==
        "link `rhino_scara_link2`: link 2 of rhino-scara\n\n"
        "D-H row 2 (revolute): theta = theta2, alpha = 180, a = 120, d = 0 (home 0)");
  CHECK(f.hover(lineOf(f.text, "  LINK rhino_scara_base "), 10) == "link `rhino_scara_base`: the base of rhino-scara (frame 0)");
  // A link defined in the same file: definition goes there.
  const unsigned def = lineOf(f.text, "LINK rhino_scara_link1");
  CHECK(f.s.result("textDocument/definition", LspSession::at(f.uri, lineOf(f.text, "  LINK rhino_scara_link1"), 10)) ==
        Json({{"uri", f.uri}, {"range", LspSession::range(def, 5, def, 22)}}));
}

TEST_CASE("rsd: a syntax error is a diagnostic", "[lsp][rsd]") {
  LspSession s;
  s.initialize();
  s.open("file:///x/bad.rsd", "LINK a\n  FROB 1 2 3\nEND\n", "robotsim-description");
  s.idle();
  const Json d = s.diagnostics("file:///x/bad.rsd");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["range"]["start"] == Json({{"line", 1}, {"character", 2}}));
  CHECK(d[0]["severity"] == 1);
}

TEST_CASE("stim: diagnostics, symbols and hover in words", "[lsp][stim]") {
  OpenFile f(std::string(ROBOTSIM_SOURCE_DIR) + "/examples/pick_and_place.stim", "robotsim-stimuli");
  CHECK(f.s.diagnostics(f.uri) == Json::array());
  CHECK(f.hover(lineOf(f.text, "at 0 input 2 on"), 3) == "at 0 s input 2 turns ON");
  CHECK(f.hover(lineOf(f.text, "when output 1 on then input 1 on after 1.5"), 3) ==
        "whenever output 1 turns ON, input 1 turns ON 1.5 s later");
  const Json symbols = f.s.result("textDocument/documentSymbol", {{"textDocument", {{"uri", f.uri}}}});
  REQUIRE(symbols.size() == 5);
  CHECK(symbols[0]["name"] == "when output 1 on then input 1 on after 1.5");
  LspSession s;
  s.initialize();
  s.open("file:///x/bad.stim", "at 1 input 9 on\n", "robotsim-stimuli");
  s.idle();
  const Json d = s.diagnostics("file:///x/bad.stim");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["range"]["start"]["line"] == 0);
}

TEST_CASE("rsd: an unsaved description is checked and hovered as the editor holds it", "[lsp][rsd]") {
  // Paths with no file behind them: only the editor has these texts.
  const std::string dir = "/nonexistent-robotsim-lsp";
  LspSession s;
  s.initialize();
  const std::string cell = rs::lsp::uriOfPath(dir + "/cell.rsd");
  s.open(cell, "WORKCELL w\n  ROBOT no-such-robot AT 0 0 0\nEND\n", "robotsim-description");
  s.idle();
  const Json d = s.diagnostics(cell);
  REQUIRE(d.size() == 1);
  CHECK(d[0]["message"].get<std::string>().find("no-such-robot") != std::string::npos);
  CHECK(d[0]["range"]["start"]["line"] == 1);
  // The stdlib robot's text under a new, unsaved name: the same D-H rows.
  const std::string text = rs::testing::readBytes(kStdlibRoot + "/robots/rhino-scara.rsd");
  const std::string robot = rs::lsp::uriOfPath(dir + "/my-scara.rsd");
  s.open(robot, text, "robotsim-description");
  s.idle();
  CHECK(s.diagnostics(robot) == Json::array());
  const Json h = s.result("textDocument/hover", LspSession::at(robot, lineOf(text, "  LINK rhino_scara_link2"), 10));
  REQUIRE(h.is_object());
  CHECK(h["contents"]["value"] ==
        "link `rhino_scara_link2`: link 2 of rhino-scara\n\n"
        "D-H row 2 (revolute): theta = theta2, alpha = 180, a = 120, d = 0 (home 0)");
}

TEST_CASE("rsd: hover on a device, and a wire's sensor goes to its SENSOR line", "[lsp][rsd][devices]") {
  OpenFile f(kStdlibRoot + "/workcells/adept-cell.rsd", "robotsim-description");
  CHECK(f.s.diagnostics(f.uri) == Json::array());
  const unsigned wire = lineOf(f.text, "  WIRE     eye");
  const unsigned sensor = lineOf(f.text, "  SENSOR   eye");
  // "  WIRE     eye": the name at characters 11..14, on both lines.
  CHECK(f.s.result("textDocument/definition", LspSession::at(f.uri, wire, 12)) ==
        Json({{"uri", f.uri}, {"range", LspSession::range(sensor, 11, sensor, 14)}}));
  const std::string beam = "sensor `eye`: a beam from (300, 520, 440) to (300, 520, 760); on while it sees parts across it";
  CHECK(f.hover(wire, 12) == beam);
  CHECK(f.hover(sensor, 12) == beam);
  CHECK(f.hover(lineOf(f.text, "  CONVEYOR outfeed"), 12) ==
        "conveyor `outfeed`: runs its belt at 100 length units per second always");
  // The CONVEYOR's object: its AS name on the OBJECT line.
  const unsigned object = lineOf(f.text, "  OBJECT conveyor   AT -750 0 -450");
  const std::size_t as = f.text.find("outfeed", f.text.find("AT -750 0 -450")) - f.text.find("  OBJECT conveyor   AT -750 0 -450");
  CHECK(f.s.result("textDocument/definition", LspSession::at(f.uri, lineOf(f.text, "  CONVEYOR outfeed"), 12)) ==
        Json({{"uri", f.uri}, {"range", LspSession::range(object, static_cast<unsigned>(as), object, static_cast<unsigned>(as + 7))}}));
}

TEST_CASE("rsd: a device line's mistakes are diagnostics", "[lsp][rsd][devices]") {
  rs::testing::TempDir dir;
  const std::string path = dir.write("c.rsd", "OBJECT o\n  BOX 0 10 10 0 10 0\nEND\nWORKCELL c\n  OBJECT o AT 0 0 0\n"
                                               "  WIRE nosuch TO IN 1\n  SINK s ZONE 0 0 1 0 1 0\nEND\n");
  OpenFile f(path, "robotsim-description");
  const Json d = f.s.diagnostics(f.uri);
  REQUIRE(d.size() == 1);  // the SINK's shape error; names are resolved once the file reads
  CHECK(d[0]["message"].get<std::string>().rfind("the ZONE has no volume", 0) == 0);
  CHECK(d[0]["range"]["start"]["line"] == 6);
  const std::string path2 = dir.write("d.rsd", "OBJECT o\n  BOX 0 10 10 0 10 0\nEND\nWORKCELL c\n  OBJECT o AT 0 0 0\n"
                                                "  WIRE nosuch TO IN 1\nEND\n");
  OpenFile g(path2, "robotsim-description");
  const Json e = g.s.diagnostics(g.uri);
  REQUIRE(e.size() == 1);
  CHECK(e[0]["message"] == "unknown sensor 'nosuch'\nhint: a signal is a SENSOR's name (declared in this WORKCELL), OUT n, LABEL.OUT n, ON or OFF");
  CHECK(e[0]["range"] == LspSession::range(5, 7, 5, 13));
}

TEST_CASE("rsd: a device line's hint reaches the editor: the name meant, the keyword meant", "[lsp][rsd][devices]") {
  rs::testing::TempDir dir;
  const std::string cell = "OBJECT o\n  BOX 0 10 10 0 10 0\nEND\nWORKCELL c\n  OBJECT o AT 0 0 0\n"
                           "  SENSOR eye ZONE 0 10 20 10 10 0\n";
  OpenFile f(dir.write("c.rsd", cell + "  WIRE ey TO IN 1\nEND\n"), "robotsim-description");
  const Json d = f.s.diagnostics(f.uri);
  REQUIRE(d.size() == 1);
  CHECK(d[0]["message"] == "unknown sensor 'ey'\nhint: did you mean 'eye'?");
  CHECK(d[0]["range"] == LspSession::range(6, 7, 6, 9));
  // "  WIRE eye TO IN 1 INVERTD": the word after the line at character 19.
  OpenFile g(dir.write("d.rsd", cell + "  WIRE eye TO IN 1 INVERTD\nEND\n"), "robotsim-description");
  const Json e = g.s.diagnostics(g.uri);
  REQUIRE(e.size() == 1);
  CHECK(e[0]["message"] == "expected the end of the WIRE line, found 'INVERTD'\nhint: did you mean 'INVERTED'?");
  CHECK(e[0]["range"]["start"] == Json({{"line", 6}, {"character", 19}}));
}
