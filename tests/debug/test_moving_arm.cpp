// The debugger on a moving arm (issue 24): goto-time stops at the time
// asked, also inside a move, and shows the pose then; a collision and a
// close on nothing are places to stop (`break collision`, `break
// warning`); a step over a close that took nothing says so. Each test runs
// the whole `robotsim debug` command on a library cell with its commands
// from a file (-x), as a user would.
//
// The expected values are worked out from gantry-cell's description
// (stdlib/workcells/gantry-cell.rsd, stdlib/robots/gantry.rsd): motors X,
// Z, Y at 1000, 1000 and 800 counts/s, no acceleration; the tool centre
// point at (500 + X/10, 200 - Y/10, 400 + Z/10); block 1 (object 2) a 40
// cube AT 200 30 700, so its centre is (220, 50, 680); pallet 1's deck top
// at y 30; the open fingers reach 20 below the tool centre point and
// stand beside the block, over the deck.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

// MOVETO over block 1 takes 2.8 s (X and Z 2800 counts at 1000/s); line 2
// lowers the ram by Y counts at 800/s.
std::string gantryLowering(int y) {
  return "        MOVETO -2800 2800 0 0\n"
         "        MOVE 0 0 " + std::to_string(y) + " 0\n"
         "        MOVE 0 0 0 100\n"
         "        END\n";
}

CliResult debugSession(const TempDir& dir, const std::string& program, const std::string& commands,
                       std::vector<std::string> extra = {}) {
  const std::string prog = dir.write("arm.rsp", program);
  const std::string cmds = dir.write("arm.cmds", commands);
  std::vector<std::string> args{"debug", prog, "--cell", "gantry-cell", "-x", cmds};
  args.insert(args.end(), extra.begin(), extra.end());
  return runCli(args);
}

// "tcp = (x, y, z)" after `marker` in the output.
std::array<double, 3> tcpAfter(const std::string& out, const std::string& marker) {
  std::array<double, 3> p{-1, -1, -1};
  const std::size_t from = out.find(marker);
  REQUIRE(from != std::string::npos);
  const std::size_t at = out.find("tcp = (", from);
  REQUIRE(at != std::string::npos);
  REQUIRE(std::sscanf(out.c_str() + at, "tcp = (%lf, %lf, %lf)", &p[0], &p[1], &p[2]) == 3);
  return p;
}

}  // namespace

TEST_CASE("debug: goto-time inside a move stops at that time with the pose then", "[debug][moving-arm]") {
  const TempDir dir;
  // Line 2 runs from 2.8 s to 2.8 + 1500/800 = 4.675 s. At 3.5 s the ram
  // has come down 0.7 s x 800 = 560 counts: the tool centre point is at
  // y 200 - 56 = 144. Before the fix the session stood at 4.675 s, y 50.
  const CliResult r = debugSession(dir, gantryLowering(1500),
                                   "goto-time 3.5\nprint motors\nprint tcp\nprint clock\n"
                                   "step\nprint tcp\n"
                                   "goto-time 2.8\nprint tcp\n"
                                   "goto-time 1.4\nprint tcp\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(r.out.find("at 3.500 s, in the middle of the move of line 2 (it ends at 4.675 s)\n"
                   "line 2 @2, step 1, clock 3.500 s\n") != std::string::npos);
  CHECK(r.out.find("X = -2800\nZ = 2800\nY = 560\nA = 0\n") != std::string::npos);
  const auto mid = tcpAfter(r.out, "clock 3.500 s");
  CHECK(mid[0] == Approx(220).margin(1e-6));
  CHECK(mid[1] == Approx(144).margin(1e-6));
  CHECK(mid[2] == Approx(680).margin(1e-6));
  CHECK(r.out.find("clock = 3.500 s (step 1)\n") != std::string::npos);
  // The step finishes the move under way: the clock at its end.
  CHECK(r.out.find("line 3 @3, step 2, clock 4.675 s\n") != std::string::npos);
  // 2.8 s is the moment between lines 1 and 2: the session stands there.
  CHECK(r.out.find("at 2.800 s\nline 2 @2, step 1, clock 2.800 s\n") != std::string::npos);
  CHECK(tcpAfter(r.out, "clock 2.800 s")[1] == Approx(200).margin(1e-6));
  // Backwards into line 1's move: X and Z half way (1400 counts each).
  CHECK(r.out.find("at 1.400 s, in the middle of the move of line 1 (it ends at 2.800 s)\n") != std::string::npos);
  const auto early = tcpAfter(r.out, "clock 1.400 s");
  CHECK(early[0] == Approx(500 - 140).margin(1e-6));
  CHECK(early[1] == Approx(200).margin(1e-6));
  CHECK(early[2] == Approx(400 + 140).margin(1e-6));
}

