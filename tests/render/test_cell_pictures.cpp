// `render --at`, `animate` and `plot` of a cell of several robots (issue 36):
// every robot drawn where its own motors are. The expected positions are
// worked out by hand from examples/two_robots/interlock.rsd: both robots
// are XR-4s whose motor F runs at 300 counts/s (stdlib/robots/rhino-xr4.rsd),
// so each MOVE of 300 counts takes 300 * 1e6 / 300 µs = 1 s, and OUTSIG,
// SET and WAITFOR on an input already on take no time. Wires: left.OUT 1
// drives right.IN 1 at once, right.OUT 1 drives left.IN 1 0.25 s later.
//   left   0 .. 1 s F 0 -> 300, 1 .. 2 s back to 0, OUTSIG 1 ON at 2 s
//   right  waits for input 1 (on at 2 s), 2 .. 3 s F 0 -> 300, 3 .. 4 s back
// So at 0.5 s left's F is 150 and right's 0; at 2.5 s left's F is 0 and
// right's 150 (constant speed: 0.5 s * 300 counts/s).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "render_test_util.h"

using rs::testing::readBytes;
using rs::testing::runCli;
using rs::testing::TempDir;

namespace cell_pictures_test {

const std::string kCellInterlock = rendertest::kSourceDir + "/examples/two_robots/interlock.rsd";
const std::string kTwoRobots = rendertest::kSourceDir + "/examples/two_robots/";

nlohmann::json cellDump(const std::vector<std::string>& args) {
  const auto r = runCli(args);
  INFO(r.err);
  REQUIRE(r.code == 0);
  return nlohmann::json::parse(r.out);
}

// The lines of robot `robot` in a --dump-lines=json document.
std::vector<nlohmann::json> cellRobotLines(const nlohmann::json& doc, int robot) {
  std::vector<nlohmann::json> out;
  for (const auto& l : doc.at("lines"))
    if (l.at("owner") == "robot" && l.at("index") == robot) out.push_back(l);
  return out;
}

bool sameRobotLines(const std::vector<nlohmann::json>& a, const std::vector<nlohmann::json>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (const char* end : {"a", "b"})
      for (int k = 0; k < 2; ++k)
        if (std::abs(a[i].at(end)[k].get<double>() - b[i].at(end)[k].get<double>()) > 1e-9) return false;
  return true;
}

// The page's model, parsed back.
nlohmann::json cellPageModel(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"robotsim-model\">";
  const std::size_t a = html.find(open);
  REQUIRE(a != std::string::npos);
  const std::size_t b = html.find("</script>", a);
  REQUIRE(b != std::string::npos);
  return nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
}

// A cell of two robots and a belt (tests/runtime/belt_and_part.h's, x
// 0..1000) that runs while b's output 1 is on, with a beam across it at
// x 500; a ends at 1 s, b turns its output on at once and waits 8 s.
void writeBeltCell(const TempDir& dir, const std::string& name) {
  dir.write(name,
            "OBJECT belt\n  BOX 0 1000 10 0 50 0\n  BELT 0 1000 10 0 45 5 DIRECTION 1 0 0\nEND\n"
            "OBJECT blk\n  PART\n  BOX 0 10 10 0 10 0\nEND\n"
            "WORKCELL c\n"
            "  ROBOT adept-one AT 0 0 -900    AS a PROGRAM a.rsp\n"
            "  ROBOT adept-one AT 5000 0 -900 AS b PROGRAM b.rsp\n"
            "  OBJECT belt AT 0 0 50 AS line\n"
            "  OBJECT blk AT 17 10 30\n"
            "  CONVEYOR line SPEED 100 RUN b.OUT 1\n"
            "  SENSOR eye BEAM 500 15 0  500 15 60\n"
            "END\n");
  dir.write("a.rsp", "        DELAY 1\n        END\n");
  dir.write("b.rsp", "        OUTSIG 1 ON\n        DELAY 8\n        END\n");
}

}  // namespace cell_pictures_test

using namespace cell_pictures_test;

