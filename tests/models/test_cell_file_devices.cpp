// The image's cell section, version 3 (issue 35): a compiled image carries
// what its WORKCELL says beyond geometry (the floor, objects' kinds, names
// and belts, robots' labels, the devices and the parts feeders copy), so an
// image runs the production its cell file runs, byte for byte; a corrupt
// section is refused or runs, never a crash.
#include <catch2/catch.hpp>

#include <string>

#include "compiler/description/library.h"
#include "model/workcell/cell_file.h"
#include "tests/cli/cli_support.h"
#include "tests/runtime/belt_and_part.h"
#include "vm/image_file.h"

namespace cellfiledevicestest {

std::string withoutFiles(std::string json) {
  // The summaries name the file they ran: the image or the program.
  for (std::size_t at = json.find("\"file\":\""); at != std::string::npos; at = json.find("\"file\":\"", at + 1))
    json.erase(at + 8, json.find('"', at + 8) - (at + 8));
  return json;
}

void fixCrcOf(std::string& image) {
  const std::uint32_t crc = rs::vm::crc32(reinterpret_cast<const std::uint8_t*>(image.data()) + 20, image.size() - 20);
  for (int i = 0; i < 4; ++i) image[static_cast<std::size_t>(16 + i)] = static_cast<char>((crc >> (8 * i)) & 0xFF);
}

}  // namespace cellfiledevicestest

using cellfiledevicestest::fixCrcOf;
using rs::testing::CliResult;
using rs::testing::runCli;
using cellfiledevicestest::withoutFiles;

TEST_CASE("cell section 3: an image of adept-cell runs the production its cell file runs", "[models][devices]") {
  rs::testing::TempDir dir;
  const std::string program = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/adept_production.rsp";
  const std::string image = dir.file("p.rsb");
  REQUIRE(runCli({"compile", program, "--cell", "adept-cell", "-o", image}).code == 0);
  const CliResult fromSource = runCli({"run", program, "--cell", "adept-cell", "--format=json"});
  const CliResult fromImage = runCli({"run", image, "--format=json"});
  REQUIRE(fromSource.code == 0);
  CHECK(fromImage.code == 0);
  // Ten blocks reach the sink only if the belts, the beam, its wire and the feeder all came along.
  CHECK(fromSource.out.find("\"sinks\":[{\"name\":\"done\",\"taken\":9}]") != std::string::npos);
  CHECK(withoutFiles(fromImage.out) == withoutFiles(fromSource.out));
  const CliResult traceSource = runCli({"run", program, "--cell", "adept-cell", "--trace"});
  const CliResult traceImage = runCli({"run", image, "--trace"});
  CHECK(traceImage.out == traceSource.out);
}

TEST_CASE("cell section 3: every fact of a device cell survives encoding", "[models][devices]") {
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  const auto cell = lib.workcell("adept-cell");
  REQUIRE(cell);
  const std::vector<std::uint8_t> bytes = rs::workcell::encodeCell(*cell);
  CHECK(bytes[4] == 3);  // the version, little-endian u16 after the magic
  const auto decoded = rs::workcell::decodeCell(bytes);
  REQUIRE(decoded.ok());
  CHECK(decoded->floor == cell->floor);
  REQUIRE(decoded->objects.size() == cell->objects.size());
  for (std::size_t i = 0; i < cell->objects.size(); ++i) {
    INFO("object " << i);
    CHECK(decoded->objects[i].kind == cell->objects[i].kind);
    CHECK(decoded->objects[i].name == cell->objects[i].name);
    CHECK(decoded->objects[i].belt.has_value() == cell->objects[i].belt.has_value());
  }
  const rs::workcell::Devices& a = decoded->devices;
  const rs::workcell::Devices& b = cell->devices;
  REQUIRE(a.conveyors.size() == 2);
  REQUIRE(a.sensors.size() == b.sensors.size());
  REQUIRE(a.feeders.size() == 1);
  REQUIRE(a.sinks.size() == 1);
  REQUIRE(a.wires.size() == 1);
  CHECK(a.conveyors[0].name == "infeed");
  CHECK(a.conveyors[0].object == b.conveyors[0].object);
  CHECK(a.conveyors[0].speed == 100);
  CHECK(a.conveyors[0].run.kind == rs::workcell::Signal::Kind::Output);
  CHECK(a.conveyors[1].run.kind == rs::workcell::Signal::Kind::On);
  CHECK(a.feeders[0].everyUs == 6'000'000);
  CHECK(a.feeders[0].at == b.feeders[0].at);
  CHECK(a.sensors[0].a == b.sensors[0].a);
  CHECK(a.sensors[0].b == b.sensors[0].b);
  CHECK(a.sinks[0].zone.min() == b.sinks[0].zone.min());
  CHECK(a.wires[0].source.sensor == 0);
  CHECK(a.wires[0].input == 1);
  CHECK(decoded->fedParts.size() == cell->fedParts.size());
  // Encoding what was decoded gives the same bytes.
  CHECK(rs::workcell::encodeCell(*decoded) == bytes);
}