TEST_CASE("debug: break collision stops at the moment of the first contact", "[debug][moving-arm]") {
  const TempDir dir;
  // Down 1700 counts: the fingers' lower ends (20 below the tool centre
  // point) meet the deck (y 30) when the tool centre point is at y 50,
  // Y = 1500, 1500/800 = 1.875 s into line 2: at 4.675 s; the move would
  // end at 2.8 + 1700/800 = 4.925 s. The swept check finds the overlap
  // within its step (docs/models.md, "Collisions"): at 4.675 s or a little
  // after, and the pose shown is the one at the time shown.
  const CliResult r = debugSession(dir, gantryLowering(1700),
                                   "break collision\ncontinue\nprint tcp\nprint objects\ncontinue\n",
                                   {"--collisions=warn"});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(r.out.find("breakpoint 1: collision\n") != std::string::npos);
  const std::size_t stop = r.out.find("breakpoint 1 (collision): ");
  REQUIRE(stop != std::string::npos);
  CHECK(r.out.find("hits object 1 (pallet) at 4.6", stop) != std::string::npos);
  double clock = 0;
  const std::size_t place = r.out.find("line 2 @2, step 1, clock ", stop);
  REQUIRE(place != std::string::npos);
  REQUIRE(std::sscanf(r.out.c_str() + place, "line 2 @2, step 1, clock %lf", &clock) == 1);
  CHECK(clock >= 4.675);
  CHECK(clock <= 4.690);
  const auto contact = tcpAfter(r.out, "breakpoint 1 (collision)");
  CHECK(contact[0] == Approx(220).margin(1e-6));
  CHECK(contact[1] <= 50.0);
  CHECK(contact[1] == Approx(200 - (clock - 2.8) * 800 / 10).margin(0.1));  // Y at 800/s, whole counts
  // The block has not moved; its centre is the one worked out above.
  CHECK(r.out.find("2 block at (200.000, 30.000, 700.000), centre (220.000, 50.000, 680.000)\n") != std::string::npos);
}