TEST_CASE("render --at of a cell draws every robot where its own motors are", "[render][cell-run][robots]") {
  const nlohmann::json home = cellDump({"render", kCellInterlock, "--dump-lines=json"});
  const nlohmann::json early = cellDump({"render", kCellInterlock, "--at", "0.5", "--dump-lines=json"});
  const nlohmann::json late = cellDump({"render", "--cell", kCellInterlock, "--at", "2.5", "--dump-lines=json"});
  // The legend: the moment, then each robot's motors in the cell's order.
  CHECK(early.at("legend")[0] == "left.rsp, right.rsp on interlock   t = 0.500 s");
  CHECK(early.at("legend")[1] == "rhino-xr4  F=150 E=0 D=0 C=0 B=0 A=0");
  CHECK(early.at("legend")[2] == "rhino-xr4  F=0 E=0 D=0 C=0 B=0 A=0");
  CHECK(late.at("legend")[1] == "rhino-xr4  F=0 E=0 D=0 C=0 B=0 A=0");
  CHECK(late.at("legend")[2] == "rhino-xr4  F=150 E=0 D=0 C=0 B=0 A=0");
  // The lines: at 0.5 s only the left robot has left home, at 2.5 s only the right one.
  CHECK_FALSE(sameRobotLines(cellRobotLines(early, 0), cellRobotLines(home, 0)));
  CHECK(sameRobotLines(cellRobotLines(early, 1), cellRobotLines(home, 1)));
  CHECK(sameRobotLines(cellRobotLines(late, 0), cellRobotLines(home, 0)));
  CHECK_FALSE(sameRobotLines(cellRobotLines(late, 1), cellRobotLines(home, 1)));
  // The right robot's lines at 2.5 s are the left robot's at 0.5 s, moved
  // by the 3000 between their bases: the same motors, the same drawing.
  const nlohmann::json moved = cellDump({"render", kCellInterlock, "--at", "0.5", "--dump-lines=json", "right=" + kTwoRobots + "left.rsp",
                                       "left=" + kTwoRobots + "right.rsp"});
  CHECK(moved.at("legend")[1] == "rhino-xr4  F=0 E=0 D=0 C=0 B=0 A=0");
  CHECK(moved.at("legend")[2] == "rhino-xr4  F=150 E=0 D=0 C=0 B=0 A=0");
  // Both robots running left.rsp move together: F out 0 .. 1 s, back 1 ..
  // 2 s, so 150 at 0.5 s and again (300 - 150) at 1.5 s. The cell stops at
  // --at when the first robot's move passes it: the other robot, stopped in
  // the middle of its move, is still drawn where that move has it.
  for (const char* t : {"0.5", "1.5"}) {
    INFO("at " << t);
    const nlohmann::json both = cellDump({"render", "--cell", kCellInterlock, "right=" + kTwoRobots + "left.rsp",
                                          "--at", t, "--dump-lines=json"});
    CHECK(both.at("legend")[1] == "rhino-xr4  F=150 E=0 D=0 C=0 B=0 A=0");
    CHECK(both.at("legend")[2] == "rhino-xr4  F=150 E=0 D=0 C=0 B=0 A=0");
  }
}

TEST_CASE("render of a cell gives the same bytes every time, and says what it drew", "[render][cell-run][robots]") {
  const TempDir dir;
  // PNG: an SVG's surface id counts cairo's surfaces in the process.
  const auto a = runCli({"render", kCellInterlock, "--at", "2.5", "-o", dir.file("a.png")});
  const auto b = runCli({"render", kCellInterlock, "--at", "2.5", "-o", dir.file("b.png")});
  INFO(a.err);
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  CHECK(readBytes(dir.file("a.png")) == readBytes(dir.file("b.png")));
  CHECK(a.out.find("left.rsp, right.rsp on interlock -> ") == 0);
  CHECK(a.out.find(", at 2.500 s)") != std::string::npos);
  // Without --at a cell is drawn at home, as always: no moment in the legend.
  // (Its title is the cell's name.)
  const nlohmann::json still = cellDump({"render", kCellInterlock, "--dump-lines=json"});
  CHECK(still.at("legend")[0] == "interlock");
  CHECK(still.at("legend")[2] == "rhino-xr4  F=0 E=0 D=0 C=0 B=0 A=0");
}

TEST_CASE("render of a cell: a LABEL=FILE naming no robot is refused with the labels", "[render][cell-run][robots]") {
  const auto r = runCli({"render", kCellInterlock, "--at", "1", "--dump-lines", "middle=" + kTwoRobots + "left.rsp"});
  CHECK(r.code == 2);
  CHECK(r.err.find("workcell interlock has no robot labelled `middle`") != std::string::npos);
  CHECK(r.err.find("hint: the cell's robots are") != std::string::npos);
}

