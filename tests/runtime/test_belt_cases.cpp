// Belts' cases (issue 35, docs/models.md "What the devices do in a run"):
// a part that runs off an END OPEN end is counted once and settles as a
// released part does (traced, text and JSON), riders queue behind a part a
// gripper holds in their way and behind a pile's footprint, parts stacked
// on a riding part ride with it, and a held part lifted clear frees the
// queue at the end of the lifting move. Every expected place and time is
// worked out by hand in the comments.
#include <catch2/catch.hpp>

#include <memory>
#include <sstream>
#include <string>

#include "../render/render_test_util.h"
#include "tests/models/models_support.h"
#include "runtime/run/placing.h"
#include "runtime/run/run.h"
#include "runtime/run/trace.h"

namespace beltcases {

// Belts 1000 long (x 0..1000 as drawn, the belt's top at y = 10, z 5..45,
// towards +x), one with a stop plate and one open at its end, and a part
// 10 on a side.
const std::string kDescriptions =
    "OBJECT plated\n"
    "  BOX 0 1000 10 0 50 0\n"
    "  BELT 0 1000 10 0 45 5 DIRECTION 1 0 0\n"
    "END\n"
    "OBJECT open\n"
    "  BOX 0 1000 10 0 50 0\n"
    "  BELT 0 1000 10 0 45 5 DIRECTION 1 0 0 END OPEN\n"
    "END\n"
    "OBJECT blk\n"
    "  PART\n"
    "  BOX 0 10 10 0 10 0\n"
    "END\n"
    "OBJECT plate\n"
    "  PART\n"
    "  BOX 0 60 5 0 10 0\n"
    "END\n";

// A cell of `lines`; one without a robot gets one out of the way, to run the program.
rs::workcell::Workcell cellOf(const std::string& lines) {
  const std::string robot = lines.find("ROBOT") == std::string::npos ? "  ROBOT adept-one AT 0 0 -900\n" : "";
  return rs::testing::workcellFromText(kDescriptions + "WORKCELL c\n" + robot + lines + "END\n");
}

struct Ran {
  std::unique_ptr<rs::runtime::Run> run;
  std::string trace;
};

Ran runOn(const rs::workcell::Workcell& cell, const std::string& program,
          rs::runtime::TraceFormat format = rs::runtime::TraceFormat::Text) {
  const rs::vm::Image image = rendertest::compileText(program, cell);
  Ran r;
  r.run = rendertest::runOf(image, &cell, {}, true, rs::runtime::CollisionMode::Off);
  std::ostringstream out;
  rs::runtime::TraceWriter trace(out, format, *r.run);
  r.run->observe(trace);
  r.run->runToEnd();
  trace.finish();
  r.trace = out.str();
  REQUIRE(r.run->outcome());
  REQUIRE(r.run->outcome()->ok());
  return r;
}

// Object `o`'s AT corner (index in the cell's objects) at the end of the run.
Eigen::Vector3d cornerOf(const Ran& r, std::size_t o) { return r.run->rig().objects()[o].at; }

bool has(const std::string& text, const std::string& part) {
  INFO(text);
  return text.find(part) != std::string::npos;
}

}  // namespace beltcases

// Named in full: the unity build puts other test files' helpers of these names beside them.

TEST_CASE("belts: a part that runs off an open end onto a belt at the same height is carried once by each",
          "[belts]") {
  // The open belt x 0..1000, the plated one right after it, x 1000..2000,
  // both tops at y = 10. The part's centre (x 22) reaches the open end at
  // (1000 - 22) / 100 = 9.78 s; it lands on the second belt with no drop
  // and rides to its stop plate: its front at 2000, its AT corner at 1990.
  const auto cell = beltcases::cellOf(
      "  OBJECT open AT 0 0 50 AS first\n"
      "  OBJECT plated AT 1000 0 50 AS second\n"
      "  OBJECT blk AT 17 10 30\n"
      "  CONVEYOR first SPEED 100 RUN ON\n"
      "  CONVEYOR second SPEED 100 RUN ON\n");
  const auto r = beltcases::runOn(cell, "        DELAY 25\n        END\n");
  CHECK(r.run->rig().devices()->carried(0) == 1);  // main counted it twice: it rode the first again from its end
  CHECK(r.run->rig().devices()->carried(1) == 1);
  CHECK(beltcases::cornerOf(r, 2).x() == Approx(1990));
  CHECK(beltcases::cornerOf(r, 2).y() == Approx(10));
  CHECK(beltcases::has(r.trace, "     9.780  conveyor first: blk (object 3) runs off its end: it settles on the belt of plated "
                     "(object 2)\n"));
}

