// Issue 36: in a cell of several robots a program runs on the robot it
// names (--robot LABEL, else its `; robot: LABEL` line, else the robot
// whose PROGRAM it is, else the first), compiled for that robot; a label the
// cell lacks is an error at its place with the cell's labels. The robots
// stand 3000 apart on x, so the tool centre's x says which one ran (the
// XR-4 at home has its tool centre at x = 238.1 from its base, as the
// one-robot runs print). At the end, issue 35: a deadlock on a wired input
// names the robot's own wire.
#include <catch2/catch.hpp>

#include <string>

#include "tests/cli/cli_support.h"
#include "tests/lsp/lsp_session.h"
#include "tools/lsp/uri.h"

namespace robot_choice_test {

const char* const kCell =
    "WORKCELL two\n"
    "  ROBOT rhino-xr4 AT 0 750 0 AS left\n"
    "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\n"
    "END\n";

rs::testing::CliResult runIn(const rs::testing::TempDir& dir, const std::string& file, std::vector<std::string> more) {
  std::vector<std::string> args{"run", dir.file(file), "--cell", dir.file("c.rsd"), "--format=json"};
  args.insert(args.end(), more.begin(), more.end());
  return rs::testing::runCli(args);
}

// The tool centre's x in a JSON summary: a run of one robot's, or in a
// run of several (r.rsp is right's PROGRAM, so it runs too) the robot
// whose program is `file`.
double tcpX(const std::string& json, const std::string& file = "") {
  const auto j = rs::lsp::Json::parse(json);
  if (!j.contains("robots")) return j.at("tcp").at(0).get<double>();
  for (const auto& r : j.at("robots"))
    if (r.at("program").get<std::string>().ends_with(file)) return r.at("tcp").at(0).get<double>();
  FAIL("no robot runs " << file);
  return 0;
}

}  // namespace robot_choice_test

using namespace robot_choice_test;

TEST_CASE("robot choice: --robot, the 'robot:' comment line and the cell's PROGRAM pick the robot", "[labels][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("p.rsp", "        END\n");
  dir.write("r.rsp", "        END\n");
  dir.write("d.rsp", "; robot: RIGHT\n        END\n");

  const auto first = runIn(dir, "p.rsp", {});
  REQUIRE(first.code == 0);
  const double home = tcpX(first.out, "p.rsp");
  CHECK(home < 1000);  // the first robot, at x 0

  const auto option = runIn(dir, "p.rsp", {"--robot", "right"});
  REQUIRE(option.code == 0);
  CHECK(tcpX(option.out, "p.rsp") == Approx(home + 3000));
  const auto directive = runIn(dir, "d.rsp", {});
  REQUIRE(directive.code == 0);
  CHECK(tcpX(directive.out, "d.rsp") == Approx(home + 3000));
  const auto program = runIn(dir, "r.rsp", {});  // right's PROGRAM
  REQUIRE(program.code == 0);
  CHECK(tcpX(program.out, "r.rsp") == Approx(home + 3000));
  const auto overridden = runIn(dir, "d.rsp", {"--robot", "left"});  // --robot wins over the line
  REQUIRE(overridden.code == 0);
  CHECK(tcpX(overridden.out, "d.rsp") == Approx(home));
}

TEST_CASE("robot choice: a label the cell lacks is an error at its place", "[labels][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("r.rsp", "        END\n");
  dir.write("n.rsp", "; robot: nobody\n        END\n");
  const auto directive = rs::testing::runCli({"check", dir.file("n.rsp"), "--cell", dir.file("c.rsd")});
  INFO(directive.err);
  CHECK(directive.code == 2);
  CHECK(directive.err.find("n.rsp:1:10: error: this program's '; robot:' line names robot `nobody`, but workcell two "
                           "has no robot labelled so") != std::string::npos);
  CHECK(directive.err.find("hint: the cell's robots are `left`, `right`") != std::string::npos);
  const auto option = rs::testing::runCli({"run", dir.file("n.rsp"), "--robot", "x"});
  CHECK(option.code == 2);
  CHECK(option.err.find("--robot: error: --robot names a robot of a cell, but the program runs on no cell") !=
        std::string::npos);
}

