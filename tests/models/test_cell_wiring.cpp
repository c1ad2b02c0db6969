// Programs on a workcell's robot (docs/models.md, "robotsim run PROG --cell
// CELL"): the motor table comes from the robot, --trace and the summary show
// the tool centre point, a compiled image carries the cell, placement moves
// the robot and objects as documented, and a corrupt cell section is refused.
//
// The robot is a planar two-link arm drawn at height 50, all z axes up:
//   frame 0 at (0, 0, 50), frame 1 at (300, 0, 50), frame 2 (the tool) at
//   (500, 0, 50); so a1 = 300, a2 = 200, every alpha and d 0, home 0, 0.
//   Motor S: joint 1, 0.5 deg per count, -400..400; motor T: joint 2,
//   0.25 deg per count, -720..720.
// Tool centre point, worked by hand, relative to frame 0:
//   (300 cos t1 + 200 cos(t1 + t2), 300 sin t1 + 200 sin(t1 + t2), 0).
//   S=60, T=120: t1 = 30, t2 = 30 -> (259.8076 + 100, 150 + 173.2051)
//                                 =  (359.8076, 323.2051); at z = 50.
//   S=180, T=-360: t1 = 90, t2 = -90 -> (200, 300).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compiler/description/library.h"
#include "model/workcell/cell_file.h"
#include "model/workcell/tool_tracker.h"
#include "tests/models/models_support.h"
#include "vm/image_file.h"

namespace {

using nlohmann::json;
using rs::testing::CliResult;
using rs::testing::lines;
using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

const std::string kPlanar = lines({
    "LINK planar_base",
    "  LINE 0 0 0  0 0 50",
    "END",
    "LINK planar_upper",
    "  LINE 0 0 50  300 0 50",
    "END",
    "LINK planar_fore",
    "  LINE 300 0 50  500 0 50",
    "END",
    "ROBOT planar",
    "  LINK planar_base   FRAME ORIGIN 0 0 50    XAXIS 1 0 50    ZAXIS 0 0 51",
    "  LINK planar_upper  FRAME ORIGIN 300 0 50  XAXIS 301 0 50  ZAXIS 300 0 51",
    "  LINK planar_fore   FRAME ORIGIN 500 0 50  XAXIS 501 0 50  ZAXIS 500 0 51",
    "  JOINT 1 REVOLUTE LETTER S PRECISION 0.5  RANGE -400 400  SPEED 200",
    "  JOINT 2 REVOLUTE LETTER T PRECISION 0.25 RANGE -720 720  SPEED 360",
    "END",
});

const std::string kWiringProgram = lines({
    "SET N 1",
    "MOVE 60 120",
    "DELAY 0.5",
    "MOVETO 180 -360",
    "OUTSIG 3 ON",
    "END",
});

json jsonLine(const std::string& text) {
  INFO(text);
  REQUIRE(json::accept(text));
  return json::parse(text);
}

std::vector<json> jsonLines(const std::string& out) {
  std::vector<json> rows;
  std::size_t start = 0;
  for (std::size_t nl; (nl = out.find('\n', start)) != std::string::npos; start = nl + 1)
    rows.push_back(jsonLine(out.substr(start, nl - start)));
  return rows;
}

void checkPoint(const json& p, double x, double y, double z) {
  INFO(p.dump());
  REQUIRE(p.is_array());
  REQUIRE(p.size() == 3);
  CHECK(p[0].get<double>() == Approx(x).margin(1e-4));
  CHECK(p[1].get<double>() == Approx(y).margin(1e-4));
  CHECK(p[2].get<double>() == Approx(z).margin(1e-4));
}

// The JSON trace row of the first instruction with this op.
json row(const std::vector<json>& rows, const std::string& op) {
  for (const json& r : rows)
    if (r.contains("op") && r["op"] == op) return r;
  FAIL("no " << op << " in the trace");
  return {};
}

void fixCrc(std::string& image) {
  const std::uint32_t crc = rs::vm::crc32(reinterpret_cast<const std::uint8_t*>(image.data()) + 20, image.size() - 20);
  for (int i = 0; i < 4; ++i) image[static_cast<std::size_t>(16 + i)] = static_cast<char>((crc >> (8 * i)) & 0xFF);
}

}  // namespace

