// Collisions through the command line: the SCARA of the library swings its
// arm through a post (a 20 x 200 x 20 box) standing on its table, 178 from
// joint E's axis, where link 2 (reaching 240 from the axis) passes.
// Worked out by hand: the post stands at x -150..-130, z 100..120; MOVETO
// 600 turns joint E by 70.5 degrees (+y: from -x towards +z) in 1.5 s, and
// link 2 sweeps through the post's angle (about 142 degrees from +x,
// i.e. 38 past -x) at roughly 38/70.5 of the move: 0.5..0.9 s.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "launch/program.h"
#include "tests/cli/cli_support.h"

namespace {

using rs::testing::runCli;
using rs::testing::TempDir;

constexpr const char* kCell = R"(
OBJECT post
  BOX 0 20 200 0 20 0
END
WORKCELL post-cell
  ROBOT rhino-scara  AT 0 750 0
  OBJECT table   AT -500 0 250
  OBJECT post    AT -150 750 120
END
)";

constexpr const char* kProgram =
    "        MOVETO 600 0 0 0 0\n"
    "        MOVETO 0 0 0 0 0\n"
    "        MOVE 0 0 0 0 120\n"
    "        END\n";

// The post's cell and the swinging program, written to a fresh folder.
struct PostCell {
  const TempDir dir;
  const std::string cell = dir.write("post-cell.rsd", kCell);
  const std::string program = dir.write("swing.rsp", kProgram);
};

}  // namespace

TEST_CASE_METHOD(PostCell, "a move through a post stops the run with the line, the time and the parts",
                 "[collision][cli]") {
  const auto r = runCli({"run", program, "--cell", cell, "--trace"});
  CHECK(r.code == 1);
  INFO(r.err);
  const auto at = r.err.find(program + ":1:9: error: runtime error: collision at ");
  REQUIRE(at != std::string::npos);
  const double seconds = std::stod(r.err.substr(at + program.size() + 40));
  CHECK(seconds > 0.5);
  CHECK(seconds < 0.9);
  // How deep at the first check that saw it: the sweep checks at least every length unit a point moves.
  const auto deep = r.err.find("link 2 (rhino_scara_link2) hits object 2 (post), ");
  REQUIRE(deep != std::string::npos);
  const double depth = std::stod(r.err.substr(deep + std::string("link 2 (rhino_scara_link2) hits object 2 (post), ").size()));
  CHECK(depth > 0);
  CHECK(depth <= 1.02);
  CHECK(r.err.find(" deep (instruction 1)") != std::string::npos);
  CHECK(r.out.find("collision at line 1: link 2 (rhino_scara_link2) hits object 2 (post)") != std::string::npos);
  CHECK(r.out.find("runtime error at line 1") != std::string::npos);
  CHECK(r.out.find("  collisions      line 1, ") != std::string::npos);
}

TEST_CASE_METHOD(PostCell, "with --collisions=warn every colliding move is listed and the run goes on, off checks nothing",
                 "[collision][cli]") {
  const auto warn = runCli({"run", program, "--cell", cell, "--collisions=warn", "--format=json"});
  CHECK(warn.code == 0);
  const auto j = nlohmann::json::parse(warn.out);
  REQUIRE(j.at("collisions").size() == 2);  // there and back
  CHECK(j["collisions"][0]["line"] == 1);
  CHECK(j["collisions"][1]["line"] == 2);
  CHECK(j["collisions"][0]["part"] == "link 2 (rhino_scara_link2)");
  CHECK(j["collisions"][0]["hits"] == "object 2 (post)");
  // Swinging back, link 2 meets the post where it left it on the way
  // there, as far from the end of the return as it was from the start of
  // the first move: so the two times into their moves add up to 1.5 s less
  // the time it spent in the post.
  const double there = j["collisions"][0]["time"], back = j["collisions"][1]["time"];
  CHECK(back > 1.5);
  CHECK(there + (back - 1.5) < 1.5);
  const auto off = runCli({"run", program, "--cell", cell, "--collisions=off", "--format=json"});
  CHECK(off.code == 0);
  CHECK(nlohmann::json::parse(off.out).count("collisions") == 0);
  const auto bad = runCli({"run", program, "--cell", cell, "--collisions=maybe"});
  CHECK(bad.code == 2);
  CHECK(bad.err.find("--collisions: error: 'maybe' is not a collision mode") != std::string::npos);
}

TEST_CASE_METHOD(PostCell, "the gripper closing on nothing is traced, and a run that never takes gets a warning",
                 "[collision][cli]") {
  const auto r = runCli({"run", program, "--cell", cell, "--collisions=off", "--trace"});
  CHECK(r.code == 0);
  // At home the tool centre point is (-225, 840, 0): 90 above the table's
  // top (y 750). The table's box (stdlib/objects/table.rsd, 800 x 750 x
  // 500 placed AT -500 0 250) spans x -500..300, y 0..750, z -250..250:
  // its centre (-100, 375, 0) is 465 below and 125 towards +x.
  CHECK(r.out.find("closes on nothing (nearest: table (object 1), its centre 465 below and 125 towards +x of the "
                   "tool centre point, which is 90 outside its box)") != std::string::npos);
  CHECK(r.err.find(program + ":3:9: warning: the gripper closed once but never took an object") != std::string::npos);
}