TEST_CASE("debug: in the default collision mode the run ends at the contact, and the session stands there",
          "[debug][moving-arm]") {
  const TempDir dir;
  // The lowering of the test above, with --collisions=error (the default):
  // the run ends at the collision, which the machine found after making the
  // whole move (to Y 1700, the tool centre point at y 30, at 4.925 s). The
  // arm never got past the contact (Y about 1500, y 50, 4.675 s or a little
  // after): that is the pose shown, at every stop after it, forwards or at
  // a time later in the move. Before the contact, a moment of the move is
  // itself: at 4.0 s, 1.2 s into line 2, Y 960, y 200 - 96 = 104.
  const CliResult r = debugSession(dir, gantryLowering(1700),
                                   "break collision\ncontinue\nprint tcp\nprint motors\ncontinue\nprint tcp\n"
                                   "goto-time 4.8\nprint tcp\ngoto-time 4.0\nprint tcp\ncontinue\nprint tcp\nreverse-step\n"
                                   "print clock\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  const std::size_t stop = r.out.find("breakpoint 1 (collision): runtime error: collision at 4.6");
  REQUIRE(stop != std::string::npos);
  CHECK(r.out.find("hits object 1 (pallet), ", stop) != std::string::npos);  // then how deep (collision_watch.cpp)
  double clock = 0;
  const std::size_t place = r.out.find("line 2 @2, step 1, clock ", stop);
  REQUIRE(place != std::string::npos);
  REQUIRE(std::sscanf(r.out.c_str() + place, "line 2 @2, step 1, clock %lf", &clock) == 1);
  CHECK(clock >= 4.675);
  CHECK(clock <= 4.690);
  CHECK(r.out.compare(r.out.find(" s", place + 25), 23, " s (the run is over)\n  ") == 0);
  const auto contact = tcpAfter(r.out, "breakpoint 1 (collision)");
  CHECK(contact[1] == Approx(200 - (clock - 2.8) * 800 / 10).margin(0.1));
  CHECK(contact[1] > 45);  // not the end of the move (y 30)
  std::int32_t y = 0;
  const std::size_t motors = r.out.find("\nY = ", stop);
  REQUIRE(motors != std::string::npos);
  REQUIRE(std::sscanf(r.out.c_str() + motors, "\nY = %d", &y) == 1);
  CHECK(y >= 1490);
  CHECK(y <= 1510);
  // On: the run is over, the session stays at the contact.
  const std::size_t over = r.out.find("the run is over (runtime error: collision at 4.6", stop);
  REQUIRE(over != std::string::npos);
  CHECK(tcpAfter(r.out.substr(over), "the run is over")[1] == Approx(contact[1]).margin(1e-9));
  // 4.8 s came after the contact: the run had ended.
  const std::size_t later = r.out.find("before 4.800 s\n");
  REQUIRE(later != std::string::npos);
  CHECK(tcpAfter(r.out.substr(later), "before 4.800 s")[1] == Approx(contact[1]).margin(1e-9));
  // 4.0 s, inside the move before the contact.
  const std::size_t before = r.out.find("at 4.000 s, in the middle of the move of line 2 (a collision ends the run in it at 4.6");
  REQUIRE(before != std::string::npos);
  CHECK(tcpAfter(r.out.substr(before), "at 4.000 s")[1] == Approx(104).margin(1e-6));
  CHECK(r.out.find("line 2 @2, step 1, clock 4.000 s\n", before) != std::string::npos);  // not over yet
  // On from there: to the contact.
  const std::size_t onwards = r.out.find("breakpoint 1 (collision): runtime error", before);
  REQUIRE(onwards != std::string::npos);
  CHECK(tcpAfter(r.out.substr(onwards), "breakpoint 1")[1] == Approx(contact[1]).margin(1e-9));
  // And back from the contact: before line 2.
  CHECK(r.out.find("clock = 2.800 s (step 1)\n") != std::string::npos);
}

TEST_CASE("debug: without a breakpoint, the runtime error of a collision stops at the contact", "[debug][moving-arm]") {
  const TempDir dir;
  const CliResult r = debugSession(dir, gantryLowering(1700), "continue\nprint tcp\nprint clock\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  const std::size_t stop = r.out.find("runtime error: collision at 4.6");
  REQUIRE(stop != std::string::npos);
  CHECK(r.out.find("breakpoint", stop) == std::string::npos);
  double clock = 0;
  const std::size_t at = r.out.find("clock = ", stop);
  REQUIRE(at != std::string::npos);
  REQUIRE(std::sscanf(r.out.c_str() + at, "clock = %lf", &clock) == 1);
  CHECK(clock >= 4.675);
  CHECK(clock <= 4.690);
  CHECK(tcpAfter(r.out, "runtime error: collision")[1] == Approx(200 - (clock - 2.8) * 800 / 10).margin(0.1));
}

TEST_CASE("debug: a step over a close that takes nothing says so, and break warning stops there", "[debug][moving-arm]") {
  const TempDir dir;
  // Down 1100 counts: the tool centre point at y 90, 40 above the block's
  // centre (y 50) and 20 above its top (y 70), when line 3 closes.
  const CliResult r = debugSession(dir, gantryLowering(1100), "step 2\nstep\nreverse-step 3\nbreak warning\ncontinue\n");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  const std::string note =
      "the gripper closed on nothing: nearest: block (object 2), its centre 40 below the tool centre point, which is "
      "20 outside its box\n";
  const std::size_t first = r.out.find(note);
  REQUIRE(first != std::string::npos);
  CHECK(r.out.compare(first + note.size(), 14, "line 4 @4, ste") == 0);  // said at the step that ran line 3
  CHECK(r.out.find(note) > r.out.find("line 3 @3, step 2"));  // and not at the steps before
  CHECK(r.out.find("breakpoint 1 (warning: a gripper closing on nothing)\n" + note + "line 4 @4, step 3") !=
        std::string::npos);
}

// examples/straight_lift.rsp on xr4-cell: DEPART 50 runs from 2.311 s to
// 2.731 s and lifts the tool centre point from y 810.05 to 860.11 (the
// trace's poses), then MOVES TAKE brings it back down by 3.149 s. A stop
// inside either is inside one of the line's many lock-step moves, not at
// the line's last one: the pose is on the vertical line (x 240.1, z -40.2
// within the line's bound of 0.1 plus a few counts) and rises, then falls,
// with the time asked.
TEST_CASE("debug: goto-time inside a straight line shows the pose on the line at that time", "[debug][moving-arm]") {
  const TempDir dir;
  const std::vector<double> times{2.35, 2.45, 2.55, 2.65, 2.80, 2.95, 3.10};
  std::string commands;
  for (double t : times) commands += "goto-time " + std::to_string(t) + "\nprint tcp\n";
  const std::string cmds = dir.write("line.cmds", commands);
  const CliResult r = runCli({"debug", std::string(ROBOTSIM_SOURCE_DIR) + "/examples/straight_lift.rsp", "-x", cmds});
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  std::vector<double> ys;
  std::size_t from = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::size_t at = r.out.find("tcp = (", from);
    REQUIRE(at != std::string::npos);
    double x = 0, y = 0, z = 0;
    REQUIRE(std::sscanf(r.out.c_str() + at, "tcp = (%lf, %lf, %lf)", &x, &y, &z) == 3);
    CHECK(std::abs(x - 240.2) < 1.0);
    CHECK(std::abs(z + 40.2) < 1.0);
    CHECK(y > 810.0);
    CHECK(y < 860.2);
    ys.push_back(y);
    from = at + 1;
  }
  // Up through DEPART (the first four), down through MOVES (the last three).
  for (std::size_t i = 1; i < 4; ++i) CHECK(ys[i] > ys[i - 1] + 5.0);
  for (std::size_t i = 5; i < ys.size(); ++i) CHECK(ys[i] < ys[i - 1] - 5.0);
}
