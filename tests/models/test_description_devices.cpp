// A WORKCELL's devices and an OBJECT's PART, FIXTURE and BELT (issue 35,
// docs/models.md "Devices"): what the reader builds from them, and each
// mistake's exact, positioned diagnostic. Columns were counted by hand
// (1-based); the expected numbers are the lines' own.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "tests/models/description_errors_support.h"

namespace devices_test {

using rs::testing::lines;
using rs::testing::Strings;
using rs::testing::TempDir;

// A 100 x 40 belt (top y 10, x 0..100, z 5..45) and a 10-unit part, on
// lines 1..9; a workcell's lines follow from line 10.
const std::string kObjects = lines({
    "OBJECT belt",                                   // 1
    "  BOX 0 100 10 0 50 0",                         // 2
    "  BELT 0 100 10 0 45 5 DIRECTION 2 0 0",        // 3
    "END",                                           // 4
    "object blk",                                    // 5 (keywords in any case)
    "  part",                                        // 6
    "  BOX 0 10 10 0 10 0",                          // 7
    "END",                                           // 8
    "; the cell",                                    // 9
});

std::string cell(const Strings& body) {
  Strings all{"WORKCELL c", "  OBJECT belt AT 0 0 50 AS line1", "  OBJECT belt AT 0 0 200"};  // 10..12
  all.insert(all.end(), body.begin(), body.end());                                           // from 13
  all.push_back("END");
  return kObjects + lines(all);
}

Strings errors(const Strings& body) {
  TempDir dir;
  dir.write("c.rsd", cell(body));
  return rs::testing::workcellErrors(dir, "c.rsd");
}

// The diagnostics of `text` as c.rsd, hints and all.
std::vector<rs::diag::Diagnostic> diagnosticsOf(const std::string& text) {
  TempDir dir;
  dir.write("c.rsd", text);
  rs::compiler::Library lib({dir.path()});
  CHECK_FALSE(lib.workcell(dir.file("c.rsd")));
  return lib.diagnostics();
}

// The one diagnostic of a workcell line (on line 13), as "col: message | hint".
std::string mistake(const std::string& line) {
  const std::vector<rs::diag::Diagnostic> d = diagnosticsOf(cell({line}));
  REQUIRE(d.size() == 1);
  CHECK(d[0].pos.line == 13);
  return fmt::format("{}: {} | {}", d[0].pos.col, d[0].message, d[0].hint);
}

}  // namespace devices_test

using devices_test::errors;

