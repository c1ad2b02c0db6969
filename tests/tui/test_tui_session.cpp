// The terminal pendant without a terminal: keys pressed by their shared
// key map names (tools/teach/keys.h) into a TuiSession over a real Pendant, and the
// screen it lays out read as text. On the library's gantry cell, whose
// numbers are simple by hand: motors X Z Y (prismatic, 0.1 per count) and
// the gripper A (0..104); the tool centre point is at (500 + X/10,
// 200 - Y/10, 400 + Z/10) in the world (tests/teach/test_pendant.cpp).
// OVER is 50 mm above the first block's middle (Y 1000, not 1500): the
// pendant refuses a move that collides, and on the slanted way to the
// middle the open fingers would cut through the second block.
// tests/tui/test_tui.sh drives the same screen in a real terminal.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/teach/gantry_pendant.h"
#include "tools/teach/keys.h"
#include "tools/teach/pendant.h"
#include "tools/teach/tui/tui_session.h"

namespace {

using rs::teach::tui::Screen;
using rs::teach::tui::TuiSession;

const std::string kProgram =
    "; gantry\n"
    "        MOVEP OVER\n"
    "        END\n"
    "POINTS\n"
    "OVER   -2800  2800  1000    0\n";

struct Fixture : rs::testing::GantryPendant {
  std::unique_ptr<TuiSession> session;
  Fixture() : GantryPendant("g.rsp", kProgram), session(std::make_unique<TuiSession>(*pendant)) {}
  Screen screen() const { return session->screen(80, 24); }
  // Row `r`, trailing blanks dropped.
  std::string row(int r) const {
    std::string s = screen().rows.at(static_cast<std::size_t>(r));
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
  }
  // Row `r`'s left panel (the first 44 columns), trailing blanks dropped.
  std::string left(int r) const {
    std::string s = screen().rows.at(static_cast<std::size_t>(r)).substr(0, 44);
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
  }
  bool shows(const std::string& text) const {
    for (const std::string& r : screen().rows)
      if (r.find(text) != std::string::npos) return true;
    return false;
  }
  void press(std::initializer_list<const char*> keys) {
    for (const char* k : keys) REQUIRE(session->press(k));
  }
};

}  // namespace

TEST_CASE("tui: the first screen, 80x24, every panel", "[teach][tui]") {
  Fixture f;
  const Screen s = f.screen();
  REQUIRE(s.rows.size() == 24);
  for (const std::string& r : s.rows) CHECK(r.size() == 80);
  // The title: program, cell, simulation, cut with '~' before the right
  // corner's keys (the scratch path is long).
  const std::string title = "robotsim teach  " + f.path + "  on gantry-cell  (simulation)";
  REQUIRE(title.size() > 64);
  CHECK(f.row(0).substr(0, 63) == title.substr(0, 63));
  CHECK(f.row(0)[63] == '~');
  CHECK(f.row(0).substr(66) == "? keys  q quit");
  CHECK(f.row(1) == std::string(80, '-'));
  CHECK(f.left(2) == " MOTORS                         jog step 10");
  CHECK(f.left(3) == "   mode joint (m: joint, world, tool)");
  // Letter, joint type, value in counts, range; the gripper open at 0.
  CHECK(f.left(4) == " > X prismatic       0  -5000..5000");
  CHECK(f.left(5) == "   Z prismatic       0  -3400..3400");
  CHECK(f.left(6) == "   Y prismatic       0  -2000..2000");
  CHECK(f.left(7) == "   A gripper         0  0..104  open");
  CHECK(f.left(9) == " TOOL CENTRE POINT (world)");
  CHECK(f.left(10) == "   x 500  y 200  z 400");
  CHECK(f.left(11) == "   approach 0 -1 0");
  CHECK(f.left(13) == "          1 2 3 4 5 6 7 8");
  CHECK(f.left(14) == " INPUTS   . . . . . . . .");
  CHECK(f.left(15) == " OUTPUTS  . . . . . . . .");
  CHECK(f.left(17) == " HOLDS    nothing");
  // The points panel: name, then each value right-aligned to its column.
  CHECK(f.row(2).substr(44) == "| POINTS (1)");
  CHECK(f.row(3).substr(44) == "| > OVER -2800 2800 1000 0");
  CHECK(f.row(21) == std::string(80, '-'));
  CHECK(f.row(23) == "Left/Right jog  Up/Down select  m mode  1 2 3 step  o c grip  t teach  ? keys");
  CHECK(s.cursorRow == -1);
}