TEST_CASE("plot of a cell: a lane group per robot, its columns named by its label", "[render][cell-run][robots]") {
  const auto csv = runCli({"plot", "--cell", kCellInterlock, "--format=csv", "--every", "0.5"});
  INFO(csv.err);
  REQUIRE(csv.code == 0);
  std::istringstream rows(csv.out);
  std::string header;
  std::getline(rows, header);
  for (const char* column : {",left.F,", ",left.out1,", ",left.in1,", ",right.F,", ",right.out1,", ",right.in1,"})
    CHECK(header.find(column) != std::string::npos);
  // Each robot's F at 0.5 s steps (see the top of this file): the rows of
  // 0.5 s and 2.5 s.
  std::vector<std::string> head, at05, at25;
  const auto split = [](const std::string& row) {
    std::vector<std::string> cells;
    std::istringstream in(row);
    for (std::string c; std::getline(in, c, ',');) cells.push_back(c);
    return cells;
  };
  head = split(header);
  for (std::string row; std::getline(rows, row);) {
    if (row.starts_with("0.500000,")) at05 = split(row);
    if (row.starts_with("2.500000,")) at25 = split(row);
  }
  REQUIRE(at05.size() == head.size());
  REQUIRE(at25.size() == head.size());
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  CHECK(at05[column("left.F")] == "150");
  CHECK(at05[column("right.F")] == "0");
  CHECK(at25[column("left.F")] == "0");
  CHECK(at25[column("right.F")] == "150");
  // Left's output 1 went on at 2 s: right's input 1 with it (a wire without AFTER).
  CHECK(at25[column("left.out1")] == "1");
  CHECK(at25[column("right.in1")] == "1");
  CHECK(at05[column("right.in1")] == "0");

  // The picture: written, the same bytes every time.
  const TempDir dir;
  const auto a = runCli({"plot", "--cell", kCellInterlock, "-o", dir.file("a.svg")});
  const auto b = runCli({"plot", "--cell", kCellInterlock, "-o", dir.file("b.svg")});
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  CHECK(readBytes(dir.file("a.svg")) == readBytes(dir.file("b.svg")));
  CHECK(a.out.find("left.rsp, right.rsp on interlock -> ") == 0);
}

TEST_CASE("animate of a cell replays every robot, the others by time", "[render][cell-run][robots]") {
  const TempDir dir;
  const auto r = runCli({"animate", "--cell", kCellInterlock, "-o", dir.file("cell.html")});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("left.rsp, right.rsp on interlock -> ") == 0);
  const nlohmann::json model = cellPageModel(readBytes(dir.file("cell.html")));
  CHECK(model.at("robots")[0].at("program") == true);
  CHECK(model.at("robots")[1].at("program") == false);
  const auto& others = model.at("run").at("others");
  REQUIRE(others.size() == 1);
  CHECK(others[0].at("robot") == 1);
  // Right's F (its first motor): out 2 .. 3 s, back 3 .. 4 s in its first
  // turn (see the top of this file), in µs.
  const auto& f = others[0].at("moves")[0];
  REQUIRE(f.at("start").size() >= 2);
  CHECK(f.at("start")[0] == 2'000'000);
  CHECK(f.at("end")[0] == 3'000'000);
  CHECK(f.at("to")[0] == 300);
  CHECK(f.at("start")[1] == 3'000'000);
  CHECK(f.at("to")[1] == 0);
  // The page's time runs to the cell's end, not only the first robot's.
  CHECK(model.at("run").at("end").get<std::int64_t>() >= others[0].at("end").get<std::int64_t>());
  // A page of one robot has no "others": its bytes are what they were.
  const auto one = runCli({"animate", kTwoRobots + "left.rsp", "--cell", "xr4-cell", "-o", dir.file("one.html")});
  INFO(one.err);
  REQUIRE(one.code != 2);
  CHECK_FALSE(cellPageModel(readBytes(dir.file("one.html"))).at("run").contains("others"));
}

