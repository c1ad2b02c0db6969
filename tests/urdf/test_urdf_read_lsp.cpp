// URDF in the language server: an open .urdf file's diagnostics at its XML
// lines; a program whose `; cell:` names a URDF file is checked against
// that robot, hover on the name shows its D-H table, and a bad URDF cell is
// an error at the directive that says where in the XML.
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tests/urdf/urdf_read_test_util.h"
#include "tools/lsp/uri.h"

using rs::lsp::Json;
using rs::testing::LspSession;

TEST_CASE("urdf lsp: an open URDF file's diagnostics come from the URDF reader at the XML line", "[urdf][lsp]") {
  LspSession s;
  s.initialize();
  const std::string path = urdftest::dataRead("unknown_type.urdf").string();
  const std::string uri = rs::lsp::uriOfPath(path);
  s.open(uri, rs::testing::readBytes(path), "urdf");
  s.idle();
  const Json d = s.diagnostics(uri);
  REQUIRE(d.size() == 1);
  CHECK(d[0]["range"]["start"]["line"] == 3);  // 0-based: the file's line 4
  CHECK(d[0]["severity"] == 1);
  CHECK(d[0]["message"].get<std::string>().find("unknown type 'screw'") != std::string::npos);
  // The editor's text counts, saved or not: fixed, the error goes.
  std::string fixed = rs::testing::readBytes(path);
  fixed.replace(fixed.find("screw"), 5, "continuous");
  fixed.replace(fixed.find("</joint>"), 0, "<axis xyz=\"0 0 1\"/>");
  s.notify("textDocument/didChange",
           {{"textDocument", {{"uri", uri}, {"version", 2}}}, {"contentChanges", Json::array({{{"text", fixed}}})}});
  s.idle();
  CHECK(s.diagnostics(uri) == Json::array());
}

TEST_CASE("urdf lsp: a program's cell may be a URDF file - hover on its name shows the D-H table", "[urdf][lsp]") {
  rs::testing::TempDir dir;
  std::filesystem::copy_file(urdftest::dataRead("ur5_dh.urdf"), dir.path() / "ur5_dh.urdf");
  const std::string program = "; cell: ur5_dh.urdf\n        MOVETO 0 0 0 0 0 0\n        END\n";
  const std::string file = dir.write("p.rsp", program);
  LspSession s;
  s.initialize();
  const std::string uri = rs::lsp::uriOfPath(file);
  s.open(uri, program);
  s.idle();
  // Six motors: a MOVETO with six values is right for the UR5.
  for (const Json& d : s.diagnostics(uri)) CHECK(d["severity"] != 1);
  const Json h = s.result("textDocument/hover", LspSession::at(uri, 0, 10));
  REQUIRE_FALSE(h.is_null());
  const std::string text = h["contents"]["value"];
  CHECK(text.find("from URDF file") != std::string::npos);
  CHECK(text.find("| axis | type |") != std::string::npos);
  CHECK(text.find("| 4 | revolute | θ4 | 90 | 0 | 109.15 |") != std::string::npos);
}

TEST_CASE("urdf lsp: a bad URDF cell is an error at the directive that says where in the XML", "[urdf][lsp]") {
  rs::testing::TempDir dir;
  std::filesystem::copy_file(urdftest::dataRead("zero_axis.urdf"), dir.path() / "bad.urdf");
  const std::string program = "; cell: bad.urdf\n        END\n";
  const std::string file = dir.write("p.rsp", program);
  LspSession s;
  s.initialize();
  const std::string uri = rs::lsp::uriOfPath(file);
  s.open(uri, program);
  s.idle();
  const Json d = s.diagnostics(uri);
  REQUIRE(d.size() >= 1);
  CHECK(d[0]["range"]["start"]["line"] == 0);
  const std::string message = d[0]["message"];
  CHECK(message.find("axis of zero length") != std::string::npos);
  CHECK(message.find("bad.urdf:4:3") != std::string::npos);
}
