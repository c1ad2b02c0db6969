// `robotsim describe CELL|ROBOT`: every number checked by hand against the
// description files in stdlib/ (the arithmetic is in the comments).
//
// scara-pick (stdlib/workcells/scara-pick.rsd): objects are placed by
// their AT corner (least x, least y, greatest z of the drawing):
//   1 table  (x 0..800, y 0..750, z 0..500) AT -500 0 250
//            -> x -500..300, y 0..750, z -250..250, centre (-100, 375, 0),
//            on the floor (y = 0).
//   2 pallet (x 0..240, y 0..30, z 0..160) AT -330 750 80
//            -> x -330..-90, y 750..780, z -80..80, centre (-210, 765, 0),
//            on the table (its top face at y = 750).
//   3..5 block (x, y, z 0..40) AT -200 780 -25, -200 780 65, -150 780 20
//            -> x -200..-160, z -65..-25; x -200..-160, z 25..65;
//            x -150..-110, z -20..20; all y 780..820, on the pallet's deck.
// rhino-scara (stdlib/robots/rhino-scara.rsd): link 0's origin, design
// (90, -125, 0), goes AT (0, 750, 0): world = design + (-90, 875, 0);
// x0 = -x, z0 = +y. Its base link spans design x 0..150, y -125..125,
// z -75..75 -> world x -90..60, y 750..1000, z -75..75, standing on the
// table top (y 750). Motors from its JOINT and GRIPPER lines. At home the
// tool centre point is design (-135, -35, 0) -> (-225, 840, 0).
// Reach: the arm is planar about joint E's axis with a1 = 105, a2 = 120:
// at most 105 + 120 = 225 from the axis (theta2 = 0, inside D's range).
// Span: world y = 840 - 0.12 C for C in -350..350 -> 798..882; world z =
// 105 sin t1 + 120 sin(t1 + t2) reaches +-225 (t1 = +-90, t2 = 0); world
// x = -(105 cos t1 + 120 cos(t1 + t2)): least -225 (t1 = t2 = 0), greatest
// with t1 at E's range end 117.5 degrees and t1 + t2 = 180:
// -(105 cos 117.5 - 120) = 168.4836 (whole counts: within 1e-3).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/models/models_support.h"

