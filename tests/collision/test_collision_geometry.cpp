// Collision geometry from descriptions (docs/models.md, "Collisions"): each
// BOX a piece, the LINEs one hull, COLLIDE statements instead, FLOOR; the
// floor in a run; stills that mark colliding parts and draw the pieces.
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compiler/description/library.h"
#include "model/workcell/collision_model.h"
#include "tests/cli/cli_support.h"

namespace {

using rs::testing::runCli;
using rs::testing::TempDir;

struct Loaded {
  std::optional<rs::workcell::Workcell> cell;
  std::vector<rs::diag::Diagnostic> diagnostics;
};

Loaded load(const std::string& text) {
  const TempDir dir;
  const std::string file = dir.write("c.rsd", text);
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  Loaded out;
  out.cell = library.workcell(file);
  out.diagnostics = library.diagnostics();
  return out;
}

}  // namespace

TEST_CASE("a shape's collision pieces: each BOX, the hull of its LINEs, or its COLLIDE statements", "[collision]") {
  const Loaded l = load(R"(
OBJECT drawn
  BOX 0 10 10 0 10 0
  LINE 0 0 0  5 5 5
  LINE 1 2 3  4 5 6
  BOX 20 30 10 0 10 0
  MOVE 100 0 0
END
OBJECT given
  BOX 0 10 10 0 10 0
  COLLIDE BOX 0 4 4 0 4 0
  ROTATE Z 90
END
OBJECT hollow
  BOX 0 10 10 0 10 0
  COLLIDE NONE
END
WORKCELL w
  FLOOR NONE
  OBJECT drawn AT 0 0 0
  OBJECT given AT 0 0 0
  OBJECT hollow AT 0 0 0
END
)");
  for (const auto& d : l.diagnostics) INFO(d.message);
  REQUIRE(l.cell);
  CHECK_FALSE(l.cell->floor);
  const auto& drawn = l.cell->objects[0].shape.collision;
  REQUIRE(drawn.size() == 3);  // two boxes, then the lines' hull
  CHECK(drawn[0].box);
  CHECK(drawn[1].box);
  CHECK_FALSE(drawn[2].box);
  CHECK(drawn[2].points.size() == 4);
  CHECK(drawn[0].points[0] == Eigen::Vector3d(100, 0, 0));  // MOVE moved the pieces with the lines
  CHECK(drawn[2].points[3] == Eigen::Vector3d(104, 5, 6));
  const auto& given = l.cell->objects[1].shape.collision;
  REQUIRE(given.size() == 1);
  // The COLLIDE box's corner (4, 4, 4) turned 90 degrees about z: (-4, 4, 4).
  CHECK((given[0].points[7] - Eigen::Vector3d(-4, 4, 4)).norm() < 1e-12);
  CHECK(l.cell->objects[2].shape.collision.empty());
}

TEST_CASE("COLLIDE and FLOOR errors are positioned, and a WORKCELL has a floor at 0", "[collision]") {
  const Loaded bad = load("OBJECT o\n  COLLIDE SPHERE 3\n  COLLIDE BOX 1 2 3\nEND\nWORKCELL w\n  FLOOR LOW\n  OBJECT o AT 0 0 0\nEND\n");
  std::vector<std::string> messages;
  for (const auto& d : bad.diagnostics) messages.push_back(fmt::format("{}:{}: {}", d.pos.line, d.pos.col, d.message));
  CHECK(messages == std::vector<std::string>{
                        "2:11: expected BOX or NONE, found 'SPHERE'",
                        "3:20: expected the COLLIDE BOX's bottom edge before the end of the line",
                        "6:9: expected the floor's height (y), or NONE, found 'LOW'",
                    });
  const Loaded good = load("OBJECT o\n  BOX 0 1 1 0 1 0\nEND\nWORKCELL w\n  OBJECT o AT 0 0 0\nEND\n");
  REQUIRE(good.cell);
  CHECK(good.cell->floor == 0.0);
  const Loaded raised = load("OBJECT o\n  BOX 0 1 1 0 1 0\nEND\nWORKCELL w\n  FLOOR -12.5\n  OBJECT o AT 0 0 0\nEND\n");
  REQUIRE(raised.cell);
  CHECK(raised.cell->floor == -12.5);
}

TEST_CASE("the gantry driven down through the floor collides with it when its fingers pass y = 0", "[collision][cli]") {
  // gantry-cell: the tool centre point is at y = 200 - Y/10, the fingers
  // reach 20 below it: they pass the floor when Y passes 1800 (1800.1
  // with the contact tolerance), at 1800 / 800 = 2.25 s of the move (Y at
  // 800 units per second). Y moves 0.1 mm per count, so the first pose
  // below the floor is Y = 1801, from 1801 / 800 = 2.25125 s on. The check
  // that sees it follows one that did not (Y <= 1800) by at most the
  // bound, 1 mm of the fingers' travel: ten counts, so Y <= 1810, before
  // 1811 / 800 = 2.26375 s (docs/models.md, "Collisions": the reported
  // time is within the bound of the first contact).
  const TempDir dir;
  const std::string program = dir.write("down.rsp", "        MOVETO 0 0 2000 0\n        END\n");
  const auto r = runCli({"run", program, "--cell", "gantry-cell", "--format=json", "--collisions=warn"});
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j.at("collisions").size() == 1);
  CHECK(j["collisions"][0]["hits"] == "the floor");
  CHECK(j["collisions"][0]["part"].get<std::string>().rfind("finger", 0) == 0);
  CHECK(j["collisions"][0]["time"].get<double>() >= 2.25125);
  CHECK(j["collisions"][0]["time"].get<double>() < 2.26375);
}

TEST_CASE("a still marks colliding parts red and draws collision shapes when asked", "[collision][render][cli]") {
  const TempDir dir;
  const std::string program = dir.write("down.rsp", "        MOVETO 0 0 2000 0\n        END\n");
  const auto count = [](const nlohmann::json& doc, const std::string& part, const std::string& color) {
    int n = 0;
    for (const auto& l : doc["lines"]) n += l["part"] == part && l["color"] == color;
    return n;
  };
  const auto plain =
      runCli({"render", "gantry-cell", "--program", program, "--at", "1", "--collisions=warn", "--dump-lines=json"});
  REQUIRE(plain.code == 0);
  const auto before = nlohmann::json::parse(plain.out);
  CHECK(count(before, "finger2", "RED") == 0);
  // Without --at the run that a collision stopped is drawn at the collision.
  const auto hit = runCli({"render", "gantry-cell", "--program", program, "--dump-lines=json"});
  CHECK(hit.code == 1);
  const auto at = nlohmann::json::parse(hit.out);
  CHECK(count(at, "finger2", "RED") + count(at, "finger3", "RED") >= 12);  // a BOX's 12 edges at least
  const auto shapes = runCli({"render", "gantry-cell", "--collision-shapes", "--dump-lines=json"});
  REQUIRE(shapes.code == 0);
  const auto home = runCli({"render", "gantry-cell", "--dump-lines=json"});
  // Every line of the library's gantry cell is a BOX edge: the pieces add
  // 12 lines per BOX, as many as the drawing has, and the gantry's bridge
  // two COLLIDE boxes in place of its one.
  const std::size_t drawn = nlohmann::json::parse(home.out)["lines"].size();
  CHECK(nlohmann::json::parse(shapes.out)["lines"].size() == 2 * drawn + 12);
}
