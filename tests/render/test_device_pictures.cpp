// The pictures of a cell with devices (issue 35): `render --at` and the
// page put the parts where the belts carried them at that time, draw a
// broken beam in its own colour, leave out a feeder's empty slots and the
// parts a sink took; `plot` has a row per sensor and per conveyor.
//
// On the library's adept-cell with examples/adept_production.rsp (worked
// out from stdlib/workcells/adept-cell.rsd, not read off a run):
//   - the infeed runs at 100 mm/s while output 1 is ON; the program turns
//     it on at 0 s. The second block (object index 2) spans x 150..190, so
//     its front reaches the beam at x = 300 after 110 / 100 = 1.1 s, the
//     beam breaks, input 1 turns on, the program turns output 1 off at
//     1.1 s: from 0 to 1.1 s the block is 100 t further along +x.
//   - the outfeed runs always at 100 mm/s: a block let go on it moves 100
//     mm a second until its centre reaches the sink at x = 640.
//   - the feeder puts a block at 0 s (the first slot, object index 4) and
//     at 6 s (the second slot, index 5, the first still in the cell).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

#include "render_test_util.h"
#include "runtime/render/animation.h"
#include "runtime/render/chart.h"
#include "runtime/render/moment.h"
#include "runtime/render/scene.h"
#include "runtime/run/device_history.h"

using rs::testing::runCli;

namespace {

const std::string kProduction = rendertest::kSourceDir + "/examples/adept_production.rsp";

// The production example on adept-cell, run until `at` (a still's moment).
rs::render::Moment devicesMomentAt(double seconds, bool log = true) {
  const rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  const rs::vm::Image image = rendertest::compile(kProduction, cell);
  auto run = rendertest::runOf(image, &cell, {}, log);
  return rs::render::momentOf(*run, static_cast<rs::vm::Micros>(std::llround(seconds * 1e6)));
}

}  // namespace

TEST_CASE("render --at puts a part where the belt carried it at that time", "[render][devices]") {
  const rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  const Eigen::Vector3d placed = cell.objects[2].F_world_design.translation();
  // The run waits for the beam (WAITFOR 1 ON) from 0 to 1.1 s: a still at
  // 0.5 s must not show the block where it is when the wait ends.
  const rs::render::Moment half = devicesMomentAt(0.5), one = devicesMomentAt(1.0);
  REQUIRE(half.reached);
  REQUIRE(half.objects.size() > 4);
  CHECK(half.objects[2].translation().x() == Approx(placed.x() + 50).margin(1e-6));
  CHECK(one.objects[2].translation().x() == Approx(placed.x() + 100).margin(1e-6));
  CHECK(half.objects[2].translation().z() == Approx(placed.z()).margin(1e-9));
  CHECK(half.objects[2].translation().y() == Approx(placed.y()).margin(1e-9));
  // The beam breaks at 1.1 s and mends when the gripper lifts the block.
  REQUIRE(one.sensorsOn.size() == 1);
  CHECK_FALSE(one.sensorsOn[0]);
  CHECK(devicesMomentAt(1.2).sensorsOn[0]);
  // On the outfeed, a second later is 100 mm further along +x, nothing else.
  const rs::render::Moment three = devicesMomentAt(3.0), four = devicesMomentAt(4.0);
  const Eigen::Vector3d moved = four.objects[2].translation() - three.objects[2].translation();
  CHECK(moved.x() == Approx(100).margin(1e-6));
  CHECK(moved.y() == Approx(0).margin(1e-9));
  CHECK(moved.z() == Approx(0).margin(1e-9));
  CHECK(three.objects[2].translation().z() < 0);  // on the outfeed (z -750..-450)
}

