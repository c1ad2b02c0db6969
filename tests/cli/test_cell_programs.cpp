// Issue 36: `check --cell CELL` and `compile --cell CELL -o DIR` without a
// program take every PROGRAM of the cell's ROBOT lines, each compiled for
// its own robot, its errors in its own file; a PROGRAM that is an image
// compiled for another robot is an error at the PROGRAM's name. Columns
// counted by hand from the lines written here.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cell_programs_test {

const char* const kCell =
    "WORKCELL two\n"
    "  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM l.rsp\n"
    "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM r.rsp\n"
    "  ROBOT rhino-xr4 AT 6000 750 0 AS idle\n"
    "END\n";

}  // namespace cell_programs_test

using namespace cell_programs_test;

TEST_CASE("cell programs: check takes every PROGRAM, each in its own file", "[cli][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("l.rsp", "        OUTSIG 1 ON\n        END\n");
  dir.write("r.rsp", "        END\n        BOGUS\n");  // line 2, column 9
  const auto text = rs::testing::runCli({"check", "--cell", dir.file("c.rsd")});
  CHECK(text.code == 2);
  CHECK(text.out.find("robot left: ") != std::string::npos);
  CHECK(text.out.find("l.rsp: ok (2 instructions executed") != std::string::npos);
  CHECK(text.out.find("robot right: ") != std::string::npos);
  CHECK(text.out.find("robot idle") == std::string::npos);  // no PROGRAM: nothing to check
  CHECK(text.err.find("r.rsp:2:9: error: unknown instruction 'BOGUS'") != std::string::npos);

  const auto json = rs::testing::runCli({"check", "--cell", dir.file("c.rsd"), "--format=json"});
  const auto j = nlohmann::json::parse(json.out);
  REQUIRE(j["robots"].size() == 2);
  CHECK(j["robots"][0]["name"] == "left");
  CHECK(j["robots"][0]["status"] == "finished");
  CHECK(j["robots"][0]["outputs"][0] == true);  // left's OUTSIG 1 ON
  CHECK(j["robots"][1]["name"] == "right");
  CHECK(j["robots"][1]["status"] == "error");

  dir.write("r.rsp", "        END\n");
  CHECK(rs::testing::runCli({"check", "--cell", dir.file("c.rsd")}).code == 0);
}

TEST_CASE("cell programs: compile writes one image per PROGRAM into a folder", "[cli][robots]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", kCell);
  dir.write("l.rsp", "        END\n");
  dir.write("r.rsp", "        END\n");
  const auto r = rs::testing::runCli({"compile", "--cell", dir.file("c.rsd"), "-o", dir.file("out")});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(std::filesystem::is_regular_file(dir.file("out/l.rsb")));
  CHECK(std::filesystem::is_regular_file(dir.file("out/r.rsb")));
  CHECK(rs::testing::runCli({"compile", "--cell", dir.file("c.rsd"), "-o", "-"}).code == 2);
  const auto none = rs::testing::runCli({"check"});
  CHECK(none.code == 2);
  CHECK(none.err.find("which program?") != std::string::npos);
}

TEST_CASE("cell programs: a PROGRAM image compiled for another robot is an error at its name", "[cli][robots]") {
  rs::testing::TempDir dir;
  dir.write("s.rsp", "        END\n");
  REQUIRE(rs::testing::runCli({"compile", dir.file("s.rsp"), "-o", dir.file("s.rsb")}).code == 0);  // the default SCARA
  dir.write("w.rsd", "WORKCELL one\n  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM s.rsb\nEND\n");
  const auto r = rs::testing::runCli({"check", "--cell", dir.file("w.rsd")});
  CHECK(r.code == 2);
  // "  ROBOT rhino-xr4 AT 0 750 0 AS left PROGRAM " is 45 bytes: the name at column 46.
  CHECK(r.err.find("w.rsd:2:46: error: PROGRAM 's.rsb' was compiled for robot 'rhino-scara' with 5 motors, but robot "
                   "'left' (rhino-xr4) has 6") != std::string::npos);
  CHECK(r.err.find("hint: compile its source for this robot") != std::string::npos);
}