TEST_CASE("tui: jog keys move the selected motor by the step, and the tool centre point follows", "[teach][tui]") {
  Fixture f;
  f.press({"ArrowRight"});  // X +10
  f.press({"3", "ArrowRight", "+"});  // X +200
  CHECK(f.pendant->state().encoders[0] == 210);
  f.press({"ArrowDown", "1", "ArrowLeft", "-"});  // Z -2
  CHECK(f.pendant->state().encoders[1] == -2);
  CHECK(f.left(2) == " MOTORS                          jog step 1");
  CHECK(f.left(4) == "   X prismatic     210  -5000..5000");
  CHECK(f.left(5) == " > Z prismatic      -2  -3400..3400");
  // (500 + 21, 200, 400 - 0.2)
  CHECK(f.left(10) == "   x 521  y 200  z 399.8");
  // The selection stops at the first and last motor.
  f.press({"ArrowUp", "ArrowUp", "ArrowUp"});
  CHECK(f.session->selection().motor == 0);
  f.press({"ArrowDown", "ArrowDown", "ArrowDown", "ArrowDown", "ArrowDown"});
  CHECK(f.session->selection().motor == 3);
}

TEST_CASE("tui: teach asks a name, writes the row and selects it", "[teach][tui]") {
  Fixture f;
  f.press({"3", "ArrowRight"});  // X = 100
  f.press({"t"});
  CHECK(f.row(23) == "name of the new point (Enter teaches, Esc cancels):");
  CHECK(f.screen().cursorRow == 23);
  f.press({"U", "P", "X", "Backspace", "Enter"});
  // The new row under OVER, laid out like it (tools/teach/points_edit.h): the
  // name at column 0, values right-aligned where OVER's end.
  CHECK(f.text() == kProgram + "UP       100     0     0    0\n");
  CHECK(f.row(4).substr(44) == "| > UP     100    0    0 0");
  CHECK(f.row(3).substr(44) == "|   OVER -2800 2800 1000 0");
  CHECK(f.row(22).rfind("taught UP", 0) == 0);
  // Escape cancels a question without a change.
  f.press({"t", "Z", "Escape"});
  CHECK(f.row(22) == "cancelled");
  CHECK(f.text() == kProgram + "UP       100     0     0    0\n");
}

TEST_CASE("tui: delete and re-teach ask first, and only y goes ahead", "[teach][tui]") {
  Fixture f;
  f.press({"x"});
  CHECK(f.row(23) == "delete OVER? (y/n)");
  f.press({"Resize"});  // the terminal changed size: the question stays
  CHECK(f.row(23) == "delete OVER? (y/n)");
  f.press({"n"});
  CHECK(f.text() == kProgram);
  f.press({"r", "Enter"});  // anything but y: no
  CHECK(f.text() == kProgram);
  f.press({"x", "y"});
  CHECK(f.text() == "; gantry\n        MOVEP OVER\n        END\nPOINTS\n");
  CHECK(f.row(3).substr(44) == "|   none yet: t teaches one");
  // No point to act on: a note, nothing asked.
  f.press({"g"});
  CHECK(f.row(22) == "there are no points yet: t teaches one");
  CHECK(f.row(23).rfind("Left/Right jog", 0) == 0);
}

TEST_CASE("tui: a refused teach shows why in the message row, marked as an error", "[teach][tui]") {
  Fixture f;
  f.press({"t", "O", "V", "E", "R", "Enter"});  // taken
  CHECK(f.text() == kProgram);
  const Screen s = f.screen();
  CHECK(s.rows[22].find("OVER") != std::string::npos);
  bool marked = false;
  for (const rs::teach::tui::Mark& m : s.marks) marked |= m.row == 22 && m.paint == rs::teach::tui::Paint::Error;
  CHECK(marked);
}

TEST_CASE("tui: go to, inputs, help, a small terminal and quit", "[teach][tui]") {
  Fixture f;
  f.press({"g"});
  CHECK(f.pendant->state().encoders == std::vector<std::int32_t>{-2800, 2800, 1000, 0});
  CHECK(f.left(10) == "   x 220  y 100  z 680");
  f.press({"i", "5"});
  CHECK(f.left(14) == " INPUTS   . . . . # . . .");
  f.press({"i", "9"});
  CHECK(f.row(22) == "inputs are 1..8, not 9");
  f.press({"u", "2"});
  CHECK(f.left(15) == " OUTPUTS  . # . . . . . .");
  f.press({"u", "2"});
  CHECK(f.left(15) == " OUTPUTS  . . . . . . . .");
  f.press({"?"});
  // Every key of the shared key map is listed, paired actions on one line,
  // then the terminal's own keys: one column, rows 2..22.
  CHECK(f.row(2) == " Up Down        select the motor (world, tool: the axis) above / below");
  CHECK(f.row(3) == " Left Right - + jog the selected motor or axis by -step / +step");
  CHECK(f.row(4) == " 1 2 3          jog step 1, 10, 100 (counts, lengths; 1, 5, 15 deg)");
  CHECK(f.row(5) == " m              jog mode: joint, world, tool (in turn)");
  CHECK(f.row(6) == " o c            open / close the gripper");
  CHECK(f.row(7) == " t              teach: name the current pose as a new point");
  CHECK(f.row(12) == " PgUp PgDn      select the point above / below");
  CHECK(f.row(19) == " u 1..8         switch an output");
  CHECK(f.row(20) == " l              read the program file again (after an edit elsewhere)");
  CHECK(f.row(23) == "KEYS, as on the web page: ? hides them, q quits");
  for (const rs::teach::KeyBinding& k : rs::teach::kKeys) {
    INFO(k.key);
    bool listed = false;
    for (int r = 2; r <= 20; ++r) {
      const std::string label = f.row(r).substr(1, 14) + " ";
      listed |= label.find(std::string(k.key.substr(0, 5) == "Arrow" ? k.key.substr(5) : k.key) + " ") !=
                    std::string::npos ||
                (k.key == "PageUp" && label.find("PgUp ") != std::string::npos) ||
                (k.key == "PageDown" && label.find("PgDn ") != std::string::npos);
    }
    CHECK(listed);
  }
  f.press({"?"});
  CHECK(f.shows("TOOL CENTRE POINT"));
  const Screen small = f.session->screen(79, 24);
  CHECK(small.rows.at(0).rfind("robotsim teach needs 80x24: enlarge the terminal (q quits)", 0) == 0);
  CHECK_FALSE(f.session->press("q"));
}