TEST_CASE("robot choice: the language server checks against the robot a 'robot:' comment names", "[labels][robots][lsp]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("r.rsp", "        END\n");
  const std::string good = "; cell: c.rsd\n; robot: right\n        END\n";
  const std::string bad = "; cell: c.rsd\n; robot: lefty\n        END\n";
  const std::string goodUri = rs::lsp::uriOfPath(dir.write("g.rsp", good));
  const std::string badUri = rs::lsp::uriOfPath(dir.write("b.rsp", bad));
  rs::testing::LspSession s;
  s.initialize();
  s.open(goodUri, good);
  s.open(badUri, bad);
  s.idle();
  bool unknownInGood = false;
  for (const auto& d : s.diagnostics(goodUri)) unknownInGood |= d.value("code", "") == "unknown-robot";
  CHECK_FALSE(unknownInGood);
  const rs::lsp::Json* found = nullptr;
  const rs::lsp::Json diags = s.diagnostics(badUri);
  for (const auto& d : diags)
    if (d.value("code", "") == "unknown-robot") found = &d;
  REQUIRE(found);
  CHECK((*found)["range"]["start"]["line"] == 1);
  CHECK((*found)["range"]["start"]["character"] == 9);  // after "; robot: "
  CHECK((*found)["message"].get<std::string>().find("names robot `lefty`") != std::string::npos);
}

TEST_CASE("robot choice: go to definition from a label to its ROBOT line, from PROGRAM to its file",
          "[labels][robots][lsp]") {
  rs::testing::TempDir dir;
  const std::string cell =
      "WORKCELL two\n"                                            // 0
      "  ROBOT rhino-xr4 AT 0 750 0 AS left\n"                    // 1: `left` at 32..36 (0-based, end excluded)
      "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\n"  // 2: `right` at 35..40, `r.rsp` at 49
      "  WIRE left.OUT 1 TO right.IN 2\n"                         // 3: `left` at 7, `right` at 22
      "END\n";
  const std::string cellUri = rs::lsp::uriOfPath(dir.write("c.rsd", cell));
  const std::string rUri = rs::lsp::uriOfPath(dir.write("r.rsp", "        END\n"));
  const std::string program = "; cell: c.rsd\n; robot: left\n        END\n";  // `left` at line 1, 9..13
  const std::string programUri = rs::lsp::uriOfPath(dir.write("p.rsp", program));
  rs::testing::LspSession s;
  s.initialize();
  s.open(cellUri, cell, "robotsim-description");
  s.open(programUri, program);
  s.idle();
  using rs::testing::LspSession;
  const auto at = [&](const std::string& uri, unsigned line, unsigned ch) {
    return s.result("textDocument/definition", LspSession::at(uri, line, ch));
  };
  CHECK(at(cellUri, 3, 8) == rs::lsp::Json({{"uri", cellUri}, {"range", LspSession::range(1, 32, 1, 36)}}));
  CHECK(at(cellUri, 3, 23) == rs::lsp::Json({{"uri", cellUri}, {"range", LspSession::range(2, 35, 2, 40)}}));
  CHECK(at(cellUri, 2, 51) == rs::lsp::Json({{"uri", rUri}, {"range", LspSession::range(0, 0, 0, 0)}}));
  CHECK(at(programUri, 1, 10) == rs::lsp::Json({{"uri", cellUri}, {"range", LspSession::range(1, 32, 1, 36)}}));
}

TEST_CASE("robot choice: wires and signals act for the robot the run drives only", "[labels][robots][devices]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd",
            "WORKCELL two\n"
            "  ROBOT rhino-xr4 AT 0 750 0 AS left\n"
            "  ROBOT rhino-xr4 AT 3000 750 0 AS right\n"
            "  WIRE left.OUT 1 TO right.IN 2\n"
            "  WIRE right.OUT 1 TO right.IN 3\n"
            "END\n");
  dir.write("p.rsp", "        OUTSIG 1 ON\n        WAITFOR 3 ON\n        END\n");
  // On right: its OUT 1 drives its IN 3; left runs nothing, so IN 2 stays OFF.
  const auto right = runIn(dir, "p.rsp", {"--robot", "right"});
  INFO(right.err);
  REQUIRE(right.code == 0);
  const auto j = rs::lsp::Json::parse(right.out);
  CHECK(j["inputs"][2] == true);
  CHECK(j["inputs"][1] == false);
  // On left: no wire ends at left's IN 3, so its WAITFOR never ends.
  const auto left = runIn(dir, "p.rsp", {"--robot", "left"});
  CHECK(left.code == 1);
  CHECK(rs::lsp::Json::parse(left.out)["diagnostics"][0]["code"] == "deadlock");
}