TEST_CASE("cell wiring: the program sees the robot's motors", "[models]") {
  TempDir dir;
  const std::string cell = dir.write("planar.rsd", kPlanar);
  SECTION("arity errors name the robot's letters") {
    const std::string prog = dir.write("p.rsp", "MOVE 1 2 3\nEND\n");
    const CliResult r = runCli({"check", prog, "--cell", cell});
    CHECK(r.code == 2);
    CHECK(r.err.rfind(prog + ":1:1: error: MOVE expects 2 values (one per motor: S T), found 3\n", 0) == 0);
    // Without --cell the same program is checked against the default robot.
    const CliResult d = runCli({"check", prog});
    CHECK(d.err.rfind(prog + ":1:1: error: MOVE expects 5 values (one per motor: E D C B A), found 3\n", 0) == 0);
  }
  SECTION("compile-time range errors use the robot's ranges") {
    const std::string prog = dir.write("p.rsp", "MOVETO 401 -720\nMOVE 0 1441\nEND\n");
    const CliResult r = runCli({"check", prog, "--cell", cell});
    CHECK(r.code == 2);
    CHECK(r.err.find(prog + ":1:8: error: MOVETO target 401 for motor S is outside its range -400..400\n") !=
          std::string::npos);
    CHECK(r.err.find(prog + ":2:8: error: MOVE by 1441 can never keep motor T within its range -720..720\n") !=
          std::string::npos);
    // 400 and -720 are at the ends of the ranges: fine.
    const std::string ok = dir.write("ok.rsp", "MOVETO 400 -720\nMOVE 0 1440\nEND\n");
    const CliResult o = runCli({"check", ok, "--cell", cell});
    CHECK(o.code == 0);
    CHECK(o.err.empty());
  }
  SECTION("run-time range errors use the robot's ranges") {
    const std::string prog = dir.write("p.rsp", "MOVE 300 0\nMOVE 300 0\nEND\n");
    const CliResult r = runCli({"run", prog, "--cell", cell});
    CHECK(r.code == 1);
    CHECK(r.err.find("-400..400") != std::string::npos);
    CHECK(r.out.find("motors          S=300  T=0\n") != std::string::npos);
  }
  SECTION("speeds come from the robot") {
    // S moves 60 counts at 200/s (0.3 s), T 120 counts at 360/s (0.333333 s):
    // the MOVE ends when the slower motor arrives.
    const std::string prog = dir.write("p.rsp", "MOVE 60 120\nEND\n");
    const CliResult r = runCli({"run", prog, "--cell", cell, "--format", "json"});
    CHECK(r.code == 0);
    const json j = jsonLine(r.out.substr(0, r.out.find('\n')));
    CHECK(j["time"].get<double>() == Approx(120.0 / 360.0).margin(1e-6));
    CHECK(j["motors"] == json({{"S", 60}, {"T", 120}}));
  }
}

