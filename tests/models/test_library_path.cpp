// Name lookup (docs/models.md "Names and the library search path"): the
// referring file, then every file already loaded, then NAME.rsd in each
// search-path directory (directly, then in the kind's folder); the path is
// stdlib/, then each --lib in order, then the ROBOTSIM_PATH entries. Names
// are case-sensitive, keywords are not.
//
// Every link below is one LINE from the origin to (N, 0, 0), N telling
// where it was found.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "tests/models/models_support.h"

namespace {

namespace fs = std::filesystem;
using rs::compiler::Library;
using rs::testing::diagnosticList;
using rs::testing::lines;
using rs::testing::runCli;
using rs::testing::ScopedRobotsimPath;
using rs::testing::TempDir;
using Strings = std::vector<std::string>;

std::string link(const std::string& name, int marker) {
  return lines({"LINK " + name, "  LINE 0 0 0 " + std::to_string(marker) + " 0 0", "END"});
}

void put(const TempDir& dir, const std::string& relative, const std::string& text) {
  fs::create_directories((dir.path() / relative).parent_path());
  dir.write(relative, text);
}

// A robot using `names` as its links, all with the same frame (so any
// number of links is a sound chain: every D-H row is zero), joints A, B, ...
std::string robot(const std::string& name, const Strings& names) {
  Strings ls{"ROBOT " + name};
  for (const std::string& n : names) ls.push_back("  LINK " + n + " FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1");
  for (std::size_t i = 1; i < names.size(); ++i)
    ls.push_back("  JOINT " + std::to_string(i) + " REVOLUTE LETTER " + std::string(1, static_cast<char>('A' + i - 1)) +
                 " PRECISION 1 RANGE -10 10");
  ls.push_back("END");
  return lines(ls);
}

// The marker of each link of a robot, in order.
std::vector<double> markers(const rs::workcell::Robot& r) {
  std::vector<double> m;
  for (const auto& s : r.links) m.push_back(s.segments.empty() ? -1.0 : s.segments.front().b.x());
  return m;
}

}  // namespace

TEST_CASE("library path: stdlib, then --lib in order, then ROBOTSIM_PATH entries", "[models]") {
  const fs::path stdlib = fs::path(ROBOTSIM_SOURCE_DIR) / "stdlib";
  {
    ScopedRobotsimPath env(std::string("/e/one::/e/two:"));
    const auto path = rs::compiler::librarySearchPath({"/lib/a", "/lib/b"});
    REQUIRE(path.size() == 5);
    CHECK(fs::equivalent(path[0], stdlib));
    CHECK(path[1] == fs::path("/lib/a"));
    CHECK(path[2] == fs::path("/lib/b"));
    CHECK(path[3] == fs::path("/e/one"));  // empty entries are skipped
    CHECK(path[4] == fs::path("/e/two"));
  }
  {
    ScopedRobotsimPath env(std::nullopt);
    const auto path = rs::compiler::librarySearchPath({"/lib/a"});
    REQUIRE(path.size() == 2);
    CHECK(fs::equivalent(path[0], stdlib));
    CHECK(path[1] == fs::path("/lib/a"));
  }
}