TEST_CASE("a wire without AFTER answers a WAITFOR at the same instant, not a deadlock", "[cell][devices]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", "WORKCELL one\n  ROBOT rhino-xr4 AT 0 750 0\n  WIRE OUT 1 TO IN 3\nEND\n");
  dir.write("p.rsp", "        OUTSIG 1 ON\n        WAITFOR 3 ON\n        END\n");
  const auto r = runIn(dir, "p.rsp", {});
  INFO(r.err);
  CHECK(r.code == 0);
  const auto j = rs::lsp::Json::parse(r.out);
  CHECK(j["status"] == "finished");
  CHECK(j["time"] == 0.0);  // the wire's change is at the OUTSIG's instant
  CHECK(j["inputs"][2] == true);
}

namespace robot_choice_test {

// A deadlock on a wired input says what drives it (launch/run_diagnostics.cpp),
// instead of the --input and --stimuli hint of an input nothing drives. The
// time is the program's DELAY (past the feeder's last tick, at 5 s: nothing
// is left on the clock after it); the line numbers are counted below:
// a part fed at 0 s beside the beam, which nothing moves; the beam is wired to input 1.
const std::string kBeamCell =
    "OBJECT blk\n  PART\n  BOX 0 10 10 0 10 0\nEND\n"  // 1..4
    "WORKCELL c\n"                                    // 5
    "  ROBOT rhino-xr4 AT 0 750 0\n"                  // 6
    "  FEEDER f blk AT 200 700 30 EVERY 5 COUNT 1\n"  // 7
    "  SENSOR eye BEAM 100 705 0  100 705 60\n"       // 8
    "  WIRE eye TO IN 1\n"                            // 9
    "  WIRE ON TO IN 2 INVERTED\n"                    // 10
    "END\n";

}  // namespace robot_choice_test

using robot_choice_test::kBeamCell;

TEST_CASE("run: a deadlock on a wired input says what drives it", "[cli][devices]") {
  rs::testing::TempDir dir;
  const std::string cell = dir.write("c.rsd", kBeamCell);
  const std::string beam = dir.write("beam.rsp", "        DELAY 7\n        WAITFOR 1 ON\n        END\n");
  const auto r = rs::testing::runCli({"run", beam, "--cell", cell});
  INFO(r.out << r.err);
  CHECK(r.code != 0);
  CHECK(r.err.find(beam + ":2:9: error: deadlock: input 1 never turns ON") != std::string::npos);
  CHECK(r.err.find("hint: input 1 is wired from sensor eye (line 9 of workcell c); no part crosses it after 7.000 s\n") !=
        std::string::npos);
  CHECK(r.err.find("--stimuli") == std::string::npos);

  const std::string held = dir.write("held.rsp", "        WAITFOR 2 ON\n        END\n");
  const auto h = rs::testing::runCli({"run", held, "--cell", cell});
  INFO(h.out << h.err);
  CHECK(h.err.find("hint: input 2 is wired from ON INVERTED (line 10 of workcell c): always OFF\n") != std::string::npos);

  // An input with no wire keeps the hint it had.
  const std::string none = dir.write("none.rsp", "        WAITFOR 3 ON\n        END\n");
  const auto n = rs::testing::runCli({"run", none, "--cell", cell});
  CHECK(n.err.find("hint: inputs change only by --input N=ON@SECONDS or a --stimuli file\n") != std::string::npos);
}

TEST_CASE("a deadlock's wire is the robot's own: another robot's wired input is not named", "[cell][devices]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", "WORKCELL two\n  ROBOT rhino-xr4 AT 0 750 0 AS left\n  ROBOT rhino-xr4 AT 3000 750 0 AS right\n"
                     "  WIRE ON TO left.IN 1 INVERTED\n  WIRE OFF TO right.IN 1\nEND\n");
  dir.write("p.rsp", "        WAITFOR 1 ON\n        END\n");
  const auto left = rs::testing::runCli({"run", dir.file("p.rsp"), "--cell", dir.file("c.rsd"), "--robot", "left"});
  CHECK(left.err.find("hint: input 1 is wired from ON INVERTED (line 4 of workcell two): always OFF\n") != std::string::npos);
  const auto right = rs::testing::runCli({"run", dir.file("p.rsp"), "--cell", dir.file("c.rsd"), "--robot", "right"});
  CHECK(right.err.find("hint: input 1 is wired from OFF (line 5 of workcell two): always OFF\n") != std::string::npos);
}
