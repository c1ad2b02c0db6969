// Issue 36, the static part: a WORKCELL ROBOT line's AS LABEL and PROGRAM
// FILE, signals and wires naming a robot by its label (LABEL.OUT n,
// LABEL.IN n), and their mistakes, each at its place with a hint; two
// robots that overlap at home are a warning naming both. Columns counted
// by hand (1-based) from the lines below.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "tests/cli/cli_support.h"
#include "tests/models/description_errors_support.h"

namespace robot_labels_test {

using rs::testing::lines;
using rs::testing::TempDir;

struct Built {
  std::optional<rs::workcell::Workcell> cell;
  std::vector<rs::diag::Diagnostic> diagnostics;
};

// The cell in c.rsd of `dir`, with the library's robots on the path.
Built build(const TempDir& dir, const std::vector<std::string>& body) {
  std::vector<std::string> all{"WORKCELL two"};  // line 1; the body from line 2
  all.insert(all.end(), body.begin(), body.end());
  all.push_back("END");
  dir.write("c.rsd", lines(all));
  rs::compiler::Library lib(rs::compiler::librarySearchPath({dir.path().string()}));
  Built b;
  b.cell = lib.workcell(dir.file("c.rsd"));
  b.diagnostics = lib.diagnostics();
  return b;
}

// The first diagnostic (an error when `error`), which must exist.
const rs::diag::Diagnostic& first(const Built& b, bool error = true) {
  for (const rs::diag::Diagnostic& d : b.diagnostics)
    if ((d.severity == rs::diag::Severity::Error) == error) return d;
  FAIL("no such diagnostic");
  return b.diagnostics.front();
}

}  // namespace robot_labels_test

using namespace robot_labels_test;

TEST_CASE("robot labels: AS and PROGRAM are kept, labelled signals resolve", "[models][labels]") {
  TempDir dir;
  dir.write("left.rsp", "        END\n");
  const Built b = build(dir, {
                                 "  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM left.rsp",  // 2
                                 "  ROBOT rhino-xr4 AT 3000 750 0 as Right",               // 3
                                 "  WIRE left.OUT 1 TO right.IN 2",                        // 4
                                 "  WIRE OFF TO LEFT.in 3 INVERTED",                       // 5
                             });
  INFO((b.diagnostics.empty() ? std::string() : b.diagnostics.front().message));
  REQUIRE(b.cell);
  CHECK(b.diagnostics.empty());
  REQUIRE(b.cell->robots.size() == 2);
  CHECK(b.cell->robots[0].labelOf() == "left");
  CHECK(b.cell->robots[0].program == (dir.path() / "left.rsp").lexically_normal().string());
  CHECK(b.cell->robots[0].programPos == rs::diag::Pos{2, 46});
  CHECK(b.cell->robots[1].labelOf() == "Right");
  CHECK(b.cell->robots[1].program.empty());
  CHECK(b.cell->robotLabeled("RIGHT") == 1);
  const std::vector<rs::workcell::Wire>& w = b.cell->devices.wires;
  REQUIRE(w.size() == 2);
  CHECK(w[0].source.kind == rs::workcell::Signal::Kind::Output);
  CHECK(w[0].source.robot == "left");
  CHECK(w[0].source.number == 1);
  CHECK(w[0].robot == "Right");  // as its ROBOT line spells it
  CHECK(w[0].input == 2);
  CHECK(w[0].inputPos == rs::diag::Pos{4, 22});
  CHECK(w[1].robot == "left");
  CHECK(w[1].input == 3);
}

TEST_CASE("robot labels: a robot without AS is labelled by its description's name", "[models][labels]") {
  TempDir dir;
  const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0", "  WIRE OUT 1 TO rhino-xr4.IN 2"});
  REQUIRE(b.cell);
  CHECK(b.cell->robots[0].labelOf() == "rhino-xr4");
  CHECK(b.cell->devices.wires.at(0).robot == "rhino-xr4");
}

