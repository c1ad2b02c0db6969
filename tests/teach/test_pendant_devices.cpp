// The teach pendant on a cell with devices (issue 35): the state shows
// each sensor and belt, switching an output runs the belt it drives, and
// letting the cell run (runCell) moves the parts on it, breaks the beam and
// turns on the input the beam is wired to. On the library's adept-cell
// (stdlib/workcells/adept-cell.rsd): the infeed runs at 100 mm/s while
// output 1 is ON, the outfeed always; the second block (object index 2)
// spans x 150..190 on the infeed, so running from standstill its front
// reaches the beam at x = 300 after 110 / 100 = 1.1 s; the beam is wired
// to input 1.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "../render/render_test_util.h"
#include "compiler/description/library.h"
#include "tests/models/models_support.h"
#include "tests/teach/carry_cell.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/teach/commands.h"
#include "tools/teach/pendant.h"

namespace {

struct AdeptPendant {
  AdeptPendant()
      : path(dir.write("pick.rsp", "        END\n")),
        cell(std::make_shared<const rs::workcell::Workcell>(rendertest::cell("adept-cell"))) {
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    pendant = std::make_unique<rs::teach::Pendant>(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
  }
  rs::testing::TempDir dir;
  std::string path;
  std::shared_ptr<const rs::workcell::Workcell> cell;
  std::unique_ptr<rs::teach::Pendant> pendant;
};

}  // namespace

TEST_CASE("pendant: shows the devices, an output runs its belt, the cell runs on request", "[teach][devices]") {
  AdeptPendant f;
  rs::teach::Pendant& p = *f.pendant;
  const double x0 = f.cell->objects[2].F_world_design.translation().x();
  rs::teach::PendantState s = p.state();
  REQUIRE(s.sensors.size() == 1);
  CHECK(s.sensors[0].name == "eye");
  CHECK_FALSE(s.sensors[0].on);
  REQUIRE(s.conveyors.size() == 2);
  CHECK(s.conveyors[0].name == "infeed");
  CHECK_FALSE(s.conveyors[0].on);  // output 1 is OFF
  CHECK(s.conveyors[1].on);        // RUN ON
  // The feeder's first part is in the cell, its other slots are not.
  const std::size_t placed = 4;  // infeed, two blocks, outfeed
  REQUIRE(s.objects.size() > placed + 1);
  CHECK(s.objects[placed].present);
  CHECK_FALSE(s.objects[placed + 1].present);

  // Output 1 runs the infeed at once; the parts move only while the cell runs.
  REQUIRE(p.setOutput(1, true).ok);
  s = p.state();
  CHECK(s.conveyors[0].on);
  CHECK(s.objects[2].pose.translation().x() == Approx(x0));
  const rs::teach::Outcome ran = p.runCell(1.0);
  INFO(ran.message);
  REQUIRE(ran.ok);
  s = p.state();
  CHECK(s.clock == 1'000'000);
  CHECK(s.objects[2].pose.translation().x() == Approx(x0 + 100).margin(1e-6));
  CHECK_FALSE(s.sensors[0].on);  // its front at x 290: 10 short of the beam
  CHECK((s.inputs & 1) == 0);
  // The motion shows the belt's run frame by frame (40 ms), the robot still.
  REQUIRE(s.motion.size() == 26);
  CHECK(s.motion.back().at == 1'000'000);
  CHECK(s.motion[1].objects[2].translation().x() == Approx(x0 + 4).margin(1e-6));
  CHECK(s.motion[1].encoders == s.encoders);
  // 0.2 s more: the front passes x = 300 at 1.1 s, the beam breaks, input 1 turns on.
  REQUIRE(p.runCell(0.2).ok);
  s = p.state();
  CHECK(s.sensors[0].on);
  CHECK(s.sensors[0].count == 1);
  CHECK((s.inputs & 1) == 1);
  CHECK(s.objects[2].pose.translation().x() == Approx(x0 + 120).margin(1e-6));
  // The page's JSON.
  const nlohmann::ordered_json j = rs::teach::pendantJson(s, p.placements());
  CHECK(j["devices"]["sensors"][0]["on"] == true);
  CHECK(j["devices"]["conveyors"][0]["running"] == true);
  CHECK(j["devices"]["feeders"] == nlohmann::ordered_json::array({{{"name", "parts"}, {"fed", 1}}}));  // its first block, at 0 s
  CHECK(j["objects"][placed + 1]["present"] == false);
  // Any other operation leaves the cell's motion behind.
  REQUIRE(p.setOutput(1, false).ok);
  CHECK(p.state().motion.empty());
  CHECK_FALSE(p.state().conveyors[0].on);
}

TEST_CASE("pendant: runCell refuses a bad duration", "[teach][devices]") {
  AdeptPendant f;
  CHECK(rs::teach::applyCommand(*f.pendant, {{"op", "runCell"}}).badRequest);
  CHECK(rs::teach::applyCommand(*f.pendant, {{"op", "runCell"}, {"seconds", "1"}}).badRequest);
  const rs::teach::Outcome zero = rs::teach::applyCommand(*f.pendant, {{"op", "runCell"}, {"seconds", 0}});
  CHECK_FALSE(zero.ok);
  CHECK(zero.badRequest);
  CHECK(rs::teach::applyCommand(*f.pendant, {{"op", "runCell"}, {"seconds", 0.5}}).ok);
  CHECK(f.pendant->state().clock == 500'000);
}

TEST_CASE("pendant: jogging a held block through a beam turns the input it is wired to on, then off",
          "[teach][devices]") {
  // The gantry over a block, a beam at x = 400 wired to input 1 (tests/teach/carry_cell.h).
  rs::testing::TempDir dir;
  const rs::workcell::Workcell built = rs::testing::workcellFromText(teachtest::kCarryCell);
  const auto cell = std::make_shared<const rs::workcell::Workcell>(built);
  const std::string path = dir.write("p.rsp", "        END\n");
  rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
  REQUIRE(file);
  rs::teach::Pendant p(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
  const std::int32_t over[] = {-2800, 2800, 0, 0};
  const rs::teach::Outcome moved = p.moveTo(over);
  INFO(moved.message);
  REQUIRE(moved.ok);
  REQUIRE(p.jog(2, 1490).ok);  // down round the block
  REQUIRE(p.gripper(true).ok);
  REQUIRE(p.jog(2, -1490).ok);  // up: the block y 179..219, x 200..240
  CHECK_FALSE(p.state().sensors[0].on);
  // 1500 counts along +x: the front face at 390, 10 short of the beam.
  REQUIRE(p.jog(0, 1500).ok);
  CHECK_FALSE(p.state().sensors[0].on);
  CHECK((p.state().inputs & 1) == 0);
  // 200 more: the front at 410, the block across the beam.
  REQUIRE(p.jog(0, 200).ok);
  CHECK(p.state().sensors[0].on);
  CHECK(p.state().sensors[0].count == 1);
  CHECK((p.state().inputs & 1) == 1);
  // 400 more: the back face at 440, past it.
  REQUIRE(p.jog(0, 400).ok);
  CHECK_FALSE(p.state().sensors[0].on);
  CHECK((p.state().inputs & 1) == 0);
}

// Issue 36: in a cell of several robots the pendant jogs its robot (the
// cell's first here) and the others stand at home as obstacles: two
// XR-4s facing each other 600 apart, as tests/cli/test_cell_run.cpp's
// "every robot is an obstacle to the other", where left's MOVE 0 600 runs
// its wrist into right's fingers. The same jog 800 apart moves.
TEST_CASE("pendant: the cell's other robots stand at home and are obstacles", "[teach][robots]") {
  rs::testing::TempDir dir;
  const std::string path = dir.write("l.rsp", "        END\n");
  for (const int x : {600, 800}) {
    dir.write("face.rsd", "WORKCELL face\n  ROBOT rhino-xr4 AT 0 750 0 AS left\n  ROBOT rhino-xr4 AT " +
                              std::to_string(x) + " 750 0 ROTATE Y 180 AS right\nEND\n");
    rs::compiler::Library library(rs::compiler::librarySearchPath({dir.path().string()}));
    std::optional<rs::workcell::Workcell> loaded = library.workcell("face");
    REQUIRE(loaded);
    const auto cell = std::make_shared<const rs::workcell::Workcell>(*loaded);
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    rs::teach::Pendant p(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
    const rs::teach::Outcome o = p.jog(1, 600);  // motor E
    INFO(o.message);
    if (x == 600) {
      CHECK_FALSE(o.ok);
      CHECK(o.message.find("of robot 'left' hits ") != std::string::npos);
      CHECK(o.message.find("of robot 'right'") != std::string::npos);
    } else {
      CHECK(o.ok);
    }
  }
}