namespace {

using nlohmann::json;
using rs::testing::runCli;

json describeJson(const std::string& name) {
  const auto r = runCli({"describe", name, "--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  REQUIRE(json::accept(r.out));
  return json::parse(r.out);
}

void checkVec(const json& v, double x, double y, double z, double margin = 1e-9) {
  REQUIRE(v.size() == 3);
  CHECK(v[0].get<double>() == Approx(x).margin(margin));
  CHECK(v[1].get<double>() == Approx(y).margin(margin));
  CHECK(v[2].get<double>() == Approx(z).margin(margin));
}

}  // namespace

TEST_CASE("describe: scara-pick objects, boxes, centres and what each stands on", "[models][describe]") {
  const json j = describeJson("scara-pick");
  CHECK(j["cell"] == "scara-pick");
  CHECK(j["frame"] == "world");
  const json& o = j["objects"];
  REQUIRE(o.size() == 5);
  const char* names[] = {"table", "pallet", "block", "block", "block"};
  const double box[5][6] = {{-500, 0, -250, 300, 750, 250},   {-330, 750, -80, -90, 780, 80},
                            {-200, 780, -65, -160, 820, -25}, {-200, 780, 25, -160, 820, 65},
                            {-150, 780, -20, -110, 820, 20}};
  for (std::size_t i = 0; i < 5; ++i) {
    INFO("object " << i + 1);
    CHECK(o[i]["object"] == i + 1);
    CHECK(o[i]["name"] == names[i]);
    checkVec(o[i]["min"], box[i][0], box[i][1], box[i][2]);
    checkVec(o[i]["max"], box[i][3], box[i][4], box[i][5]);
    checkVec(o[i]["centre"], (box[i][0] + box[i][3]) / 2, (box[i][1] + box[i][4]) / 2, (box[i][2] + box[i][5]) / 2);
  }
  CHECK(o[0]["on"] == json({{"kind", "floor"}}));
  CHECK(o[1]["on"] == json({{"kind", "object"}, {"object", 1}, {"name", "table"}}));
  for (std::size_t i = 2; i < 5; ++i) CHECK(o[i]["on"] == json({{"kind", "object"}, {"object", 2}, {"name", "pallet"}}));
  CHECK(j["inputs"] == 8);
  CHECK(j["outputs"] == 8);
}

TEST_CASE("describe: scara-pick robot, motors, home, reach and base", "[models][describe]") {
  const json j = describeJson("scara-pick");
  REQUIRE(j["robots"].size() == 1);
  const json& r = j["robots"][0];
  CHECK(r["name"] == "rhino-scara");
  checkVec(r["frame0"]["origin"], 0, 750, 0);
  checkVec(r["frame0"]["x"], -1, 0, 0);
  checkVec(r["frame0"]["z"], 0, 1, 0);
  const json motors = r["motors"];
  REQUIRE(motors.size() == 5);
  const char* letters[] = {"E", "D", "C", "B", "A"};
  const char* types[] = {"revolute", "revolute", "prismatic", "revolute", "gripper"};
  const double precision[] = {0.1175, 0.2233, 0.12, 0.2233, 0.5};
  const int lo[] = {-1000, -550, -350, -700, 0}, hi[] = {1000, 550, 350, 700, 120}, speed[] = {400, 400, 300, 500, 200};
  for (std::size_t m = 0; m < 5; ++m) {
    INFO("motor " << letters[m]);
    CHECK(motors[m]["letter"] == letters[m]);
    CHECK(motors[m]["type"] == types[m]);
    CHECK(motors[m]["precision"].get<double>() == precision[m]);
    CHECK(motors[m]["unit"] == (m == 2 ? "length" : "deg"));
    CHECK(motors[m]["min"] == lo[m]);
    CHECK(motors[m]["max"] == hi[m]);
    CHECK(motors[m]["speed"] == speed[m]);
    CHECK(motors[m]["coupling"] == false);
  }
  checkVec(r["home_tcp"], -225, 840, 0);
  CHECK(r["reach"]["radius"].get<double>() == Approx(225).margin(1e-6));
  const double farX = -(105 * std::cos(117.5 * M_PI / 180) - 120);
  checkVec(r["reach"]["min"], -225, 798, -225, 1e-3);
  checkVec(r["reach"]["max"], farX, 882, 225, 1e-3);
  checkVec(r["base"]["min"], -90, 750, -75);
  checkVec(r["base"]["max"], 60, 1000, 75);
  CHECK(r["base"]["on"] == json({{"kind", "object"}, {"object", 1}, {"name", "table"}}));
}

TEST_CASE("describe: the text form of scara-pick, line by line", "[models][describe]") {
  const auto r = runCli({"describe", "scara-pick"});
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  // The same numbers as the JSON test, as a student reads them.
  for (const char* line : {
           "workcell scara-pick: world coordinates, y up, lengths in the cell's unit\n",
           "robot rhino-scara (runs the program)\n",
           "  frame 0  origin (0, 750, 0), x0 (-1, 0, 0), z0 (0, 1, 0) (z0 is joint 1's axis)\n",
           "  E      revolute       0.1175 deg    -1000..1000        400  off\n",
           "  C      prismatic            0.12      -350..350        300  off\n",
           "  A      gripper           0.5 deg         0..120        200  (0 open, 120 closed)\n",
           "  tool centre point at home (every motor at 0): (-225, 840, 0)\n",
           "  reach    225 from joint E's axis (tool centre point)\n",
           "  span     x -225..168.4836  y 798..882  z -225..225 (tool centre point)\n",
           "  base     x -90..60  y 750..1000  z -75..75, on table (object 1)\n",
           "object 2  pallet\n  box     x -330..-90  y 750..780  z -80..80\n  centre  (-210, 765, 0)\n"
           "  on      table (object 1)\n",
           "object 5  block\n  box     x -150..-110  y 780..820  z -20..20\n  centre  (-130, 800, 0)\n"
           "  on      pallet (object 2)\n",
           "inputs 1..8 and outputs 1..8: the controller's lines (descriptions do not name them)\n",
       })
    CHECK_THAT(r.out, Catch::Contains(line));
}

TEST_CASE("describe: a block between a conveyor's guides stands on its belt", "[models][describe]") {
  // scorobot-cell: the conveyor (stdlib/objects/conveyor.rsd: belt top at
  // y 500, side guides up to 530) AT 300 0 750 spans x 300..1800, z
  // 450..750; the block AT 600 500 620 sits at y 500..540, x 600..640, z
  // 580..620: on the belt, below the guides' top. The pallet AT 500 0 -400
  // is on the floor and the block AT 540 30 -440 on its deck (y 30).
  const json j = describeJson("scorobot-cell");
  const json& o = j["objects"];
  REQUIRE(o.size() == 4);
  CHECK(o[1]["on"] == json({{"kind", "object"}, {"object", 1}, {"name", "conveyor"}}));
  CHECK(o[2]["on"] == json({{"kind", "floor"}}));
  CHECK(o[3]["on"] == json({{"kind", "object"}, {"object", 3}, {"name", "pallet"}}));
  // ROTATE X -90 turns scorobot's z0 (design +z) to world +y.
  checkVec(j["robots"][0]["frame0"]["z"], 0, 1, 0);
}

TEST_CASE("describe: a robot alone, in its design coordinates, and a block floating", "[models][describe]") {
  rs::testing::TempDir dir;
  const std::string cell = dir.write("float.rsd", rs::testing::lines({
                                                      "WORKCELL float",
                                                      "  ROBOT gantry AT 0 1000 0",
                                                      "  OBJECT block AT 0 10 0",
                                                      "END",
                                                  }));
  const json f = describeJson(cell);
  CHECK(f["objects"][0]["on"] == json({{"kind", "nothing"}}));
  // The gantry's first joint slides: no radius.
  CHECK(f["robots"][0]["reach"]["radius"].is_null());

  const json j = describeJson("rhino-scara");
  CHECK(j["cell"].is_null());
  CHECK(j["frame"] == "design");
  CHECK(j["objects"].empty());
  checkVec(j["robots"][0]["home_tcp"], -135, -35, 0);
  const auto text = runCli({"describe", "rhino-scara"});
  CHECK_THAT(text.out, Catch::StartsWith("robot rhino-scara alone: its design coordinates"));
  const auto bad = runCli({"describe", "no-such-cell"});
  CHECK(bad.code == 2);
  CHECK(bad.err == "no-such-cell: error: no such file, and no workcell or robot of that name on the library path\n");
}

TEST_CASE("describe: a gantry whose feet stand beside a pallet's runners is on the floor", "[models][describe]") {
  // gantry-cell: the gantry's frame reaches y = 0 (its feet) over x
  // -100..1100, z -20..820, which covers the pallet AT 150 0 760 (x
  // 150..390, z 600..760, runners from y 0); the pallet's lines at y = 0
  // are its own bottom, which holds nothing up.
  const json j = describeJson("gantry-cell");
  CHECK(j["robots"][0]["base"]["on"] == json({{"kind", "floor"}}));
  CHECK(j["objects"][0]["on"] == json({{"kind", "floor"}}));
  CHECK(j["objects"][1]["on"] == json({{"kind", "object"}, {"object", 1}, {"name", "pallet"}}));
}

TEST_CASE("describe: how far a gripper's fingers reach and how wide they open", "[models][describe][devices][slow]") {
  // abb-irb120.rsd by hand: the tool centre point at x = 454, a = +x; the
  // fingers' boxes run x 394..474 (20 past it) with inner faces at z = 24
  // and z = -24 (48 apart).
  const auto r = runCli({"describe", "irb120-cell"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("  fingers  reach 20 below the tool centre point (along a), open 48 wide (as drawn)\n"));
  const auto j = runCli({"describe", "irb120-cell", "--json"});
  REQUIRE(j.code == 0);
  const auto doc = nlohmann::json::parse(j.out);
  CHECK(doc["robots"][0]["fingers"]["reach"].get<double>() == Approx(20));
  CHECK(doc["robots"][0]["fingers"]["opening"].get<double>() == Approx(48));
}

TEST_CASE("describe: every library cell's gripper opens wider than the library's block", "[models][describe][devices][slow]") {
  // block.rsd: a 40 cube. The five grippers widened for honest grasping
  // have their inner faces 24 either side of the tool axis by their files
  // (48 apart; the Adept One's 30, 60 apart, for a block turned any way);
  // the gantry's and SCOROBOT's were wider already.
  const std::pair<const char*, double> widened[] = {
      {"xr4-cell", 48}, {"irb120-cell", 48}, {"adept-cell", 60}, {"puma-cell", 48}, {"rv-m1-cell", 48}};
  for (const auto& [cell, opening] : widened) {
    INFO(cell);
    const auto j = runCli({"describe", cell, "--json"});
    REQUIRE(j.code == 0);
    CHECK(nlohmann::json::parse(j.out)["robots"][0]["fingers"]["opening"].get<double>() == Approx(opening));
  }
  for (const char* cell : {"gantry-cell", "scorobot-cell"}) {  // scara-pick: the paper's gripper, 17 wide (not widened)
    INFO(cell);
    const auto j = runCli({"describe", cell, "--json"});
    REQUIRE(j.code == 0);
    const auto doc = nlohmann::json::parse(j.out);
    REQUIRE(doc["robots"][0].contains("fingers"));
    CHECK(doc["robots"][0]["fingers"]["opening"].get<double>() > 40);
  }
}

// adept-cell's device lines (stdlib/workcells/adept-cell.rsd), the numbers
// as the file writes them: objects 1 infeed, 2 and 3 block, 4 outfeed;
//   CONVEYOR infeed  SPEED 100 RUN OUT 1
//   CONVEYOR outfeed SPEED 100 RUN ON
//   FEEDER   parts   block AT -740 500 620 EVERY 6
//   SENSOR   eye     BEAM 300 520 440  300 520 760
//   WIRE     eye TO IN 1
//   SINK     done    ZONE 640 760 600 500 -750 -450  (x 640..760, y 500..600, z -750..-450)
TEST_CASE("describe: adept-cell's devices and the wire to input 1, in JSON", "[models][describe][devices]") {
  const json j = describeJson("adept-cell");
  const json& d = j["devices"];
  REQUIRE(d["sensors"].size() == 1);
  CHECK(d["sensors"][0]["name"] == "eye");
  CHECK(d["sensors"][0]["kind"] == "beam");
  checkVec(d["sensors"][0]["from"], 300, 520, 440);
  checkVec(d["sensors"][0]["to"], 300, 520, 760);
  CHECK(d["sensors"][0]["sees"] == "parts");
  REQUIRE(d["conveyors"].size() == 2);
  CHECK(d["conveyors"][0] == json({{"name", "infeed"}, {"object", 1}, {"speed", 100.0}, {"run", {{"kind", "output"}, {"number", 1}}}}));
  CHECK(d["conveyors"][1] == json({{"name", "outfeed"}, {"object", 4}, {"speed", 100.0}, {"run", {{"kind", "on"}}}}));
  REQUIRE(d["feeders"].size() == 1);
  const json& f = d["feeders"][0];
  CHECK(f["name"] == "parts");
  CHECK(f["object"] == "block");
  checkVec(f["at"], -740, 500, 620);
  CHECK(f["every"] == 6.0);
  CHECK(f["when"].is_null());
  CHECK(f["count"].is_null());
  REQUIRE(d["sinks"].size() == 1);
  CHECK(d["sinks"][0]["name"] == "done");
  checkVec(d["sinks"][0]["min"], 640, 500, -750);
  checkVec(d["sinks"][0]["max"], 760, 600, -450);
  CHECK(j["wires"] == json::array({{{"input", 1},
                                    {"robot", nullptr},
                                    {"source", {{"kind", "sensor"}, {"sensor", "eye"}}},
                                    {"after", 0.0},
                                    {"inverted", false}}}));
  // A cell without devices lists none.
  const json plain = describeJson("scara-pick");
  CHECK(plain["devices"] == json({{"sensors", json::array()}, {"conveyors", json::array()}, {"feeders", json::array()},
                                  {"sinks", json::array()}}));
  CHECK(plain["wires"] == json::array());
}

TEST_CASE("describe: adept-cell's devices in text, the language server's hover sentences", "[models][describe][devices]") {
  const auto r = runCli({"describe", "adept-cell"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out,
             Catch::Contains("\ndevices\n"
                             "  sensor `eye`: a beam from (300, 520, 440) to (300, 520, 760); on while it sees parts across it\n"
                             "  conveyor `infeed`: runs its belt at 100 length units per second while output 1 is on "
                             "(the belt of object 1)\n"
                             "  conveyor `outfeed`: runs its belt at 100 length units per second always (the belt of object 4)\n"
                             "  feeder `parts`: puts a `block` at (-740, 500, 620) at the start and then every 6 s\n"
                             "  sink `done`: a part whose centre enters the zone from (640, 500, -750) to (760, 600, -450) "
                             "leaves the cell, counted\n"
                             "  wire: input 1 follows sensor `eye`\n"
                             "\ninputs 1..8 and outputs"));
  CHECK(runCli({"describe", "scara-pick"}).out.find("devices") == std::string::npos);
}

TEST_CASE("describe: a zone that sees all, a feeder on a signal, a wire AFTER and INVERTED", "[models][describe][devices]") {
  // The ZONE's edges left right top bottom front back: x 0..100, y
  // 500..600, z 650..700.
  rs::testing::TempDir dir;
  const std::string cell = dir.write("dev.rsd", rs::testing::lines({
                                                    "WORKCELL dev",
                                                    "  ROBOT adept-one AT 0 0 0",
                                                    "  OBJECT conveyor AT -750 0 750 AS belt",
                                                    "  SENSOR eye ZONE 0 100 600 500 700 650 SEES ALL",
                                                    "  CONVEYOR belt SPEED 50 RUN eye",
                                                    "  FEEDER more block AT -740 500 620 WHEN OUT 2 COUNT 3",
                                                    "  WIRE eye TO IN 2 AFTER 0.5 INVERTED",
                                                    "  WIRE OUT 3 TO IN 4",
                                                    "END",
                                                }));
  const json j = describeJson(cell);
  const json& d = j["devices"];
  REQUIRE(d["sensors"].size() == 1);
  CHECK(d["sensors"][0]["kind"] == "zone");
  checkVec(d["sensors"][0]["min"], 0, 500, 650);
  checkVec(d["sensors"][0]["max"], 100, 600, 700);
  CHECK(d["sensors"][0]["sees"] == "all");
  CHECK(d["conveyors"][0]["run"] == json({{"kind", "sensor"}, {"sensor", "eye"}}));
  CHECK(d["feeders"][0]["every"].is_null());
  CHECK(d["feeders"][0]["when"] == json({{"kind", "output"}, {"number", 2}}));
  CHECK(d["feeders"][0]["count"] == 3);
  REQUIRE(j["wires"].size() == 2);
  CHECK(j["wires"][0]["input"] == 2);
  CHECK(j["wires"][0]["after"] == 0.5);
  CHECK(j["wires"][0]["inverted"] == true);
  CHECK(j["wires"][1]["source"] == json({{"kind", "output"}, {"number", 3}}));
  const auto r = runCli({"describe", cell});
  REQUIRE(r.code == 0);
  for (const char* line : {
           "  sensor `eye`: a zone from (0, 500, 650) to (100, 600, 700); on while it sees parts and robots in it\n",
           "  conveyor `belt`: runs its belt at 50 length units per second while sensor `eye` is on (the belt of object 1)\n",
           "  feeder `more`: puts a `block` at (-740, 500, 620) on each rising edge of output 2, at most 3\n",
           "  wire: input 2 follows sensor `eye`, 0.5 s later, inverted\n",
           "  wire: input 4 follows output 3\n",
       })
    CHECK_THAT(r.out, Catch::Contains(line));
}