TEST_CASE("cell wiring: --trace and the summary show the tool centre point", "[models]") {
  TempDir dir;
  const std::string cell = dir.write("planar.rsd", kPlanar);
  const std::string prog = dir.write("p.rsp", kWiringProgram);
  SECTION("JSON trace") {
    const CliResult r = runCli({"run", prog, "--cell", cell, "--trace=json"});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    const std::vector<json> rows = jsonLines(r.out.substr(0, r.out.find("run of ")));
    REQUIRE(rows.size() == 6);
    checkPoint(row(rows, "SET")["tcp"], 500, 0, 50);  // home
    const json move = row(rows, "MOVE");
    CHECK(move["motors"] == json({{"S", 60}, {"T", 120}}));
    checkPoint(move["tcp"], 359.8076, 323.2051, 50);
    checkPoint(row(rows, "MOVETO")["tcp"], 200, 300, 50);
  }
  SECTION("text trace and summary") {
    const CliResult r = runCli({"run", prog, "--cell", cell, "--trace"});
    CHECK(r.code == 0);
    CHECK(r.out.find("tool centre point") != std::string::npos);
    CHECK(r.out.find("(359.81, 323.21, 50)") != std::string::npos);
    CHECK(r.out.find("run of " + prog + " on planar: ") != std::string::npos);
    CHECK(r.out.find("  tool centre     (200, 300, 50)\n") != std::string::npos);
  }
  SECTION("JSON summary") {
    const CliResult r = runCli({"run", prog, "--cell", cell, "--format", "json"});
    CHECK(r.code == 0);
    const json j = jsonLine(r.out.substr(0, r.out.find('\n')));
    checkPoint(j["tcp"], 200, 300, 50);
  }
  SECTION("the same numbers from the tool tracker") {
    rs::compiler::Library lib({dir.path()});
    const auto c = lib.workcell(cell);
    REQUIRE(c);
    REQUIRE(c->robots.size() == 1);
    rs::workcell::ToolTracker tool(c->robots[0]);
    // Five poses, then back and forth among them: the tracker keeps the
    // last four frames, and a kept one must be the right one.
    const std::vector<std::pair<int, int>> poses{{0, 0}, {60, 120}, {180, -360}, {-400, 720}, {37, -11}};
    std::vector<std::pair<int, int>> asked = poses;
    for (const std::size_t i : {4, 3, 4, 0, 1, 4, 2, 2, 0, 3}) asked.push_back(poses[i]);
    for (const auto& [s, t] : asked) {
      const std::vector<std::int32_t> enc{s, t};
      const double t1 = 0.5 * s * M_PI / 180, t2 = 0.25 * t * M_PI / 180;
      const auto p = tool.tcp(enc);
      CHECK(p[0] == Approx(300 * std::cos(t1) + 200 * std::cos(t1 + t2)).margin(1e-9));
      CHECK(p[1] == Approx(300 * std::sin(t1) + 200 * std::sin(t1 + t2)).margin(1e-9));
      CHECK(p[2] == Approx(50).margin(1e-9));
    }
  }
}

TEST_CASE("cell wiring: a compiled image carries the cell, its run is byte-identical", "[models]") {
  TempDir dir;
  const std::string cell = dir.write("planar.rsd", kPlanar);
  const std::string prog = dir.write("p.rsp", kWiringProgram);
  const std::string image = dir.file("p.rsb");
  const CliResult c = runCli({"compile", prog, "--cell", cell, "-o", image});
  REQUIRE(c.code == 0);
  CHECK(c.err.empty());
  // The description is not needed any more.
  std::filesystem::remove(cell);
  for (const std::vector<std::string>& extra :
       std::vector<std::vector<std::string>>{{"--trace"}, {"--trace=json"}, {"--trace=json", "--format", "json"}, {}}) {
    std::vector<std::string> fromImage{"run", image};
    fromImage.insert(fromImage.end(), extra.begin(), extra.end());
    const std::string again = dir.write("planar.rsd", kPlanar);
    std::vector<std::string> fromSource{"run", prog, "--cell", again};
    fromSource.insert(fromSource.end(), extra.begin(), extra.end());
    const CliResult s = runCli(fromSource);
    std::filesystem::remove(again);
    const CliResult i = runCli(fromImage);
    INFO(extra.size());
    CHECK(s.code == 0);
    CHECK(i.code == 0);
    CHECK(i.out == s.out);
    CHECK(i.err == s.err);
    if (!extra.empty()) CHECK(i.out.find("359.8") != std::string::npos);
  }
  // disasm and check take the image too.
  CHECK(runCli({"check", image}).code == 0);
  CHECK(runCli({"disasm", image}).code == 0);
}