TEST_CASE("belts: a part that runs off an open end drops onto a lower belt, traced, and rides it", "[belts]") {
  // The open belt 100 higher (its top at y = 110), the lower one under its
  // end, x 500..1500, top y = 10. At 9.78 s the part (x 995..1005) drops
  // 110 - 10 = 100 onto the lower belt, which carries it 495 to its stop
  // plate (front at 1500): AT corner (1490, 10).
  const std::string lines =
      "  OBJECT open AT 0 100 50 AS upper\n"
      "  OBJECT plated AT 500 0 50 AS lower\n"
      "  OBJECT blk AT 17 110 30\n"
      "  CONVEYOR upper SPEED 100 RUN ON\n"
      "  CONVEYOR lower SPEED 100 RUN ON\n";
  const auto cell = beltcases::cellOf(lines);
  const auto r = beltcases::runOn(cell, "        DELAY 20\n        END\n");
  CHECK(beltcases::has(r.trace, "     9.780  conveyor upper: blk (object 3) runs off its end: it settles on the belt of plated "
                     "(object 2), dropped 100\n"));
  CHECK(beltcases::cornerOf(r, 2).x() == Approx(1490));
  CHECK(beltcases::cornerOf(r, 2).y() == Approx(10));
  CHECK(r.run->rig().devices()->carried(0) == 1);
  CHECK(r.run->rig().devices()->carried(1) == 1);
  // Expected, not sloppy placing: no warning, not counted as a long drop.
  CHECK(r.run->rig().world()->longDropCount() == 0);
  CHECK(rs::runtime::placingWarnings(*r.run, "p.rsp").empty());
  // The JSON trace's conveyor event, with what it settled on.
  const auto j = beltcases::runOn(cell, "        DELAY 20\n        END\n", rs::runtime::TraceFormat::Json);
  CHECK(beltcases::has(j.trace, "{\"event\":\"conveyor\",\"time\":9.78,\"name\":\"upper\",\"object\":3,\"part\":\"blk\","
                     "\"settled\":{\"on\":\"the belt of plated (object 2)\",\"object\":2,\"belt\":true,\"drop\":100.0},"
                     "\"text\":\"conveyor upper: blk (object 3) runs off its end: it settles on the belt of plated "
                     "(object 2), dropped 100\"}"));
}

TEST_CASE("belts: a part that runs off settles as a released part does, on a part its footprint meets or the floor",
          "[belts]") {
  // The open belt's top at y = 110. A block stands on the floor at x
  // 1001..1011: the part at x 995..1005 overlaps it though its centre (1000)
  // misses it, so it settles on it (its top y = 10): dropped 100, as a
  // let-go there would (main fell past it to the floor: 110).
  const auto onPart = beltcases::cellOf(
      "  OBJECT open AT 0 100 50 AS upper\n"
      "  OBJECT blk AT 17 110 30\n"
      "  OBJECT blk AT 1001 0 30\n"
      "  CONVEYOR upper SPEED 100 RUN ON\n");
  const auto a = beltcases::runOn(onPart, "        DELAY 15\n        END\n");
  CHECK(beltcases::has(a.trace, "     9.780  conveyor upper: blk (object 2) runs off its end: it settles on blk (object 3), "
                     "dropped 100\n"));
  CHECK(beltcases::cornerOf(a, 1).y() == Approx(10));
  // Nothing under it but the floor: dropped 110 onto it.
  const auto onFloor = beltcases::cellOf(
      "  OBJECT open AT 0 100 50 AS upper\n"
      "  OBJECT blk AT 17 110 30\n"
      "  CONVEYOR upper SPEED 100 RUN ON\n");
  const auto b = beltcases::runOn(onFloor, "        DELAY 15\n        END\n");
  CHECK(beltcases::has(b.trace, "     9.780  conveyor upper: blk (object 2) runs off its end: it settles on the floor, dropped 110\n"));
  CHECK(beltcases::cornerOf(b, 1).y() == Approx(0));
  CHECK(beltcases::cornerOf(b, 1).x() == Approx(995));
}