TEST_CASE("description devices: a cell's devices are read and resolved", "[models][devices]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", devices_test::cell({
                         "  conveyor LINE1 speed 50 run out 2",                  // 13
                         "  SENSOR eye BEAM 90 15 0  90 15 60 SEES ALL",         // 14
                         "  SENSOR bay ZONE 0 10 20 10 50 0",                    // 15
                         "  FEEDER f blk AT 0 10 20 WHEN eye COUNT 3",           // 16
                         "  FEEDER g blk AT 20 10 20 EVERY 0.25",                // 17
                         "  SINK done ZONE 90 100 30 10 50 0",                   // 18
                         "  WIRE eye TO IN 1 AFTER 1.5 INVERTED",                // 19
                         "  WIRE OFF TO IN 8",                                   // 20
                         "  OBJECT blk AT 50 10 20 FIXTURE",                     // 21
                     }));
  rs::compiler::Library lib({dir.path()});
  const auto c = lib.workcell(dir.file("c.rsd"));
  INFO(rs::testing::joined(rs::testing::diagnosticList(lib.diagnostics(), dir.path().string())));
  REQUIRE(c);
  using namespace rs::workcell;
  REQUIRE(c->objects.size() == 3);
  CHECK(c->objects[0].name == "line1");
  CHECK(c->objects[1].name == "belt");  // no AS: the description's name
  CHECK(c->objects[0].kind == ObjectKind::Fixture);  // the default
  CHECK(c->objects[2].kind == ObjectKind::Fixture);  // the line overrides blk's PART
  REQUIRE(c->objects[0].belt);
  CHECK(c->objects[0].belt->direction == Eigen::Vector3d::UnitX());  // 2 0 0, made unit
  CHECK(c->objects[0].belt->surface.max() == Eigen::Vector3d(100, 10, 45));
  CHECK(c->objects[0].belt->pos.line == 3);
  const Devices& d = c->devices;
  REQUIRE(d.conveyors.size() == 1);
  CHECK(d.conveyors[0].object == 0);
  CHECK(d.conveyors[0].speed == 50);
  CHECK(d.conveyors[0].run.kind == Signal::Kind::Output);
  CHECK(d.conveyors[0].run.number == 2);
  CHECK(d.conveyors[0].pos.line == 13);
  REQUIRE(d.sensors.size() == 2);
  CHECK(d.sensors[0].shape == Sensor::Shape::Beam);
  CHECK(d.sensors[0].sees == Sensor::Sees::All);
  CHECK(d.sensors[1].sees == Sensor::Sees::Parts);
  CHECK(d.sensors[1].zone.min() == Eigen::Vector3d(0, 10, 0));
  CHECK(d.sensors[1].zone.max() == Eigen::Vector3d(10, 20, 50));
  REQUIRE(d.feeders.size() == 2);
  CHECK(d.feeders[0].when->kind == Signal::Kind::Sensor);
  CHECK(d.feeders[0].when->sensor == 0);
  CHECK(d.feeders[0].count == 3);
  CHECK_FALSE(d.feeders[0].everyUs);
  CHECK(d.feeders[1].everyUs == 250'000);
  CHECK_FALSE(d.feeders[1].count);
  CHECK(d.feeders[0].part == d.feeders[1].part);  // one copy of blk for both
  REQUIRE(c->fedParts.size() == 1);
  CHECK(c->fedParts[0].kind == ObjectKind::Part);
  CHECK(c->fedParts[0].name == "blk");
  REQUIRE(d.sinks.size() == 1);
  REQUIRE(d.wires.size() == 2);
  CHECK(d.wires[0].input == 1);
  CHECK(d.wires[0].afterUs == 1'500'000);
  CHECK(d.wires[0].inverted);
  CHECK(d.wires[0].source.sensor == 0);
  CHECK(d.wires[1].source.kind == Signal::Kind::Off);
  CHECK(d.wires[1].pos.line == 20);
  CHECK(d.wires[1].pos.col == 3);
}

TEST_CASE("description devices: each mistake in a device line is positioned", "[models][devices]") {
  using Strings = devices_test::Strings;
  CHECK(errors({"  CONVEYOR line1 SPEED 0 RUN ON"}) ==
        Strings{"c.rsd:13:24: a conveyor's SPEED must be more than 0 and at most 1000000, found 0"});
  CHECK(errors({"  CONVEYOR line1 SPEED 5 RUN"}) ==
        Strings{"c.rsd:13:29: expected a signal: a sensor's name, OUT n, LABEL.OUT n, ON or OFF before the end of the line"});
  CHECK(errors({"  WIRE OUT 9 TO IN 1"}) == Strings{"c.rsd:13:12: output 9 does not exist: the lines are numbered 1..8"});
  CHECK(errors({"  WIRE ON TO IN 0"}) == Strings{"c.rsd:13:17: input 0 does not exist: the lines are numbered 1..8"});
  CHECK(errors({"  WIRE ON TO OUT 1"}) == Strings{"c.rsd:13:14: expected IN or LABEL.IN, found 'OUT'"});
  CHECK(errors({"  SINK s ZONE 0 0 10 0 10 0"}) ==
        Strings{"c.rsd:13:15: the ZONE has no volume: two of its opposite edges are the same"});
  CHECK(errors({"  SENSOR s BEAM 1 2 3 1 2 3"}) == Strings{"c.rsd:13:17: the beam's two ends are the same point"});
  CHECK(errors({"  SENSOR s ZONE 0 10 20 10 50 0 SEES NOBODY"}) ==
        Strings{"c.rsd:13:38: expected ROBOTS or ALL, found 'NOBODY'"});
  CHECK(errors({"  FEEDER f blk AT 0 10 20 EVERY 0"}) ==
        Strings{"c.rsd:13:33: EVERY must be more than 0 seconds and at most a year, found 0"});
  CHECK(errors({"  FEEDER f blk AT 0 10 20 EVERY 1 COUNT 0"}) ==
        Strings{"c.rsd:13:41: a feeder's COUNT must be 1 or more, found 0"});
  CHECK(errors({"  FEEDER f blk AT 0 10 20"}) ==
        Strings{"c.rsd:13:26: expected EVERY or WHEN before the end of the line"});
}