TEST_CASE("a feeder's slot is drawn once fed, and a part a sink took is not", "[render][devices]") {
  const rs::render::Moment early = devicesMomentAt(5.9), fed = devicesMomentAt(6.1);
  using rs::render::kNotInCellBelow;
  CHECK(early.objects[4].translation().y() > kNotInCellBelow);  // fed at 0 s
  CHECK(early.objects[5].translation().y() < kNotInCellBelow);  // not yet
  CHECK(fed.objects[5].translation().y() > kNotInCellBelow);
  // The sink took the first block carried out (object index 2) before 5.9 s:
  // its centre reaches x = 640 (360 mm past where it was let go at x 280).
  CHECK(early.objects[2].translation().y() < kNotInCellBelow);
  // The still's lines: objects in the cell, the slot fed, no empty slot.
  const auto dump = runCli({"render", "adept-cell", "--program", kProduction, "--at", "1.2", "--dump-lines=json"});
  INFO(dump.err);
  REQUIRE(dump.code == 0);
  const auto doc = nlohmann::json::parse(dump.out);
  int sensorLines = 0, slotLines = 0, emptySlotLines = 0;
  for (const auto& line : doc["lines"]) {
    if (line["owner"] == "sensor") {
      ++sensorLines;
      CHECK(line["name"] == "eye");
      CHECK(line["color"] == "LIGHTMAGENTA");
    }
    if (line["owner"] == "object" && line["index"] == 4) ++slotLines;
    if (line["owner"] == "object" && line["index"].get<int>() > 4) ++emptySlotLines;
  }
  CHECK(sensorLines == 1);  // the broken beam: one line between its ends
  CHECK(slotLines == 12);   // the fed block's box
  CHECK(emptySlotLines == 0);
  // At 1.0 s the beam is whole: not drawn.
  const auto whole = runCli({"render", "adept-cell", "--program", kProduction, "--at", "1.0", "--dump-lines=json"});
  REQUIRE(whole.code == 0);
  const nlohmann::json wholeLines = nlohmann::json::parse(whole.out);  // kept: a loop over a temporary's member dangles
  for (const auto& line : wholeLines["lines"]) CHECK(line["owner"] != "sensor");
}

TEST_CASE("an occupied zone is drawn as its box", "[render][devices]") {
  rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  rs::workcell::Sensor zone;
  zone.name = "bay";
  zone.shape = rs::workcell::Sensor::Shape::Zone;
  zone.zone = Eigen::AlignedBox3d(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(11, 22, 33));
  cell.devices.sensors.push_back(zone);
  rs::render::CellPoser poser(cell);
  std::vector<rs::render::Line3> lines;
  const auto sensorLines = [&] {
    poser.lines(lines);
    std::vector<rs::render::Line3> out;
    for (const auto& l : lines)
      if (l.part.kind == rs::render::PartKind::Sensor) out.push_back(l);
    return out;
  };
  CHECK(sensorLines().empty());  // OFF: not drawn
  poser.setSensorOn(1, true);
  const std::vector<rs::render::Line3> box = sensorLines();
  REQUIRE(box.size() == 12);
  double length = 0;
  for (const auto& l : box) {
    CHECK(l.part.owner == 1);
    CHECK(l.color == rs::render::kSensorOnColor);
    length += (l.b - l.a).norm();
  }
  CHECK(length == Approx(4 * (10 + 20 + 30)));  // each edge of a 10 x 20 x 30 box once
}