TEST_CASE("library path: lookup order", "[models]") {
  TempDir root, a, b, e;
  ScopedRobotsimPath env(e.path().string());
  const std::string file = root.write("r.rsd", link("here", 1) +
                                                   robot("r", {"here", "inA", "extra", "inB", "inE", "folder", "both",
                                                               "skip", "deep"}));
  put(a, "here.rsd", link("here", 901));             // the file itself wins
  put(a, "inA.rsd", link("inA", 10) + link("extra", 60));
  put(b, "inA.rsd", link("inA", 11));                // --lib order: a before b
  put(e, "inA.rsd", link("inA", 12));
  put(e, "extra.rsd", link("extra", 61));            // already loaded (from a/inA.rsd) wins
  put(a, "extra.rsd", link("extra", 62));            // ... even over a/extra.rsd
  put(b, "inB.rsd", link("inB", 21));                // --lib before ROBOTSIM_PATH
  put(e, "inB.rsd", link("inB", 22));
  put(e, "inE.rsd", link("inE", 32));                // ROBOTSIM_PATH is searched too
  put(a, "links/folder.rsd", link("folder", 40));    // kind folder of an earlier directory ...
  put(b, "folder.rsd", link("folder", 41));          // ... before a later directory
  put(a, "both.rsd", link("both", 50));              // directly in a directory ...
  put(a, "links/both.rsd", link("both", 51));        // ... before its kind folder
  put(a, "skip.rsd", link("other", 69));             // NAME.rsd that does not define NAME: keep looking
  put(b, "skip.rsd", link("skip", 70));
  put(e, "links/deep.rsd", link("deep", 80));
  Library lib(rs::compiler::librarySearchPath({a.path().string(), b.path().string()}));
  const auto r = lib.robot(file);
  INFO(rs::testing::joined(diagnosticList(lib.diagnostics(), root.path().string())));
  REQUIRE(r);
  CHECK(markers(*r) == std::vector<double>{1, 10, 60, 21, 32, 40, 50, 70, 80});
}

TEST_CASE("library path: files loaded for one robot are seen by the next lookups", "[models]") {
  TempDir root, a;
  put(a, "first.rsd", link("shared", 5) + robot("first", {"shared"}));
  put(a, "shared.rsd", link("shared", 6));
  const std::string second = root.write("second.rsd", robot("second", {"shared"}));
  Library lib({a.path()});
  REQUIRE(lib.robot("first"));
  const auto r = lib.robot(second);
  REQUIRE(r);
  CHECK(markers(*r) == std::vector<double>{5});
}

TEST_CASE("library path: stdlib comes before --lib and ROBOTSIM_PATH", "[models]") {
  TempDir a, e;
  // A different one-link "scorobot" in a --lib directory and on ROBOTSIM_PATH.
  put(a, "robots/scorobot.rsd", link("tiny", 1) + robot("scorobot", {"tiny"}));
  put(e, "scorobot.rsd", link("tiny", 1) + robot("scorobot", {"tiny"}));
  ScopedRobotsimPath env(e.path().string());
  Library lib(rs::compiler::librarySearchPath({a.path().string()}));
  const auto r = lib.robot("scorobot");
  REQUIRE(r);
  CHECK(r->joints.size() == 5);
  // And through a workcell that names it.
  TempDir w;
  const std::string cell = w.write("w.rsd", lines({"WORKCELL w", "  ROBOT scorobot AT 0 0 0", "END"}));
  Library lib2(rs::compiler::librarySearchPath({a.path().string()}));
  const auto c = lib2.workcell(cell);
  REQUIRE(c);
  REQUIRE(c->robots.size() == 1);
  CHECK(c->robots[0].robot.joints.size() == 5);
}

TEST_CASE("library path: kind folders", "[models]") {
  TempDir a;
  put(a, "links/base.rsd", link("base", 1));
  put(a, "links/upper.rsd", link("upper", 2));
  put(a, "grippers/claw.rsd",
      lines({"GRIPPER claw", "  BASE base FINGERS upper upper", "  LETTER G PRECISION 1 RANGE 0 10",
             "  AXIS2 0 0 0 1 0 0", "  AXIS3 0 0 0 -1 0 0", "  NORMAL 5 0 0 6 0 0", "  APPROACH 5 0 0 5 0 -1",
             "END"}));
  put(a, "robots/arm.rsd",
      lines({"ROBOT arm", "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",
             "  LINK upper FRAME ORIGIN 5 0 0 XAXIS 6 0 0 ZAXIS 5 0 1",
             "  JOINT 1 REVOLUTE LETTER A PRECISION 1 RANGE -10 10",
             "  JOINT 2 REVOLUTE LETTER B PRECISION 1 RANGE -10 10", "  GRIPPER claw", "END"}));
  put(a, "objects/crate.rsd", lines({"OBJECT crate", "  BOX 0 1 1 0 1 0", "END"}));
  put(a, "workcells/shop.rsd", lines({"WORKCELL shop", "  ROBOT arm AT 0 0 0", "  OBJECT crate AT 9 0 0", "END"}));
  put(a, "objects/stray.rsd", link("stray", 3));  // a LINK filed under objects/
  Library lib({a.path()});
  const auto cell = lib.workcell("shop");
  INFO(rs::testing::joined(diagnosticList(lib.diagnostics(), a.path().string())));
  REQUIRE(cell);
  REQUIRE(cell->robots.size() == 1);
  CHECK(cell->robots[0].robot.name == "arm");
  CHECK(cell->robots[0].robot.hasGripper);
  CHECK(cell->robots[0].robot.gripper.letter == 'G');
  REQUIRE(cell->objects.size() == 1);
  CHECK(cell->objects[0].shape.name == "crate");
  // A robot's library name also works as a workcell (it stands where drawn).
  Library lib2({a.path()});
  const auto alone = lib2.workcell("arm");
  REQUIRE(alone);
  CHECK(alone->robots.size() == 1);
  // A link is looked up in links/, not in objects/.
  TempDir r;
  const std::string file = r.write("r.rsd", robot("r", {"base", "stray"}));
  Library lib3({a.path()});
  CHECK_FALSE(lib3.robot(file));
  CHECK(diagnosticList(lib3.diagnostics(), r.path().string()) ==
        Strings{"r.rsd:3:8: unknown link 'stray': not defined in this file, and no stray.rsd beside it or on the library path"});
}