TEST_CASE("robot labels: each mistake is an error at its place with a hint", "[models][labels]") {
  TempDir dir;
  {  // a label used twice: at the second
    const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0 AS left", "  ROBOT rhino-xr4 AT 3000 750 0 AS LEFT"});
    const rs::diag::Diagnostic& d = first(b);
    CHECK(d.message == "a second robot labelled 'LEFT' in this workcell (the first is at line 2)");
    CHECK(d.pos == rs::diag::Pos{3, 36});
    CHECK(d.hint == "give each robot its own label: ROBOT NAME AT x y z AS LABEL");
  }
  {  // two robots of one model without AS: the description's name twice
    const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0", "  ROBOT rhino-xr4 AT 3000 750 0"});
    CHECK(first(b).message == "a second robot labelled 'rhino-xr4' in this workcell (the first is at line 2)");
    CHECK(first(b).pos == rs::diag::Pos{3, 9});
  }
  {  // a PROGRAM that does not exist
    const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0 PROGRAM progs/nope.rsp"});
    CHECK(first(b).message == "PROGRAM 'progs/nope.rsp' does not exist");
    CHECK(first(b).pos == rs::diag::Pos{2, 38});
    CHECK(first(b).hint == "PROGRAM names a program file (.rsp) beside this description, relative to its folder");
  }
  {  // a PROGRAM outside the cell file's folder
    const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0 PROGRAM ../c.rsd"});
    CHECK_THAT(first(b).message, Catch::StartsWith("PROGRAM '../c.rsd' "));
  }
  {  // a PROGRAM that is a folder, not a regular file
    std::filesystem::create_directories(dir.path() / "folder.rsp");
    const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0 PROGRAM folder.rsp"});
    CHECK(first(b).message == "PROGRAM 'folder.rsp' is not a regular file");
  }
  const std::vector<std::string> two{"  ROBOT rhino-xr4 AT 0 750 0 AS left", "  ROBOT rhino-xr4 AT 3000 750 0 AS right"};
  {  // a wire to a robot that is not there
    std::vector<std::string> body = two;
    body.push_back("  WIRE left.OUT 1 TO middle.IN 2");  // 4
    const Built b = build(dir, body);
    CHECK(first(b).message == "no robot labelled 'middle' in this workcell");
    CHECK(first(b).pos == rs::diag::Pos{4, 22});
    CHECK(first(b).hint == "the robots are left, right (a ROBOT line's AS label, else its name)");
  }
  {  // an unlabelled OUT and IN in a cell of several
    std::vector<std::string> body = two;
    body.push_back("  WIRE OUT 1 TO right.IN 2");  // 4
    body.push_back("  WIRE left.OUT 2 TO IN 3");   // 5
    const Built b = build(dir, body);
    REQUIRE(b.diagnostics.size() == 2);
    CHECK(b.diagnostics[0].message == "OUT 1 names no robot, and this workcell has 2");
    CHECK(b.diagnostics[0].pos == rs::diag::Pos{4, 8});
    CHECK(b.diagnostics[0].hint == "say whose, such as left.OUT 1: the robots are left, right");
    CHECK(b.diagnostics[1].message == "IN 3 names no robot, and this workcell has 2");
    CHECK(b.diagnostics[1].pos == rs::diag::Pos{5, 22});
  }
  {  // one input of each robot may have its own wire; the same robot's twice is an error
    std::vector<std::string> body = two;
    body.push_back("  WIRE ON TO left.IN 1");    // 4
    body.push_back("  WIRE ON TO right.IN 1");   // 5
    body.push_back("  WIRE OFF TO Left.IN 1");   // 6
    const Built b = build(dir, body);
    REQUIRE(b.diagnostics.size() == 1);
    CHECK(b.diagnostics[0].message == "input 1 has a second source: the WIRE at line 4 drives it already");
    CHECK(b.diagnostics[0].pos.line == 6);
  }
}

TEST_CASE("robot labels: two robots overlapping at home are a warning naming both", "[models][labels]") {
  TempDir dir;
  // Two XR-4s on one spot: every link of one is inside the other's.
  const Built b = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0 AS left", "  ROBOT rhino-xr4 AT 0 750 0 AS right"});
  REQUIRE(b.cell);
  const rs::diag::Diagnostic& w = first(b, false);
  CHECK_THAT(w.message, Catch::StartsWith("robots 'left' and 'right' overlap at their home poses: "));
  CHECK(w.pos == rs::diag::Pos{3, 9});
  CHECK(w.code == "home-collision");
  // Far apart: nothing.
  const Built apart = build(dir, {"  ROBOT rhino-xr4 AT 0 750 0 AS left", "  ROBOT rhino-xr4 AT 5000 750 0 AS right"});
  REQUIRE(apart.cell);
  for (const rs::diag::Diagnostic& d : apart.diagnostics) CHECK_THAT(d.message, !Catch::Contains("overlap at their home"));
}

TEST_CASE("robot labels: check --strict fails a cell whose robots overlap at home, naming both", "[models][labels][cli]") {
  TempDir dir;
  dir.write("two.rsd", lines({"WORKCELL two", "  ROBOT rhino-xr4 AT 0 750 0 AS left", "  ROBOT rhino-xr4 AT 0 750 0 AS right", "END"}));
  const std::string program = dir.write("p.rsp", "        END\n");
  const rs::testing::CliResult strict = rs::testing::runCli({"check", program, "--cell", dir.file("two.rsd"), "--strict"});
  CHECK(strict.code != 0);
  CHECK_THAT(strict.err, Catch::Contains("two.rsd:3:9: error: robots 'left' and 'right' overlap at their home poses"));
}