TEST_CASE("description devices: names and places are checked when the cell is built", "[models][devices]") {
  using Strings = devices_test::Strings;
  // Unknown names.
  CHECK(errors({"  CONVEYOR nowhere SPEED 5 RUN ON"}) ==
        Strings{"c.rsd:13:12: unknown object 'nowhere': no OBJECT line of this workcell places it or names it so"});
  CHECK(errors({"  WIRE eye TO IN 1"}) == Strings{"c.rsd:13:8: unknown sensor 'eye'"});
  CHECK(errors({"  CONVEYOR line1 SPEED 5 RUN eye"}) == Strings{"c.rsd:13:30: unknown sensor 'eye'"});
  CHECK(errors({"  FEEDER f nothing AT 0 10 20 EVERY 1"}) ==
        Strings{"c.rsd:13:12: unknown object 'nothing': not defined in this file, and no nothing.rsd beside it or on "
                "the library path"});
  // Two objects share the name a conveyor gives; a second conveyor, sensor name.
  CHECK(errors({"  OBJECT belt AT 0 0 100", "  CONVEYOR belt SPEED 5 RUN ON"}) == Strings{"c.rsd:14:12: two objects of this workcell are named 'belt'"});
  CHECK(errors({"  CONVEYOR line1 SPEED 5 RUN ON", "  CONVEYOR LINE1 SPEED 5 RUN OFF"}) ==
        Strings{"c.rsd:14:12: a second CONVEYOR for 'LINE1' (the first is at line 13)"});
  CHECK(errors({"  SENSOR eye BEAM 0 15 0 90 15 0", "  SINK eye ZONE 90 100 30 10 50 0"}) ==
        Strings{"c.rsd:14:8: a second device named 'eye' (the first is at line 13)"});
  // A belt on an object without one.
  CHECK(errors({"  OBJECT blk AT 0 10 20 AS b", "  CONVEYOR b SPEED 5 RUN ON"}) ==
        Strings{"c.rsd:14:12: object 'b' (blk) has no BELT to run"});
  // A sensor out of the cell (it spans x 0..100, y 0..10, z 0..200, grown by 200/4).
  CHECK(errors({"  SENSOR far ZONE 1000 1010 10 0 10 0"}) ==
        Strings{"c.rsd:13:10: sensor 'far' is out of the cell: it is nowhere near what the cell holds "
                "(x -50..150, y -50..60, z -50..250)"});
  CHECK(errors({"  SENSOR low BEAM 0 -5 0 10 -5 0"}) ==
        Strings{"c.rsd:13:10: sensor 'low' is out of the cell: it is under the floor"});
  // A feeder's place overlapping a fixture: blk at y 5..15 sinks into the belt (top y 10); on it, it does not.
  CHECK(errors({"  FEEDER f blk AT 20 5 20 EVERY 1"}) ==
        Strings{"c.rsd:13:10: feeder 'f' puts its blk inside fixture 'line1' (at line 11): the part would span "
                "x 20..30, y 5..15, z 10..20"});
  CHECK(errors({"  FEEDER f blk AT 20 10 20 EVERY 1"}).empty());
  // A second source for one input: the error is at the second.
  CHECK(errors({"  WIRE ON TO IN 3", "  WIRE OUT 1 TO IN 2", "  WIRE OFF TO IN 3 AFTER 2"}) ==
        Strings{"c.rsd:15:3: input 3 has a second source: the WIRE at line 13 drives it already"});
}

TEST_CASE("description devices: PART, FIXTURE and BELT belong in an OBJECT", "[models][devices]") {
  rs::testing::TempDir dir;
  dir.write("c.rsd", rs::testing::lines({"OBJECT o", "  BOX 0 1 1 0 1 0", "  BELT 0 1 1 0 1 1 DIRECTION 1 0 0", "END",
                            "OBJECT p", "  BELT 0 1 1 0 1 0 DIRECTION 0 0 0", "END", "LINK l", "  PART", "END",
                            "WORKCELL c", "  OBJECT o AT 0 0 0", "  OBJECT p AT 0 0 0", "END"}));
  const devices_test::Strings d = rs::testing::workcellErrors(dir, "c.rsd");
  CHECK(d == devices_test::Strings{
                 "c.rsd:3:3: the BELT's top has no area: its left and right edges, or its front and back, are the same",
                 "c.rsd:6:30: the belt's DIRECTION is zero",
                 "c.rsd:9:3: expected a LINK statement, found 'PART'",
             });
}