TEST_CASE("library path: names are case-sensitive, keywords are not", "[models]") {
  TempDir root, a;
  put(a, "Upper.rsd", link("Upper", 7));
  SECTION("a name in the file with other case is not a match") {
    const std::string file = root.write("r.rsd", link("Base", 1) + robot("r", {"base"}));
    Library lib({a.path()});
    CHECK_FALSE(lib.robot(file));
    CHECK(diagnosticList(lib.diagnostics(), root.path().string()) ==
          Strings{"r.rsd:5:8: unknown link 'base': not defined in this file, and no base.rsd beside it or on the library path"});
  }
  SECTION("a file on the path with other case is not a match") {
    const std::string file = root.write("r.rsd", link("base", 1) + robot("r", {"base", "upper"}));
    Library lib({a.path()});
    CHECK_FALSE(lib.robot(file));
    CHECK(diagnosticList(lib.diagnostics(), root.path().string()) ==
          Strings{"r.rsd:6:8: unknown link 'upper': not defined in this file, and no upper.rsd beside it or on the library path"});
  }
  SECTION("exact case is found") {
    const std::string file = root.write("r.rsd", link("base", 1) + robot("r", {"base", "Upper"}));
    Library lib({a.path()});
    const auto r = lib.robot(file);
    REQUIRE(r);
    CHECK(markers(*r) == std::vector<double>{1, 7});
  }
  SECTION("keywords in any case; motor letters upper-cased") {
    const std::string file = root.write("r.rsd", lines({
                                                     "link base",
                                                     "  Line 0 0 0 1 0 0 color Red",
                                                     "eNd",
                                                     "robot r",
                                                     "  link base frame origin 0 0 0 xaxis 1 0 0 zaxis 0 0 1",
                                                     "  link base Frame Origin 0 0 0 XAxis 1 0 0 ZAxis 0 0 1",
                                                     "  joint 1 prismatic letter q precision 2 range -5 5 coupling off speed 9",
                                                     "end",
                                                 }));
    Library lib({a.path()});
    const auto r = lib.robot(file);
    REQUIRE(r);
    REQUIRE(r->joints.size() == 1);
    CHECK(r->joints[0].letter == 'Q');
    CHECK(r->joints[0].type == rs::kinematics::JointType::Prismatic);
    CHECK(r->joints[0].speed == 9);
    CHECK(r->links[0].segments[0].color == rs::workcell::Color::Red);
  }
  SECTION("library names for commands") {
    Library lib(rs::compiler::librarySearchPath({}));
    CHECK_FALSE(lib.robot("SCOROBOT"));
    Library lib2(rs::compiler::librarySearchPath({}));
    CHECK(lib2.robot("scorobot"));
  }
}