TEST_CASE("cell wiring: refusals", "[models]") {
  TempDir dir;
  const std::string cell = dir.write("planar.rsd", kPlanar);
  const std::string prog = dir.write("p.rsp", kWiringProgram);
  SECTION("--cell with an image") {
    const std::string image = dir.file("p.rsb");
    REQUIRE(runCli({"compile", prog, "--cell", cell, "-o", image}).code == 0);
    for (const char* cmd : {"run", "check", "disasm"}) {
      const CliResult r = runCli({cmd, image, "--cell", cell});
      INFO(cmd);
      CHECK(r.code == 2);
      CHECK(r.err == image + ": error: --cell applies to program sources: a compiled image carries its own cell\n");
    }
  }
  SECTION("a workcell with no robot") {
    const std::string empty = dir.write("objects-only.rsd", lines({"OBJECT crate", "  BOX 0 1 1 0 1 0", "END",
                                                                   "WORKCELL storeroom", "  OBJECT crate AT 0 0 0",
                                                                   "END"}));
    for (const char* cmd : {"run", "check", "compile", "disasm"}) {
      std::vector<std::string> args{cmd, prog, "--cell", empty};
      if (std::string(cmd) == "compile") args.insert(args.end(), {"-o", dir.file("x.rsb")});
      const CliResult r = runCli(args);
      INFO(cmd);
      CHECK(r.code == 2);
      CHECK(r.err == empty + ": error: the workcell has no robot to run the program\n");
    }
    CHECK_FALSE(std::filesystem::exists(dir.file("x.rsb")));
  }
  SECTION("a file with neither a WORKCELL nor a ROBOT") {
    const std::string links = dir.write("links.rsd", lines({"LINK l", "  LINE 0 0 0 1 1 1", "END"}));
    const CliResult r = runCli({"run", prog, "--cell", links});
    CHECK(r.code == 2);
    CHECK(r.err == links + ": error: the file defines no WORKCELL and no ROBOT\n");
  }
  SECTION("a cell with errors prints them and runs nothing") {
    const std::string bad = dir.write("bad.rsd", lines({"WORKCELL w", "  ROBOT nobody", "END"}));
    const CliResult r = runCli({"run", prog, "--cell", bad, "--format", "json"});
    CHECK(r.code == 2);
    CHECK(r.err.rfind(bad + ":2:9: error: unknown robot 'nobody'", 0) == 0);
    CHECK(r.err.find("  ROBOT nobody\n") != std::string::npos);
    const json j = jsonLine(r.out.substr(0, r.out.find('\n')));
    CHECK(j["status"] == "error");
  }
}

TEST_CASE("cell wiring: placement in a workcell", "[models]") {
  TempDir dir;
  dir.write("planar.rsd", kPlanar);
  const std::string prog = dir.write("p.rsp", lines({"DELAY 0.1", "MOVE 60 120", "END"}));
  const auto tcps = [&](const std::string& placement) {
    const std::string cell = dir.write("cell.rsd", lines({"WORKCELL c", "  ROBOT planar AT " + placement, "END"}));
    const CliResult r = runCli({"run", prog, "--cell", cell, "--lib", dir.path().string(), "--trace=json"});
    INFO(r.err);
    REQUIRE(r.code == 0);
    const std::vector<json> rows = jsonLines(r.out.substr(0, r.out.find("run of ")));
    return std::pair{row(rows, "DELAY")["tcp"], row(rows, "MOVE")["tcp"]};
  };
  SECTION("AT only: link 0's origin (0, 0, 50) goes to the point") {
    // Home TCP is 500 along x from link 0's origin.
    const auto [home, moved] = tcps("1000 500 0");
    checkPoint(home, 1500, 500, 0);
    checkPoint(moved, 1000 + 359.8076, 500 + 323.2051, 0);
  }
  SECTION("ROTATE Z 90 about the point") {
    // (500, 0, 0) from the origin turns to (0, 500, 0); (359.8076, 323.2051, 0)
    // to (-323.2051, 359.8076, 0).
    const auto [home, moved] = tcps("1000 500 0 ROTATE Z 90");
    checkPoint(home, 1000, 1000, 0);
    checkPoint(moved, 1000 - 323.2051, 500 + 359.8076, 0);
  }
  SECTION("rotations apply in order, about the world axes") {
    // Z 90 then X 90: (500, 0, 0) -> (0, 500, 0) -> (0, 0, 500).
    const auto [home, moved] = tcps("1000 500 0 ROTATE Z 90 ROTATE X 90");
    checkPoint(home, 1000, 500, 500);
    // (359.8076, 323.2051, 0) -> (-323.2051, 359.8076, 0) -> (-323.2051, 0, 359.8076)
    checkPoint(moved, 1000 - 323.2051, 500, 359.8076);
  }
  SECTION("a lone robot file stands where it was drawn") {
    const CliResult r = runCli({"run", prog, "--cell", dir.file("planar.rsd"), "--trace=json"});
    REQUIRE(r.code == 0);
    const std::vector<json> rows = jsonLines(r.out.substr(0, r.out.find("run of ")));
    checkPoint(row(rows, "DELAY")["tcp"], 500, 0, 50);
  }
}