TEST_CASE("description devices: the library's conveyor cells read with their devices", "[models][devices][library]") {
  rs::compiler::Library lib({std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib"});
  for (const char* name : {"adept-cell", "scorobot-cell"}) {
    CAPTURE(name);
    const auto c = lib.workcell(name);
    REQUIRE(c);
    const rs::workcell::Devices& d = c->devices;
    CHECK(d.conveyors.size() >= 1);
    CHECK(d.sensors.size() == 1);
    CHECK(d.feeders.size() == 1);
    CHECK(d.sinks.size() == 1);
    CHECK(d.wires.size() == 1);
    for (const rs::workcell::PlacedObject& o : c->objects)
      CHECK((o.kind == rs::workcell::ObjectKind::Part) == (o.shape.name == "block"));
  }
}

TEST_CASE("description devices: 100,000 device lines, each mistake reported once", "[models][devices]") {
  // Linear by construction (every name a hash-map look-up); what this checks
  // is that each of 50,000 wires past the first eight is reported, at its
  // own line, and nothing else: a look-up that scanned the lines before
  // would show as a run of minutes here, and bench/ times the reader.
  constexpr int kEach = 50'000;
  std::string body = "WORKCELL c\n  OBJECT blk AT 0 0 10\n";
  for (int i = 0; i < kEach; ++i) body += fmt::format("  SENSOR s{} ZONE 0 10 10 0 10 0\n", i);
  for (int i = 0; i < kEach; ++i) body += fmt::format("  WIRE s{} TO IN {}\n", kEach - 1 - i, i % 8 + 1);
  body += "END\n";
  rs::testing::TempDir dir;
  dir.write("c.rsd", devices_test::kObjects + body);
  rs::compiler::Library lib({dir.path()});
  CHECK_FALSE(lib.workcell(dir.file("c.rsd")));
  const auto& d = lib.diagnostics();
  REQUIRE(d.size() == static_cast<std::size_t>(kEach - 8));
  const std::uint32_t firstWire = 9 + 2 + kEach + 1;  // kObjects, WORKCELL and OBJECT, the sensors
  CHECK(d.front().pos.line == firstWire + 8);
  CHECK(d.back().pos.line == firstWire + kEach - 1);
  CHECK(d.back().message == fmt::format("input {} has a second source: the WIRE at line {} drives it already",
                                        (kEach - 1) % 8 + 1, firstWire + (kEach - 1) % 8));
}

TEST_CASE("description devices: every mistake in a device line has a hint", "[models][devices]") {
  // One bad line for each error the reader and the resolver raise; the
  // table test checks that each is alone, on its line, with a hint.
  const devices_test::Strings bad{
      "  CONVEYOR 5 SPEED 5 RUN ON",                       // a name expected
      "  CONVEYOR line1 FAST 5 RUN ON",                    // SPEED expected
      "  CONVEYOR line1 SPEED fast RUN ON",                // a number expected
      "  CONVEYOR line1 SPEED 0 RUN ON",                   // out of range
      "  CONVEYOR line1 SPEED 5 ON",                       // RUN expected
      "  CONVEYOR line1 SPEED 5 RUN TO",                   // a signal expected
      "  CONVEYOR line1 SPEED 5 RUN OUT 9",                // no such output
      "  CONVEYOR line1 SPEED 5 RUN OUT 1.5",              // not a whole number
      "  CONVEYOR line1 SPEED 1e3 RUN ON",                 // an exponent
      "  CONVEYOR nowhere SPEED 5 RUN ON",                 // unknown object
      "  CONVEYOR line1 SPEED 5 RUN eye",                  // unknown sensor
      "  CONVEYOR line1 SPEED 5 RUN nobody.OUT 1",         // unknown robot label
      "  CONVEYOR line1 SPEED 5 RUN ON AT 1 2 3",          // words after the line
      "  OBJECT blk AT 0 10 20 CONVEYOR line1 SPEED 5 RUN ON",  // not at the line's start
      "  FEEDER 7 blk AT 0 10 20 EVERY 1",                 // a name expected
      "  FEEDER f 7 AT 0 10 20 EVERY 1",                   // an object name expected
      "  FEEDER f blk 0 10 20 EVERY 1",                    // AT expected
      "  FEEDER f blk AT 0 10 EVERY 1",                    // a point expected
      "  FEEDER f blk AT 0 10 20 SOMETIMES",               // EVERY or WHEN expected
      "  FEEDER f blk AT 0 10 20 EVERY soon",              // seconds expected
      "  FEEDER f blk AT 0 10 20 EVERY 0",                 // out of range
      "  FEEDER f blk AT 0 10 20 WHEN",                    // a signal expected
      "  FEEDER f blk AT 0 10 20 EVERY 1 COUNT many",      // a count expected
      "  FEEDER f blk AT 0 10 20 EVERY 1 COUNT 0",         // out of range
      "  FEEDER f blk AT 0 10 20 EVERY 1 COUNT 2 COUNT 3", // COUNT twice
      "  FEEDER f nothing AT 0 10 20 EVERY 1",             // unknown object description
      "  FEEDER f blk AT 20 5 20 EVERY 1",                 // inside a fixture
      "  SENSOR 3 BEAM 0 15 0 90 15 0",                    // a name expected
      "  SENSOR s BOX 0 15 0 90 15 0",                     // BEAM or ZONE expected
      "  SENSOR s BEAM 0 15 0 90 15",                      // a point expected
      "  SENSOR s BEAM 1 2 3 1 2 3",                       // the same point
      "  SENSOR s ZONE 0 10 20 10 50",                     // an edge expected
      "  SENSOR s ZONE 0 0 20 10 50 0",                    // no volume
      "  SENSOR s ZONE 0 10 20 10 50 0 SEES NOBODY",       // ROBOTS or ALL expected
      "  SENSOR far ZONE 1000 1010 10 0 10 0",             // out of the cell
      "  SENSOR low BEAM 0 -5 0 10 -5 0",                  // under the floor
      "  SENSOR s ZONE 0 10 20 10 50 0 SEES ALL SEES ROBOTS",  // SEES twice
      "  SINK 4 ZONE 0 10 20 10 50 0",                     // a name expected
      "  SINK s BEAM 0 10 20 10 50 0",                     // ZONE expected
      "  SINK s ZONE 0 10 20 10 50 x",                     // an edge expected
      "  SINK s ZONE 0 0 10 0 10 0",                       // no volume
      "  SINK far ZONE 1000 1010 10 0 10 0",               // out of the cell
      "  WIRE ON IN 1",                                    // TO expected
      "  WIRE ON TO OUT 1",                                // IN expected
      "  WIRE ON TO IN",                                   // a number expected
      "  WIRE ON TO IN 0",                                 // no such input
      "  WIRE ON TO IN 1 AFTER -1",                        // out of range
      "  WIRE ON TO IN 1 AFTER later",                     // seconds expected
      "  WIRE ON TO nobody.IN 1",                          // unknown robot label
      "  WIRE ey TO IN 1",                                 // unknown sensor
      "  WIRE ON TO IN 1 INVERTED AFTER 1",                // out of order
      "  WIRE ON TO IN 1 # a comment?",                    // an unexpected character
  };
  for (const std::string& line : bad) {
    CAPTURE(line);
    const std::string m = devices_test::mistake(line);
    CAPTURE(m);
    CHECK(m.size() > 3);
    CHECK(m.substr(m.size() - 3) != " | ");  // a hint
  }
  // Two-line mistakes: the second line is the error.
  const std::vector<devices_test::Strings> pairs{
      {"  SENSOR eye BEAM 0 15 0 90 15 0", "  SINK eye ZONE 90 100 30 10 50 0"},  // a second device named so
      {"  OBJECT belt AT 0 0 100", "  CONVEYOR belt SPEED 5 RUN ON"},             // two objects named so
      {"  OBJECT blk AT 0 10 20 AS b", "  CONVEYOR b SPEED 5 RUN ON"},            // no BELT
      {"  CONVEYOR line1 SPEED 5 RUN ON", "  CONVEYOR LINE1 SPEED 5 RUN OFF"},   // a second CONVEYOR
      {"  WIRE ON TO IN 3", "  WIRE OFF TO IN 3"},                              // a second source
  };
  for (const devices_test::Strings& body : pairs) {
    CAPTURE(body[1]);
    const std::vector<rs::diag::Diagnostic> d = devices_test::diagnosticsOf(devices_test::cell(body));
    REQUIRE(d.size() == 1);
    CHECK(d[0].pos.line == 14);
    CHECK_FALSE(d[0].hint.empty());
  }
}

TEST_CASE("description devices: unknown names are offered the near one, extra words the line's form", "[models][devices]") {
  using devices_test::mistake;
  // The sensor, the object and the object description a near miss meant.
  CHECK(devices_test::errors({"  SENSOR eye BEAM 0 15 0 90 15 0", "  WIRE ey TO IN 1"}) ==
        devices_test::Strings{"c.rsd:14:8: unknown sensor 'ey'"});
  const auto eye = devices_test::diagnosticsOf(devices_test::cell({"  SENSOR eye BEAM 0 15 0 90 15 0", "  WIRE ey TO IN 1"}));
  REQUIRE(eye.size() == 1);
  CHECK(eye[0].hint == "did you mean 'eye'?");
  CHECK(mistake("  CONVEYOR lin1 SPEED 5 RUN ON") ==
        "12: unknown object 'lin1': no OBJECT line of this workcell places it or names it so | did you mean 'line1'?");
  CHECK(mistake("  FEEDER f blok AT 0 10 20 EVERY 1") ==
        "12: unknown object 'blok': not defined in this file, and no blok.rsd beside it or on the library path | "
        "did you mean 'blk'?");
  CHECK(mistake("  WIRE nosuch TO IN 1") ==
        "8: unknown sensor 'nosuch' | a signal is a SENSOR's name (declared in this WORKCELL), OUT n, LABEL.OUT n, ON or OFF");
  // A keyword misspelled: the one meant; a word no keyword is near: the line's form.
  CHECK(mistake("  CONVEYOR line1 SPED 5 RUN ON") == "18: expected SPEED, found 'SPED' | did you mean 'SPEED'?");
  CHECK(mistake("  SINK s ZONE 0 10 20 10 50") ==
        "28: expected the ZONE's back edge before the end of the line | a SINK line reads SINK NAME ZONE left right "
        "top bottom front back");
  // A device line stands alone: nothing after it, nothing before it.
  CHECK(mistake("  WIRE ON TO IN 1 INVERTED AFTER 1") ==
        "28: expected the end of the WIRE line, found 'AFTER' | AFTER is written once, in its place: WIRE SOURCE TO "
        "IN n [AFTER s] [INVERTED]");
  CHECK(mistake("  WIRE ON TO IN 1 INVERTD") ==
        "19: expected the end of the WIRE line, found 'INVERTD' | did you mean 'INVERTED'?");
  CHECK(mistake("  SINK s ZONE 0 10 20 10 50 0 SINK t ZONE 0 10 20 10 50 0") ==
        "31: expected the end of the SINK line, found 'SINK' | a device line stands alone: SINK NAME ZONE left right "
        "top bottom front back; start the next one on a new line");
  CHECK(mistake("  OBJECT blk AT 0 10 20 WIRE ON TO IN 1") ==
        "25: WIRE starts a line of its own: it cannot follow other words | put the WIRE line on a new line");
}

TEST_CASE("description devices: every mistake in a BELT line has a hint", "[models][devices]") {
  const devices_test::Strings bad{
      "  BELT 0 1 1 0 1",                                // an edge expected
      "  BELT 0 0 1 0 1 0 DIRECTION 1 0 0",              // no area
      "  BELT 0 1 1 0 1 0 TOWARDS 1 0 0",                // DIRECTION expected
      "  BELT 0 1 1 0 1 0 DIRECTION 1 0",                // a point expected
      "  BELT 0 1 1 0 1 0 DIRECTION 0 0 0",              // zero
      "  BELT 0 1 1 0 1 0 DIRECTION 1 0 0 END SHUT",     // OPEN expected
      "  BELT 0 1 1 0 1 0 DIRECTION 1 0 0 COLOR RED",    // words after the line
      "  PART BELT 0 1 1 0 1 0 DIRECTION 1 0 0",         // not at the line's start
      "  BELT 0 1 1 0 1 0 DIRECTION 1 0 0\n  BELT 0 1 1 0 1 0 DIRECTION 1 0 0",  // a second BELT
  };
  for (const std::string& line : bad) {
    CAPTURE(line);
    const std::vector<rs::diag::Diagnostic> d = devices_test::diagnosticsOf(
        "OBJECT o\n  BOX 0 1 1 0 1 0\n" + line + "\nEND\nWORKCELL c\n  OBJECT o AT 0 0 0\nEND\n");
    REQUIRE(d.size() == 1);
    CHECK(d[0].pos.line >= 3);
    CHECK_FALSE(d[0].hint.empty());
  }
}