TEST_CASE("library path: the CLI takes --lib and ROBOTSIM_PATH", "[models]") {
  TempDir a, b, e;
  const std::string arm = link("base", 1) + link("upper", 2) +
                          lines({"ROBOT ARM_NAME", "  LINK base FRAME ORIGIN 0 0 0 XAXIS 1 0 0 ZAXIS 0 0 1",
                                 "  LINK upper FRAME ORIGIN 5 0 0 XAXIS 6 0 0 ZAXIS 5 0 1",
                                 "  JOINT 1 REVOLUTE LETTER A PRECISION 1 RANGE -10 10", "END"});
  const auto named = [&](const std::string& n) {
    std::string s = arm;
    s.replace(s.find("ARM_NAME"), 8, n);
    return s;
  };
  put(a, "robots/twin.rsd", named("from-a"));
  put(b, "robots/twin.rsd", named("from-b"));
  put(b, "robots/only-b.rsd", named("only-b"));
  put(e, "only-e.rsd", named("only-e"));
  ScopedRobotsimPath env(e.path().string());
  const auto first = [](const std::string& out) { return out.substr(0, out.find('\n')); };
  auto r = runCli({"table", "twin", "--lib", a.path().string(), "--lib", b.path().string()});
  CHECK(r.code == 0);
  CHECK(first(r.out) == "KINEMATIC PARAMETERS: from-a (standard D-H; degrees and length units)");
  r = runCli({"table", "twin", "--lib", b.path().string(), "--lib", a.path().string()});
  CHECK(first(r.out) == "KINEMATIC PARAMETERS: from-b (standard D-H; degrees and length units)");
  r = runCli({"table", "only-b", "--lib", a.path().string(), "--lib", b.path().string()});
  CHECK(first(r.out) == "KINEMATIC PARAMETERS: only-b (standard D-H; degrees and length units)");
  r = runCli({"table", "only-e"});
  CHECK(r.code == 0);
  CHECK(first(r.out) == "KINEMATIC PARAMETERS: only-e (standard D-H; degrees and length units)");
  r = runCli({"table", "twin"});
  CHECK(r.code == 2);
  CHECK(r.err == "twin: error: no such file, and no robot of that name on the library path\n");
}

TEST_CASE("library path: a cell finds the robot file beside it first, with no --lib", "[models]") {
  // my-cell.rsd places ROBOT my-scara, written in my-scara.rsd in the same folder: no --lib needed. A link
  // named in the robot's file is looked up beside the robot's file, in links/ there too.
  TempDir here, lib;
  put(here, "my-scara.rsd", robot("my-scara", {"base", "arm"}));
  put(here, "links/base.rsd", link("base", 1));
  put(here, "arm.rsd", link("arm", 2));
  const std::string cell = here.write("my-cell.rsd", lines({"WORKCELL my-cell", "  ROBOT my-scara AT 0 0 0", "END"}));
  SECTION("found beside the cell") {
    Library l({lib.path()});
    const auto c = l.workcell(cell);
    INFO(rs::testing::joined(diagnosticList(l.diagnostics(), here.path().string())));
    REQUIRE(c);
    REQUIRE(c->robots.size() == 1);
    CHECK(c->robots[0].robot.name == "my-scara");
    CHECK(markers(c->robots[0].robot) == std::vector<double>{1, 2});
  }
  SECTION("the folder comes before the search path") {
    put(lib, "arm.rsd", link("arm", 9));
    Library l({lib.path()});
    const auto c = l.workcell(cell);
    REQUIRE(c);
    CHECK(markers(c->robots[0].robot) == std::vector<double>{1, 2});
  }
  SECTION("the command line, from another folder, with no --lib") {
    const auto r = runCli({"describe", cell});
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.out.find("robot my-scara") != std::string::npos);
  }
  SECTION("not there, nor on the path: the message says where it looked") {
    fs::remove(here.path() / "my-scara.rsd");
    Library l({lib.path()});
    CHECK_FALSE(l.workcell(cell));
    CHECK(diagnosticList(l.diagnostics(), here.path().string()) ==
          Strings{"my-cell.rsd:2:9: unknown robot 'my-scara': not defined in this file, and no my-scara.rsd beside it "
                  "or on the library path"});
  }
}