TEST_CASE("cell wiring: OBJECT AT places the lowest, left-most, front-most corner", "[models]") {
  // The box x in [-10, 20], y in [5, 30] (bottom..top), z in [-3, 7]
  // (back..front): least y, least x, greatest z is (-10, 5, 7).
  TempDir dir;
  dir.write("crate.rsd", lines({"OBJECT crate", "  BOX -10 20 30 5 7 -3", "END"}));
  dir.write("planar.rsd", kPlanar);
  const std::string cell = dir.write("cell.rsd", lines({"WORKCELL c", "  ROBOT planar", "  OBJECT crate AT 100 200 300",
                                                        "  OBJECT crate AT 100 200 300 ROTATE Z 30", "END"}));
  rs::compiler::Library lib({dir.path()});
  const auto c = lib.workcell(cell);
  REQUIRE(c);
  REQUIRE(c->objects.size() == 2);
  const Eigen::Vector3d corner(-10, 5, 7), at(100, 200, 300);
  for (const auto& o : c->objects) CHECK((o.F_world_design * corner - at).norm() < 1e-9);
  // Unturned: everything shifts by at - corner = (110, 195, 293).
  CHECK((c->objects[0].F_world_design * Eigen::Vector3d(20, 30, -3) - Eigen::Vector3d(130, 225, 290)).norm() < 1e-9);
  // Turned by Z 30 about the corner: the corner (20, 5, 7), 30 along x from
  // it, goes to at + (30 cos 30, 30 sin 30, 0) = (125.98076, 215, 300).
  CHECK((c->objects[1].F_world_design * Eigen::Vector3d(20, 5, 7) - Eigen::Vector3d(125.98076211353316, 215, 300)).norm() <
        1e-9);
  // The robot without AT stands at the origin: link 0's origin (0, 0, 50) -> (0, 0, 0).
  REQUIRE(c->robots.size() == 1);
  CHECK((c->robots[0].F_world_design * Eigen::Vector3d(0, 0, 50)).norm() < 1e-9);
}