TEST_CASE("cell section 3: a flipped byte of the devices' part is refused or runs, never a crash", "[models][devices]") {
  rs::testing::TempDir dir;
  const std::string cellFile = dir.write("c.rsd", std::string(celltest::kBeltAndPart) +
                                         "WORKCELL c\n"
                                         "  ROBOT adept-one AT 0 0 -900\n"
                                         "  OBJECT belt AT 0 0 50 AS line\n"
                                         "  CONVEYOR line SPEED 100 RUN OUT 1\n"
                                         "  FEEDER f blk AT 30 10 30 EVERY 2 COUNT 3\n"
                                         "  SENSOR eye BEAM 500 15 0  500 15 60\n"
                                         "  SENSOR bay ZONE 600 700 30 10 50 0 SEES ALL\n"
                                         "  SINK out ZONE 900 1000 40 10 50 0\n"
                                         "  WIRE eye TO IN 1 AFTER 0.5 INVERTED\n"
                                         "END\n");
  const std::string program = dir.write("p.rsp", "        OUTSIG 1 ON\n        DELAY 3\n        END\n");
  const std::string image = dir.file("p.rsb");
  REQUIRE(runCli({"compile", program, "--cell", cellFile, "-o", image}).code == 0);
  const std::string original = rs::testing::readBytes(image);
  const auto loaded = rs::vm::loadImage(original);
  REQUIRE(loaded.ok());
  const auto cell = rs::workcell::decodeCell(loaded.value().cell);
  REQUIRE(cell.ok());
  REQUIRE(cell->devices.wires.size() == 1);
  // Where version 3's part begins: the same cell without what it adds
  // encodes (as version 1) to exactly the bytes before it.
  rs::workcell::Workcell bare = *cell;
  bare.floor.reset(), bare.devices = {}, bare.fedParts.clear();
  for (auto& o : bare.objects) o.kind = rs::workcell::ObjectKind::Part, o.name.clear(), o.belt.reset();
  for (auto& r : bare.robots) r.label.clear();
  const std::size_t geometry = rs::workcell::encodeCell(bare).size();
  const std::size_t cellBytes = loaded.value().cell.size();
  REQUIRE(cellBytes > geometry + 100);
  const std::string section(loaded.value().cell.begin(), loaded.value().cell.end());
  const std::size_t cellAt = original.find(section);
  REQUIRE(cellAt != std::string::npos);
  const std::size_t start = cellAt + geometry;
  std::size_t refused = 0, ran = 0;
  for (std::size_t at = start; at < cellAt + cellBytes; ++at) {
    std::string bytes = original;
    bytes[at] = static_cast<char>(bytes[at] ^ 0xFF);
    fixCrcOf(bytes);
    const std::string path = dir.write("bad.rsb", bytes);
    const CliResult r = runCli({"run", path, "--format=json"});
    INFO("byte " << at - start << " of version 3's part: " << r.err);
    CHECK((r.code == 0 || r.code == 1 || r.code == 2));
    if (r.code == 2) {
      ++refused;
      CHECK(r.err.rfind(path + ": error: image rejected: ", 0) == 0);
    } else {
      ++ran;
    }
  }
  CHECK(refused > 0);
  CHECK(ran > 0);  // a name's letter, a coordinate's low byte: still a cell that runs
}