// The post moved onto the arm's path at home: link 2 lies along -x.
static std::string postInTheWay() {
  std::string text = kCell;
  text.replace(text.find("AT -150 750 120"), 15, "AT -150 750 10 ");
  return text;
}

TEST_CASE("a robot that overlaps an object at home is reported when the cell is loaded", "[collision][cli]") {
  const TempDir dir;
  const std::string cell = dir.write("post-cell.rsd", postInTheWay()), program = dir.write("swing.rsp", kProgram);
  const auto r = runCli({"check", program, "--cell", cell});
  CHECK(r.err.find("post-cell.rsd:6:9: warning: robot 'rhino-scara' collides at its home pose: link 2 "
                   "(rhino_scara_link2) overlaps object 2 (post)") != std::string::npos);
  CHECK(r.code == 1);  // and the first move starts in the post
}

TEST_CASE("run PROG --cell CELL reads the cell once: its warning comes once", "[collision][cli]") {
  const TempDir dir;
  const std::string cell = dir.write("post-cell.rsd", postInTheWay()), program = dir.write("swing.rsp", kProgram);
  const auto r = runCli({"run", program, "--cell", cell});
  const std::string warning = "post-cell.rsd:6:9: warning: robot 'rhino-scara' collides at its home pose";
  const std::size_t first = r.err.find(warning);
  REQUIRE(first != std::string::npos);
  CHECK(r.err.find(warning, first + 1) == std::string::npos);
}

TEST_CASE("a program's load takes the cell its request carries, without reading the file again", "[collision][cli]") {
  const TempDir dir;
  const std::string cell = dir.write("post-cell.rsd", kCell), program = dir.write("swing.rsp", kProgram);
  rs::launch::ProgramRequest request;
  request.file = program, request.cell = cell;
  rs::launch::LoadedProgram first;
  auto read = std::make_shared<rs::launch::LoadedCell>();
  read->cell = rs::launch::loadCell(request, first);
  REQUIRE(read->cell);
  read->descriptions = first.descriptions;
  // Gone from the disk: only the request's copy can give the cell now.
  std::filesystem::remove(cell);
  CHECK_FALSE(rs::launch::loadProgram(request).ok());
  request.loadedCell = read;
  const rs::launch::LoadedProgram again = rs::launch::loadProgram(request);
  CHECK(again.ok());
  CHECK(again.cell->name == "post-cell");
}

TEST_CASE("robotsim test: no collision, and collides with NAME at line N", "[collision][testrun][cli]") {
  const TempDir dir;
  dir.write("post-cell.rsd", kCell);
  const std::string good = dir.write("good.rsp",
                                     "; test: cell post-cell.rsd\n"
                                     "; expect: collides with post at line 6\n"
                                     "; expect: collides with rhino_scara_link2\n"
                                     "; expect: finished\n"
                                     "        MOVETO 600 0 0 0 0\n"
                                     "        MOVETO 0 0 0 0 0\n"
                                     "        END\n");
  const auto pass = runCli({"test", good});
  INFO(pass.out);
  CHECK(pass.code == 0);
  const std::string bad = dir.write("bad.rsp",
                                    "; test: cell post-cell.rsd\n"
                                    "; expect: no collision\n"
                                    "; expect: collides with table\n"
                                    "; expect: collides with post at line 3\n"
                                    "        MOVETO 600 0 0 0 0\n"
                                    "        END\n");
  const auto fail = runCli({"test", bad});
  INFO(fail.out);
  CHECK(fail.code == 1);
  CHECK(fail.out.find(bad + ":2:3: error: expected no collision; 1 found, the first at line 5, ") != std::string::npos);
  CHECK(fail.out.find(bad + ":3:3: error: expected a collision with table; the run's first was at line 5") !=
        std::string::npos);
  CHECK(fail.out.find(bad + ":4:3: error: expected a collision with post at line 3;") != std::string::npos);
}

TEST_CASE_METHOD(PostCell, "animate puts each collision's parts and moment in the page's model",
                 "[collision][render][cli]") {
  const auto r = runCli({"animate", program, "--cell", cell, "--collisions=warn", "-o", dir.file("swing.html")});
  REQUIRE(r.code == 0);
  const std::string html = rs::testing::readBytes(dir.file("swing.html"));
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const auto from = html.find(open);
  REQUIRE(from != std::string::npos);
  const auto to = html.find("</script>", from);
  const auto model = nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size()));
  const auto& c = model["run"]["collisions"];
  REQUIRE(c["at"].size() == 2);
  // Red from the collision to the end of its move: the moves end at 1.5 s and 3 s.
  CHECK(c["end"] == nlohmann::json::parse("[1500000, 3000000]"));
  CHECK(c["at"][0].get<double>() < 1500000);
  CHECK(c["robotParts"] == nlohmann::json::parse("[[2], [2]]"));  // link 2: the robot's third part
  CHECK(c["objects"] == nlohmann::json::parse("[[1], [1]]"));     // the post
  CHECK(model["robots"][0]["parts"][2]["kind"] == "link");
  CHECK(model["robots"][0]["parts"][2]["index"] == 2);
}
