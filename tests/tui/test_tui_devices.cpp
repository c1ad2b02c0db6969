// The terminal pendant's device rows (issue 35: "the page and the terminal
// pendant show the devices; switching an output runs its belt; jogging a
// part through a beam turns the input on"), as tests/teach/
// test_pendant_devices.cpp checks the page's state. Keys go through a
// TuiSession and the 80x24 screen is read as text.
//
// adept-cell (stdlib/workcells/adept-cell.rsd): the infeed runs at 100 mm/s
// while output 1 is ON, the outfeed always; the feeder puts a block at the
// infeed's start at 0 s and every 6 s; the beam across x = 300 is wired to
// input 1. Block 2 (x 150..190) and block 1 (x 0..40) ride the infeed from
// the moment output 1 turns on at 0 s: block 2's front meets the beam at
// (300 - 190) / 100 = 1.1 s and its back leaves it at 1.5 s; block 1's
// front meets it at 2.6 s and its back leaves at 3.0 s; the fed block (x
// -740..-700) meets it at 10 s. The infeed's end is x = 750: block 2 stops
// there at 5.6 s, block 1 reaches its back at 6.7 s.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "../render/render_test_util.h"
#include "tests/models/models_support.h"
#include "tests/teach/carry_cell.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/teach/pendant.h"
#include "tools/teach/tui/tui_session.h"

namespace {

using rs::teach::tui::TuiSession;

struct TuiOnCell {
  explicit TuiOnCell(rs::workcell::Workcell built)
      : path(dir.write("p.rsp", "        END\n")), cell(std::make_shared<const rs::workcell::Workcell>(std::move(built))) {
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    pendant = std::make_unique<rs::teach::Pendant>(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
    session = std::make_unique<TuiSession>(*pendant);
  }
  // The left panel's row that starts with `title` (" SENSORS"), trailing
  // blanks dropped; "" when no row does.
  std::string rowOf(const std::string& title) const {
    for (std::string r : session->screen(80, 24).rows) {
      r = r.substr(0, 44);
      while (!r.empty() && r.back() == ' ') r.pop_back();
      if (r.rfind(title, 0) == 0) return r;
    }
    return "";
  }
  void press(std::initializer_list<const char*> keys) {
    for (const char* k : keys) REQUIRE(session->press(k));
  }
  rs::testing::TempDir dir;
  std::string path;
  std::shared_ptr<const rs::workcell::Workcell> cell;
  std::unique_ptr<rs::teach::Pendant> pendant;
  std::unique_ptr<TuiSession> session;
};

}  // namespace

TEST_CASE("tui: the device rows, an output runs the belt shown there, the beam turns input 1 on", "[teach][tui][devices]") {
  TuiOnCell f(rendertest::cell("adept-cell"));
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye off (0)");
  CHECK(f.rowOf(" BELTS") == " BELTS    infeed stopped, outfeed runs");
  CHECK(f.rowOf(" FEEDERS") == " FEEDERS  parts fed 1");  // its first block at the start
  f.press({"u", "1"});
  CHECK(f.rowOf(" OUTPUTS") == " OUTPUTS  # . . . . . . .");
  CHECK(f.rowOf(" BELTS") == " BELTS    infeed runs, outfeed runs");
  f.press({"w"});  // the cell runs 1 s: block 2's front at 290, 10 short of the beam
  CHECK(f.pendant->state().clock == 1'000'000);
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye off (0)");
  CHECK(f.rowOf(" INPUTS") == " INPUTS   . . . . . . . .");
  REQUIRE(f.pendant->runCell(0.2).ok);  // 1.2 s: block 2 across the beam
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye ON (1)");
  CHECK(f.rowOf(" INPUTS") == " INPUTS   # . . . . . . .");
  for (int i = 0; i < 5; ++i) f.press({"w"});  // 6.2 s: block 1 passed too, the second block fed at 6 s
  CHECK(f.pendant->state().clock == 6'200'000);
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye off (2)");
  CHECK(f.rowOf(" INPUTS") == " INPUTS   . . . . . . . .");
  CHECK(f.rowOf(" FEEDERS") == " FEEDERS  parts fed 2");
  f.press({"u", "1"});
  CHECK(f.rowOf(" BELTS") == " BELTS    infeed stopped, outfeed runs");
}

TEST_CASE("tui: a block jogged through a beam turns the input row on, then off", "[teach][tui][devices]") {
  // As the page's test: the gantry (the tool centre point at (500 + X/10,
  // 200 - Y/10, 400 + Z/10)) over the block centred at (220, 50, 680), a
  // beam across x = 400 at y = 200 wired to input 1. Held 149 up (y
  // 179..219), the block's x is 200..240 at X -2800; the jog keys move X
  // by 100 counts, 10 mm.
  const rs::workcell::Workcell built = rs::testing::workcellFromText(teachtest::kCarryCell);
  TuiOnCell f(built);
  rs::teach::Pendant& p = *f.pendant;
  const std::int32_t over[] = {-2800, 2800, 0, 0};
  REQUIRE(p.moveTo(over).ok);
  REQUIRE(p.jog(2, 1490).ok);  // down round the block
  REQUIRE(p.gripper(true).ok);
  REQUIRE(p.jog(2, -1490).ok);  // up
  CHECK(f.rowOf(" HOLDS") == " HOLDS    block (object 2)");
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye off (0)");
  CHECK(f.rowOf(" BELTS").empty());  // no conveyor, no row
  f.press({"3"});  // step 100 counts; motor X is selected
  for (int i = 0; i < 15; ++i) f.press({"ArrowRight"});  // the front face at 390
  CHECK(p.state().encoders[0] == -1300);
  CHECK(f.rowOf(" INPUTS") == " INPUTS   . . . . . . . .");
  f.press({"ArrowRight", "ArrowRight"});  // at 410: across the beam
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye ON (1)");
  CHECK(f.rowOf(" INPUTS") == " INPUTS   # . . . . . . .");
  for (int i = 0; i < 4; ++i) f.press({"ArrowRight"});  // the back face at 440: past it
  CHECK(f.rowOf(" SENSORS") == " SENSORS  eye off (1)");
  CHECK(f.rowOf(" INPUTS") == " INPUTS   . . . . . . . .");
}