TEST_CASE("belts: a rider stops behind a pile's footprint, and parts stacked on a rider ride with it", "[belts]") {
  // A block stands at the stop plate (x 990..1000) with a plate on it
  // (y 20..25) reaching back to x 960: the rider (x 17..27) stops with its
  // front at the plate's back, 960: AT corner 950 (main let it run on to
  // the block's back, 990: AT corner 980).
  const auto pile = beltcases::cellOf(
      "  OBJECT plated AT 0 0 50 AS line\n"
      "  OBJECT blk AT 990 10 30\n"
      "  OBJECT plate AT 960 20 30\n"
      "  OBJECT blk AT 17 10 30\n"
      "  CONVEYOR line SPEED 100 RUN ON\n");
  const auto a = beltcases::runOn(pile, "        DELAY 15\n        END\n");
  CHECK(beltcases::cornerOf(a, 3).x() == Approx(950));
  CHECK(beltcases::cornerOf(a, 1).x() == Approx(990));  // the pile stays put
  CHECK(beltcases::cornerOf(a, 2).x() == Approx(960));
  // A block on a riding block (x 100..110, its bottom on the other's top
  // at y = 20) rides with it: 100 a second for 3 s, both at x 400..410,
  // each counted once (main left the top one hanging at x 100).
  const auto stack = beltcases::cellOf(
      "  OBJECT plated AT 0 0 50 AS line\n"
      "  OBJECT blk AT 100 10 30\n"
      "  OBJECT blk AT 100 20 30\n"
      "  CONVEYOR line SPEED 100 RUN ON\n");
  const auto b = beltcases::runOn(stack, "        DELAY 3\n        END\n");
  CHECK(beltcases::cornerOf(b, 1).x() == Approx(400));
  CHECK(beltcases::cornerOf(b, 2).x() == Approx(400));
  CHECK(beltcases::cornerOf(b, 2).y() == Approx(20));
  CHECK(b.run->rig().devices()->carried(0) == 2);
  // Stopped at the plate, the stack stays: the lower block's front at
  // 1000 after 8.9 s, the upper on it.
  const auto c = beltcases::runOn(stack, "        DELAY 20\n        END\n");
  CHECK(beltcases::cornerOf(c, 1).x() == Approx(990));
  CHECK(beltcases::cornerOf(c, 2).x() == Approx(990));
}

namespace beltcases {

// The library's adept-one at the origin: its tool centre point at home is
// (800, 580, 0), pointing down; C 5900 lowers it 59, to 1 above the middle
// of a block (40 high) on a belt whose top is at y = 500. A library
// conveyor placed AT 300 0 150 runs x 300..1800 under it (clear of the
// robot's base), its belt z -140..140; the held block stands at x
// 780..820, a rider behind it at x 400..440.
const std::string kHeldLines =
    "  ROBOT adept-one AT 0 0 0\n"
    "  OBJECT conveyor AT 300 0 150 AS line\n"
    "  OBJECT block AT 780 500 20\n"
    "  OBJECT block AT 400 500 20\n"
    "  CONVEYOR line SPEED 100 RUN OUT 1\n";

}  // namespace beltcases

TEST_CASE("belts: riders queue behind a part a gripper holds in their way", "[belts]") {
  const auto cell = beltcases::cellOf(beltcases::kHeldLines);
  // Take the block, run the belt for 10 s: the rider's front (440) stops at
  // the held block's back (780) after 3.4 s: AT corner 740 (main ran it
  // through the held block: 400 + 100 x 10.0 = 1400).
  const auto r = beltcases::runOn(cell,
                       "        MOVE 0 0 5900 0 0\n"
                       "        MOVE 0 0 0 0 80\n"
                       "        OUTSIG 1 ON\n"
                       "        DELAY 10\n"
                       "        END\n");
  REQUIRE(r.run->rig().world()->held());
  CHECK(beltcases::cornerOf(r, 2).x() == Approx(740));
}

TEST_CASE("belts: a held part lifted clear of the belt frees the queue at the end of the lifting move", "[belts]") {
  const auto cell = beltcases::cellOf(beltcases::kHeldLines);
  // The rider waits behind the held block (x 740..780 from 3.4 s after the
  // belt starts); the lift (C 5900 at 50,000 a second: 0.118 s) puts the
  // block's bottom 59 above the belt's top; the rider goes on from the
  // lift's end, 200 in the 2 s after it: AT corner 940 (main ran it
  // through: 400 + 100 x 7.118 = 1111.8).
  const auto r = beltcases::runOn(cell,
                       "        MOVE 0 0 5900 0 0\n"
                       "        MOVE 0 0 0 0 80\n"
                       "        OUTSIG 1 ON\n"
                       "        DELAY 5\n"
                       "        MOVE 0 0 -5900 0 0\n"
                       "        DELAY 2\n"
                       "        END\n");
  CHECK(beltcases::cornerOf(r, 2).x() == Approx(940).margin(1e-3));
}