namespace {

// Compiles kWiringProgram for the planar arm; returns the image bytes.
std::string compiledImage(const TempDir& dir) {
  const std::string cell = dir.write("planar.rsd", kPlanar);
  const std::string prog = dir.write("p.rsp", kWiringProgram);
  const std::string image = dir.file("p.rsb");
  REQUIRE(runCli({"compile", prog, "--cell", cell, "-o", image}).code == 0);
  std::filesystem::remove(cell);
  return readBytes(image);
}

// True if the decoded cell's first robot gives exactly the image's motor table.
bool cellMatchesMotors(const rs::vm::Image& im) {
  const auto decoded = rs::workcell::decodeCell(im.cell);
  if (!decoded || decoded->robots.empty()) return false;
  const auto motors = rs::compiler::motorTable(decoded->robots.front().robot);
  if (motors.size() != im.motors.size()) return false;
  for (std::size_t i = 0; i < motors.size(); ++i) {
    const auto &a = motors[i], &b = im.motors[i];
    if (a.letter != b.letter || a.kind != b.kind || a.precision != b.precision || a.min != b.min || a.max != b.max ||
        a.speed != b.speed)
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("cell wiring: a corrupt cell section is refused, never a crash", "[models]") {
  TempDir dir;
  const std::string original = compiledImage(dir);
  const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(original);
  REQUIRE(loaded.ok());
  REQUIRE(cellMatchesMotors(loaded.value()));
  const std::size_t cellBytes = loaded.value().cell.size();
  REQUIRE(cellBytes > 100);
  REQUIRE(original.size() > cellBytes + 24);
  const std::size_t start = original.size() - cellBytes;  // the cell is the last section
  const std::string path = dir.file("bad.rsb");
  std::size_t refused = 0;
  std::vector<std::size_t> acceptedMismatch;  // ran although the cell disagrees with the motor table
  // The 4-byte count before the cell, then every byte of the cell.
  for (std::size_t at = start - 4; at < original.size(); ++at) {
    std::string bytes = original;
    bytes[at] = static_cast<char>(bytes[at] ^ 0xFF);
    fixCrc(bytes);
    dir.write("bad.rsb", bytes);
    const CliResult r = runCli({"run", path, "--format", "json"});
    INFO("byte " << static_cast<long>(at) - static_cast<long>(start) << " of the cell section: " << r.err);
    CHECK((r.code == 0 || r.code == 2));
    if (r.code == 2) {
      ++refused;
      CHECK(r.err.rfind(path + ": error: ", 0) == 0);
      CHECK(((r.err.find("image rejected: cell section: ") != std::string::npos ||
              r.err.find("image rejected: its cell's robot does not match its motor table") != std::string::npos ||
              r.err.find("malformed image") != std::string::npos)));
    } else {
      const rs::diag::Result<rs::vm::Image> l = rs::vm::loadImage(bytes);
      if (!cellMatchesMotors(l.value())) acceptedMismatch.push_back(at - start);
    }
  }
  // The magic, version and counts are structural: flipping any of them must
  // be refused (first 6 bytes, then the 4-byte count before the section).
  for (std::size_t at = start - 4; at < start + 6; ++at) {
    std::string bytes = original;
    bytes[at] = static_cast<char>(bytes[at] ^ 0xFF);
    fixCrc(bytes);
    dir.write("bad.rsb", bytes);
    INFO("byte " << static_cast<long>(at) - static_cast<long>(start));
    CHECK(runCli({"run", path}).code == 2);
  }
  CHECK(refused > 0);
  // A cell whose robot disagrees with the image's motor table (another
  // letter, range, speed or precision) must not run: the trace would show
  // a tool centre point computed with other motors than the VM moved.
  std::string offsets;
  for (std::size_t o : acceptedMismatch) offsets += std::to_string(o) + " ";
  INFO("cell bytes whose flip ran with a mismatched motor table: " << offsets);
  CHECK(acceptedMismatch.empty());
}

// disasm and check load an image exactly as run does: the cell section is
// decoded and checked against the motor table before anything is listed.
TEST_CASE("cell wiring: disasm and check refuse a corrupt cell section as run does", "[models]") {
  TempDir dir;
  const std::string original = compiledImage(dir);
  const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(original);
  REQUIRE(loaded.ok());
  REQUIRE(runCli({"disasm", dir.file("p.rsb")}).code == 0);
  const std::size_t start = original.size() - loaded.value().cell.size();  // the cell is the last section
  SECTION("a bad magic number") {
    std::string bytes = original;
    bytes[start] = static_cast<char>(bytes[start] ^ 0xFF);
    fixCrc(bytes);
    const std::string path = dir.write("bad.rsb", bytes);
    for (const char* cmd : {"run", "check", "disasm"}) {
      INFO(cmd);
      const CliResult r = runCli({cmd, path});
      CHECK(r.code == 2);
      CHECK(r.out.empty());
      CHECK(r.err == path + ": error: image rejected: cell section: bad magic number\n");
    }
  }
  SECTION("a cell whose robot does not match the motor table") {
    rs::diag::Result<rs::workcell::Workcell> decoded = rs::workcell::decodeCell(loaded.value().cell);
    REQUIRE(decoded.ok());
    decoded->robots.front().robot.joints.front().max = 10;
    rs::vm::Image im = loaded.value();
    im.cell = rs::workcell::encodeCell(*decoded);
    const auto bytes = rs::vm::writeImage(im);
    const std::string path = dir.write("mismatch.rsb", std::string(bytes.begin(), bytes.end()));
    for (const char* cmd : {"run", "check", "disasm"}) {
      INFO(cmd);
      const CliResult r = runCli({cmd, path});
      CHECK(r.code == 2);
      CHECK(r.out.empty());
      CHECK(r.err == path + ": error: image rejected: its cell's robot does not match its motor table\n");
    }
  }
}

// Names in the cell section come from descriptions, which never hold
// control characters: a forged one is refused, and the message does not
// quote it.
TEST_CASE("cell wiring: a cell section name with a control character is refused", "[models]") {
  TempDir dir;
  const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(compiledImage(dir));
  REQUIRE(loaded.ok());
  const auto forged = [&](auto change) {
    rs::diag::Result<rs::workcell::Workcell> decoded = rs::workcell::decodeCell(loaded.value().cell);
    REQUIRE(decoded.ok());
    change(*decoded);
    rs::vm::Image im = loaded.value();
    im.cell = rs::workcell::encodeCell(*decoded);
    const auto bytes = rs::vm::writeImage(im);
    return dir.write("forged.rsb", std::string(bytes.begin(), bytes.end()));
  };
  const std::string names[] = {
      forged([](rs::workcell::Workcell& c) { c.name = "cell\x1b]0;pwned\x07"; }),
      forged([](rs::workcell::Workcell& c) { c.robots.front().robot.name = "planar\x1b[2J"; }),
      forged([](rs::workcell::Workcell& c) { c.robots.front().robot.links.front().name = "base\x07"; }),
  };
  for (const std::string& path : names)
    for (const char* cmd : {"run", "disasm"}) {
      INFO(cmd);
      const CliResult r = runCli({cmd, path});
      CHECK(r.code == 2);
      CHECK(r.err == path + ": error: image rejected: cell section: a name that holds a control character\n");
    }
}

TEST_CASE("cell wiring: an image whose cell's robot disagrees with its motor table is refused", "[models]") {
  TempDir dir;
  const std::string original = compiledImage(dir);
  const rs::diag::Result<rs::vm::Image> loaded = rs::vm::loadImage(original);
  REQUIRE(loaded.ok());
  const auto decoded = rs::workcell::decodeCell(loaded.value().cell);
  REQUIRE(decoded.ok());
  const auto tamper = [&](auto change) {
    rs::workcell::Workcell cell = *decoded;
    change(cell.robots.front().robot.joints.front());
    rs::vm::Image im = loaded.value();
    im.cell = rs::workcell::encodeCell(cell);
    const auto bytes = rs::vm::writeImage(im);
    dir.write("t.rsb", std::string(bytes.begin(), bytes.end()));
    return runCli({"run", dir.file("t.rsb")});
  };
  CHECK(tamper([](rs::workcell::JointSpec&) {}).code == 0);  // untouched: runs
  CHECK(tamper([](rs::workcell::JointSpec& j) { j.precision = 2.0; }).code == 2);
  CHECK(tamper([](rs::workcell::JointSpec& j) { j.letter = 'T'; }).code == 2);  // also a duplicate letter
  CHECK(tamper([](rs::workcell::JointSpec& j) { j.max = 10; }).code == 2);
}