TEST_CASE("tui: the gripper closes on the block at a point and the panel says what it holds", "[teach][tui]") {
  // OVER is 50 mm above the centre of gantry-cell's first block, object 2
  // after the pallet (stdlib/workcells/gantry-cell.rsd). Y down 490 more,
  // to 1 mm above the centre (at the centre the closing fingers would dip
  // 0.09 into the pallet, docs/teach.md), and closing there takes it.
  Fixture f;
  f.press({"g", "ArrowDown", "ArrowDown", "3", "ArrowRight", "ArrowRight", "ArrowRight", "ArrowRight", "2"});
  for (int i = 0; i < 9; ++i) f.press({"ArrowRight"});
  CHECK(f.left(6) == " > Y prismatic    1490  -2000..2000");
  CHECK(f.left(10) == "   x 220  y 51  z 680");
  f.press({"c"});
  CHECK(f.left(7) == "   A gripper       104  0..104  closed");
  CHECK(f.left(17) == " HOLDS    block (object 2)");
  f.press({"o"});
  CHECK(f.left(7) == "   A gripper         0  0..104  open");
  CHECK(f.left(17) == " HOLDS    nothing");
}

TEST_CASE("tui: l reads the file again after an edit elsewhere, and teaching goes on on top of it", "[teach][tui]") {
  Fixture f;
  const std::string edited = kProgram + "; an editor was here\n";
  f.dir.write("g.rsp", edited);
  f.press({"t", "A", "Enter"});
  CHECK(f.text() == edited);  // refused: the edit is kept
  f.press({"l"});
  CHECK(f.row(22).find("read again: 1 points") != std::string::npos);
  f.press({"t", "A", "Enter"});
  // The new row under OVER, above the editor's comment.
  CHECK(f.text() == kProgram + "A          0     0     0    0\n; an editor was here\n");
}

TEST_CASE("tui: m switches the jog mode, in world the arrows select an axis and jog the tool along it",
          "[teach][tui][jog]") {
  Fixture f;
  f.press({"m"});
  CHECK(f.session->selection().mode == rs::teach::JogMode::World);
  CHECK(f.left(2) == " WORLD AXES              jog step 10, 5 deg");
  CHECK(f.left(3) == "   mode world (m: joint, world, tool)");
  // The gantry's axes: X, Y, Z and no turn (it has none).
  CHECK(f.left(4) == " > X       along the world's X");
  CHECK(f.left(5) == "   Y       along the world's Y");
  CHECK(f.left(6) == "   Z       along the world's Z");
  CHECK(f.row(22) == "jog mode world");
  // Z +10 twice, by the step of 10 (the gantry's Z is 0.1 a count: 200 counts), then X -1.
  f.press({"ArrowDown", "ArrowDown", "ArrowDown", "ArrowRight", "+"});
  CHECK(f.session->selection().axis == 2);
  CHECK(f.pendant->state().encoders == std::vector<std::int32_t>{0, 200, 0, 0});
  CHECK(f.row(22) == "world jog Z +10 length units: tool centre point at 500 200 420");
  f.press({"ArrowUp", "ArrowUp", "1", "ArrowLeft"});
  CHECK(f.pendant->state().encoders == std::vector<std::int32_t>{-10, 200, 0, 0});
  CHECK(f.left(9) == "   x 499  y 200  z 420");  // three axes rows: the point one row higher than under four motors
  // Tool, then back to joint.
  f.press({"m"});
  CHECK(f.left(2) == " TOOL AXES                jog step 1, 1 deg");
  CHECK(f.left(4).rfind(" > X       along the tool's x (the normal)", 0) == 0);
  f.press({"m"});
  CHECK(f.left(2) == " MOTORS                          jog step 1");
  // In joint mode the arrows move motors again.
  f.press({"ArrowRight"});
  CHECK(f.pendant->state().encoders == std::vector<std::int32_t>{-9, 200, 0, 0});
}