TEST_CASE("the page's model carries the parts' motions and the sensors' edges", "[render][devices]") {
  const rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  const rs::vm::Image image = rendertest::compile(kProduction, cell);
  auto run = rendertest::runOf(image, &cell, {}, /*log=*/true);
  REQUIRE(run->runToEnd().ok());
  rs::render::AnimationInput input;
  input.cell = run->rig().cell();
  input.run = run->log();
  input.listing.name = "adept_production.rsp";
  const nlohmann::ordered_json model = rs::render::animationModel(input);
  REQUIRE(model.contains("sensors"));
  CHECK(model["sensors"][0]["name"] == "eye");
  CHECK(model["sensors"][0]["pts"] == nlohmann::ordered_json::array({300.0, 520.0, 440.0, 300.0, 520.0, 760.0}));
  CHECK(model["objects"][5]["parked"] == true);
  CHECK_FALSE(model["objects"][2].contains("parked"));
  // The first edges: ON at 1.1 s (the beam breaks), OFF when the block is lifted.
  const auto& edges = model["run"]["sensors"];
  REQUIRE(edges["at"].size() >= 2);
  CHECK(edges["at"][0] == 1'100'000);
  CHECK(edges["on"][0] == true);
  CHECK(edges["on"][1] == false);
  // Object 2's first motion: at 0 s, from where the cell placed it, along +x
  // at 100 mm/s (the page moves its pts by min(100 t, travel)).
  const auto& m = model["run"]["motions"];
  std::size_t first = m["object"].size();
  for (std::size_t i = 0; i < m["object"].size(); ++i)
    if (m["object"][i] == 2) {
      first = i;
      break;
    }
  REQUIRE(first < m["object"].size());
  CHECK(m["at"][first] == 0);
  CHECK(m["velocity"][3 * first] == Approx(100));
  CHECK(m["velocity"][3 * first + 2] == Approx(0));
  CHECK(m["present"][first] == 1);
  for (int k = 9; k < 12; ++k) CHECK(m["pose"][12 * first + k].get<double>() == Approx(0).margin(1e-9));  // P · P⁻¹
  // The stills and the page read the same history.
  const rs::runtime::DeviceHistory history(*run->log(), *run->rig().cell());
  const std::optional<Eigen::Isometry3d> at05 = history.restingPose(2, 500'000);
  REQUIRE(at05);
  CHECK(at05->translation().x() == Approx(cell.objects[2].F_world_design.translation().x() + 50));
}

TEST_CASE("plot has a row per sensor and per conveyor, switching when the trace says", "[render][devices]") {
  const rs::workcell::Workcell cell = rendertest::cell("adept-cell");
  const rs::vm::Image image = rendertest::compile(kProduction, cell);
  auto run = rendertest::runOf(image, &cell, {}, /*log=*/true);
  REQUIRE(run->runToEnd().ok());
  rs::render::ChartInput input;
  input.cell = run->rig().cell();
  input.run = run->log();
  input.every = 1000;  // 1 ms
  const rs::render::Chart chart = rs::render::chartOf(input);
  const auto seriesOf = [&](const std::string& column) -> const std::vector<double>& {
    for (const auto& s : chart.series)
      if (s.column == column) return s.values;
    FAIL("no column " << column);
    return chart.series.front().values;
  };
  const std::vector<double>& eye = seriesOf("sensor_eye");
  const std::vector<double>& infeed = seriesOf("belt_infeed");
  const std::vector<double>& outfeed = seriesOf("belt_outfeed");
  // The sample at (or first after) each edge the log's trace gives has the
  // new state, the one before it the old.
  int edges = 0;
  for (const auto& r : run->log()->devices) {
    const auto& e = r.event;
    if (e.kind != rs::runtime::DeviceEvent::Kind::SensorOn && e.kind != rs::runtime::DeviceEvent::Kind::SensorOff)
      continue;
    const bool on = e.kind == rs::runtime::DeviceEvent::Kind::SensorOn;
    const auto i = static_cast<std::size_t>((e.at + 999) / 1000);
    INFO("edge at " << e.at);
    REQUIRE(i < eye.size());
    CHECK(eye[i] == (on ? 1 : 0));
    if (i > 0) CHECK(eye[i - 1] == (on ? 0 : 1));
    ++edges;
  }
  CHECK(edges == 20);  // ten blocks break the beam and leave it
  CHECK(eye[1100] == 1);  // 1.1 s: the first block's front at the beam (by hand)
  CHECK(eye[1099] == 0);
  // The infeed runs while output 1 is ON: 0 .. 1.1 s (OUTSIG 1 ON, then
  // OFF once the beam breaks); the outfeed always.
  CHECK(infeed[0] == 1);
  CHECK(infeed[1099] == 1);
  CHECK(infeed[1100] == 0);
  for (const double v : outfeed) REQUIRE(v == 1);
  // The lanes: sensors, then conveyors, each row named.
  const auto lane = [&](rs::render::LaneKind kind) -> const rs::render::ChartLane* {
    for (const auto& l : chart.lanes)
      if (l.kind == kind) return &l;
    return nullptr;
  };
  REQUIRE(lane(rs::render::LaneKind::Sensors));
  CHECK(lane(rs::render::LaneKind::Sensors)->rows == std::vector<std::string>{"eye"});
  REQUIRE(lane(rs::render::LaneKind::Conveyors));
  CHECK(lane(rs::render::LaneKind::Conveyors)->rows == std::vector<std::string>{"infeed", "outfeed"});
  // plot itself: the CSV has the columns.
  const rs::testing::TempDir dir;
  const auto csv = runCli({"plot", kProduction, "--cell", "adept-cell", "-o", dir.file("chart.csv")});
  INFO(csv.err);
  REQUIRE(csv.code == 0);
  const std::string text = rs::testing::readBytes(dir.file("chart.csv"));
  CHECK(text.find(",sensor_eye,belt_infeed,belt_outfeed,line\n") != std::string::npos);
}