TEST_CASE("plot and animate of a cell: the devices act in every robot's steps", "[render][cell-run][robots][devices]") {
  // The belt of tests/runtime/belt_and_part.h (x 0..1000) runs while b's
  // output 1 is on (from 0 s); its part's front (x 27) meets the beam at
  // x 500 after 473 / 100 = 4.73 s and its back (x 17) leaves it 0.1 s
  // later, while a has long ended (at 1 s): the edges come in b's step,
  // b's log has them, yet the cell's lanes and page must show them.
  const TempDir dir;
  writeBeltCell(dir, "c.rsd");
  const auto csv = runCli({"plot", "--cell", dir.file("c.rsd"), "--format=csv", "--every", "0.05"});
  INFO(csv.err);
  REQUIRE(csv.code == 0);
  std::istringstream rows(csv.out);
  std::string header;
  std::getline(rows, header);
  const auto split = [](const std::string& row) {
    std::vector<std::string> cells;
    std::istringstream in(row);
    for (std::string c; std::getline(in, c, ',');) cells.push_back(c);
    return cells;
  };
  const std::vector<std::string> head = split(header);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  REQUIRE(column("sensor_eye") < head.size());
  REQUIRE(column("belt_line") < head.size());
  std::map<std::string, std::vector<std::string>> at;  // the rows of 0.05, 4.7, 4.75, 4.8 and 4.85 s
  for (std::string row; std::getline(rows, row);)
    for (const char* t : {"0.050000", "4.700000", "4.750000", "4.800000", "4.850000"})
      if (row.starts_with(std::string(t) + ",")) at[t] = split(row);
  REQUIRE(at.size() == 5);
  CHECK(at["0.050000"][column("belt_line")] == "1");
  CHECK(at["4.700000"][column("sensor_eye")] == "0");
  CHECK(at["4.750000"][column("sensor_eye")] == "1");
  CHECK(at["4.800000"][column("sensor_eye")] == "1");
  CHECK(at["4.850000"][column("sensor_eye")] == "0");

  // The page: the sensor's edge and the part's motion, from b's steps.
  const auto page = runCli({"animate", "--cell", dir.file("c.rsd"), "-o", dir.file("cell.html")});
  INFO(page.err);
  REQUIRE(page.code == 0);
  const nlohmann::json run = cellPageModel(readBytes(dir.file("cell.html"))).at("run");
  REQUIRE(run.at("sensors").at("at").size() >= 1);
  CHECK(run.at("sensors").at("at")[0] == 4'730'000);
  CHECK(run.at("motions").at("object").size() >= 1);
}

TEST_CASE("render --at of a cell marks every robot's overlaps and draws the sensors that are on",
          "[render][cell-run][robots][devices]") {
  const TempDir dir;
  // The interlock cell with a 40-unit block over the right robot's tool
  // centre point at home, (3238.1, 1070.7, 0) (its run's trace): the block
  // spans y 1130..1170, clear of the tool centre point, into the wrist. At
  // 0.5 s the right robot still stands at home (it waits until 2 s), the
  // left one far away (3000 apart): only the right robot's parts and the
  // block are red.
  dir.write("left.rsp", readBytes(kTwoRobots + "left.rsp"));
  dir.write("right.rsp", readBytes(kTwoRobots + "right.rsp"));
  dir.write("c.rsd",
            "WORKCELL interlock\n"
            "  ROBOT rhino-xr4 AT 0 750 0    AS left  PROGRAM left.rsp\n"
            "  ROBOT rhino-xr4 AT 3000 750 0 AS right PROGRAM right.rsp\n"
            "  OBJECT block AT 3218 1130 20\n"
            "  WIRE left.OUT 1  TO right.IN 1\n"
            "  WIRE right.OUT 1 TO left.IN 1 AFTER 0.25\n"
            "END\n");
  const nlohmann::json still = cellDump({"render", dir.file("c.rsd"), "--at", "0.5", "--dump-lines=json"});
  std::map<std::string, int> red;
  for (const auto& l : still.at("lines"))
    if (l.at("color") == "RED") ++red[l.at("owner").get<std::string>() + std::to_string(l.at("index").get<int>())];
  CHECK(red["robot1"] > 0);
  CHECK(red["object0"] == 12);  // the block's 12 edges
  CHECK(red.count("robot0") == 0);

  // The belt cell of the test above: its beam is broken 4.73 .. 4.83 s, in b's steps.
  writeBeltCell(dir, "b.rsd");
  const auto sensorLines = [&](const char* at) {
    int n = 0;
    const nlohmann::json d = cellDump({"render", dir.file("b.rsd"), "--at", at, "--dump-lines=json"});
    for (const auto& l : d.at("lines"))
      n += l.at("owner") == "sensor";
    return n;
  };
  CHECK(sensorLines("4.7") == 0);
  CHECK(sensorLines("4.75") == 1);  // a beam: one line
  CHECK(sensorLines("4.9") == 0);
}
