// The cell's devices acting on its clock (issue 35, docs/models.md
// "Devices"): a belt carries a part through a beam at the microsecond
// computed here by hand, the sensor's wire ends the robot's WAITFOR, a
// sink takes the part, a feeder waits for its place, a feeder that floods
// the cell stops the run, and two devices listed in either order give the
// same instant.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>

#include "../render/render_test_util.h"
#include "tests/runtime/belt_and_part.h"
#include "tests/models/models_support.h"
#include "launch/run_request.h"
#include "runtime/run/run.h"
#include "runtime/run/trace.h"
#include "vm/io_lines.h"

namespace celldevicestest {

const std::string kObjects = celltest::kBeltAndPart;

rs::workcell::Workcell cellOf(const std::string& devices) {
  // The belt's AT corner (least x, least y, greatest z) at (0, 0, 50)
  // leaves it where it is drawn; the part's, (0, 0, 10), at (17, 10, 30)
  // puts its box at x 17..27, y 10..20 (on the belt), z 20..30.
  return rs::testing::workcellFromText(kObjects +
                                       "WORKCELL c\n"
                                       "  ROBOT adept-one AT 0 0 -900\n"
                                       "  OBJECT belt AT 0 0 50 AS line\n"
                                       "  OBJECT blk AT 17 10 30\n" +
                                       devices + "END\n");
}

struct Ran {
  std::unique_ptr<rs::runtime::Run> run;
  std::string trace;
};

Ran runOn(const rs::workcell::Workcell& cell, const std::string& program) {
  const rs::vm::Image image = rendertest::compileText(program, cell);
  Ran r;
  r.run = rendertest::runOf(image, &cell, {}, true, rs::runtime::CollisionMode::Off);
  std::ostringstream out;
  rs::runtime::TraceWriter trace(out, rs::runtime::TraceFormat::Text, *r.run);
  r.run->observe(trace);
  r.run->runToEnd();
  trace.finish();  // as `run --trace` ends it
  r.trace = out.str();
  return r;
}

}  // namespace celldevicestest

using celldevicestest::cellOf;
using celldevicestest::runOn;

TEST_CASE("a part carried by a belt breaks a beam at the microsecond computed by hand", "[cell][devices]") {
  const auto cell = cellOf(
      "  CONVEYOR line SPEED 37 RUN OUT 2\n"
      "  SENSOR eye BEAM 500 15 0  500 15 60\n"
      "  WIRE eye TO IN 1\n");
  const auto r = runOn(cell, "        OUTSIG 2 ON\n        WAITFOR 1 ON\n        END\n");
  REQUIRE(r.run->outcome()->ok());
  // The part's leading face, x = 27, meets the beam at x = 500 after
  // 473 / 37 = 12.78378378... s: the first whole microsecond it touches
  // is 12,783,784.
  CHECK(r.run->rig().clock() == 12'783'784);
  const rs::runtime::RunLog& log = *r.run->log();
  REQUIRE(log.devices.size() == 1);
  CHECK(log.devices[0].event.kind == rs::runtime::DeviceEvent::Kind::SensorOn);
  CHECK(log.devices[0].event.at == 12'783'784);
  REQUIRE(log.inputChanges.size() == 1);
  CHECK(log.inputChanges[0].at == 12'783'784);
  CHECK(log.inputChanges[0].cause.kind == rs::runtime::InputCause::Kind::Wire);
  CHECK(r.trace.find("    12.784  sensor eye ON\n    12.784  input 1 ON: wire from sensor eye\n") !=
        std::string::npos);
  CHECK(r.run->rig().devices()->sensorCount(0) == 1);
  CHECK(r.run->rig().devices()->carried(0) == 1);
}

TEST_CASE("a belt stops its parts at its end, one behind another, and a sink takes what enters it",
          "[cell][devices]") {
  // Speed 100: the part's front (27) reaches the stop plate (1000) at 9.73 s.
  const auto stopped = cellOf("  CONVEYOR line SPEED 100 RUN ON\n");
  const auto a = runOn(stopped, "        DELAY 20\n        END\n");
  const auto objects = a.run->rig().objects();
  CHECK(objects[1].at.x() == Approx(990));
  // A sink over x 600..700: the part's centre (22) enters at x 600 after 5.78 s.
  const auto sunk = cellOf(
      "  CONVEYOR line SPEED 100 RUN ON\n"
      "  SINK done ZONE 600 700 30 0 50 0\n");
  const auto b = runOn(sunk, "        DELAY 20\n        END\n");
  CHECK(b.run->rig().devices()->taken(0) == 1);
  CHECK_FALSE(b.run->rig().devices()->present(1));
  CHECK(b.trace.find("     5.780  sink done: takes blk (object 2)\n") != std::string::npos);
}

TEST_CASE("a feeder puts parts that get new numbers and waits while its place is taken", "[cell][devices]") {
  // A part every 2 s at x 100..110 on a belt that does not run: the first
  // at 0 is object 3, the next waits.
  const auto cell = cellOf("  FEEDER f blk AT 100 10 30 EVERY 2\n");
  const auto r = runOn(cell, "        DELAY 5\n        END\n");
  CHECK(r.run->rig().devices()->fed(0) == 1);
  CHECK(r.trace.find("     0.000  feeder f: blk (object 3) at (100, 10, 30)\n") != std::string::npos);
  CHECK(r.trace.find("     2.000  feeder f: waits, its place is taken by blk (object 3)\n") != std::string::npos);
  // Running at 100, the part leaves its place (x 100..110) after 0.1 s: a
  // part every 2 s, numbered 3, 4, 5 (object 2 is the placed one).
  const auto running = cellOf(
      "  CONVEYOR line SPEED 100 RUN ON\n"
      "  FEEDER f blk AT 100 10 30 EVERY 2\n");
  const auto s = runOn(running, "        DELAY 5\n        END\n");
  CHECK(s.run->rig().devices()->fed(0) == 3);
  CHECK(s.trace.find("     4.000  feeder f: blk (object 5) at (100, 10, 30)\n") != std::string::npos);
}

TEST_CASE("a feeder that floods the cell stops the run at its limit of parts", "[cell][devices]") {
  // 1000 a second carry each part 20 away before the next: 64 parts fill
  // the feeder's slots by 1.26 s, the 65th stops the run.
  const auto cell = cellOf(
      "  CONVEYOR line SPEED 1000 RUN ON\n"
      "  FEEDER f blk AT 30 10 30 EVERY 0.02\n");
  const auto r = runOn(cell, "        DELAY 5\n        END\n");
  REQUIRE(r.run->outcome());
  CHECK_FALSE(r.run->outcome()->ok());
  CHECK(r.run->outcome()->message.find("feeder f has 64 parts in the cell at once") != std::string::npos);
  CHECK(r.run->rig().clock() == 1'280'000);
}

TEST_CASE("two devices at one instant give the same inputs whichever is listed first", "[cell][devices]") {
  const std::string eye1 = "  SENSOR eye1 BEAM 500 15 0  500 15 60\n  WIRE eye1 TO IN 1\n";
  const std::string eye2 = "  SENSOR eye2 BEAM 500 12 0  500 12 60\n  WIRE eye2 TO IN 2\n";
  const std::string belt = "  CONVEYOR line SPEED 37 RUN OUT 2\n";
  const std::string program = "        OUTSIG 2 ON\n        WAITFOR 1 ON\n        END\n";
  const auto a = runOn(cellOf(belt + eye1 + eye2), program);
  const auto b = runOn(cellOf(belt + eye2 + eye1), program);
  REQUIRE(a.run->outcome()->ok());
  REQUIRE(b.run->outcome()->ok());
  CHECK(a.run->rig().clock() == 12'783'784);
  CHECK(b.run->rig().clock() == a.run->rig().clock());
  // Both beams broke at the instant the WAITFOR ended, in both orders.
  CHECK(a.run->rig().machine().inputs() == 0b11);
  CHECK(b.run->rig().machine().inputs() == 0b11);
}


TEST_CASE("a stimulus for an input the cell wires is an error at the stimulus's line", "[cell][devices]") {
  const auto cell = cellOf("  SENSOR eye BEAM 500 15 0  500 15 60\n  WIRE eye TO IN 1\n");
  rs::testing::TempDir dir;
  rs::launch::RunRequest request;
  request.stimuliFile = dir.write("s.stim", "at 1 input 2 on\nat 2 input 1 on\n");
  rs::launch::LoadedProgram program;
  program.image = std::make_shared<const rs::vm::Image>(rendertest::compileText("        END\n", cell));
  program.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  std::vector<rs::diag::Diagnostic> diags;
  CHECK_FALSE(rs::launch::prepareRun(program, request, diags, 1000));
  REQUIRE(diags.size() == 1);
  CHECK(diags[0].pos.line == 2);  // input 2 is not wired: line 1 is fine
  CHECK(diags[0].pos.col == 1);
  CHECK(diags[0].message == "input 1 has a second source: this stimulus, and the WIRE at line 14 of workcell c");
  CHECK_FALSE(diags[0].hint.empty());  // the WIRE is line 14: 8 lines of objects, WORKCELL, ROBOT, two OBJECTs, SENSOR
}

TEST_CASE("a program that answers its own inputs through wires at one instant stops with the wires named",
          "[cell][devices]") {
  // OUT 1 drives IN 1 inverted, OUT 2 drives IN 2: each WAITFOR is met at
  // once by the OUTSIG before it, so the loop never lets the clock move.
  const auto cell = cellOf(
      "  WIRE OUT 1 TO IN 1 INVERTED\n"
      "  WIRE OUT 2 TO IN 2\n");
  // A still-clock limit of 20,000 instructions, not the default 10,000,000:
  // the sanitizer build runs the suite too.
  const auto stillRun = [](const rs::workcell::Workcell& c, const std::string& program) {
    rs::runtime::RunSpec spec;
    spec.collisions = rs::runtime::CollisionMode::Off;
    spec.image = std::make_shared<const rs::vm::Image>(rendertest::compileText(program, c));
    spec.cell = std::make_shared<const rs::workcell::Workcell>(c);
    spec.limits.maxStepsPerInstant = 20'000;
    auto run = std::make_unique<rs::runtime::Run>(std::move(spec));
    run->runToEnd();
    return run;
  };
  const auto r = stillRun(cell,
                       "l:      OUTSIG 1 OFF\n"
                       "        WAITFOR 1 ON\n"
                       "        OUTSIG 2 ON\n"
                       "        WAITFOR 2 ON\n"
                       "        OUTSIG 1 ON\n"
                       "        WAITFOR 1 OFF\n"
                       "        OUTSIG 2 OFF\n"
                       "        WAITFOR 2 OFF\n"
                       "        GOTO l\n");
  REQUIRE(r->outcome());
  CHECK(r->outcome()->reason == rs::vm::StopReason::InstantLimit);
  CHECK(r->rig().clock() == 0);
  // The WORKCELL block's WIRE lines are 13 and 14 (8 lines of objects, WORKCELL, ROBOT, two OBJECTs).
  const std::string m = r->outcome()->message;  // outcome() is a copy
  INFO(m);
  CHECK(m.find("; wires changed its inputs at that instant without end: ") != std::string::npos);
  CHECK(m.find("OUT 1 TO IN 1 (line 13)") != std::string::npos);
  CHECK(m.find("OUT 2 TO IN 2 (line 14)") != std::string::npos);
  // Without wires, the same kind of stop names none.
  const auto plain = stillRun(cellOf(""), "l:      OUTSIG 1 ON\n        GOTO l\n");
  REQUIRE(plain->outcome());
  CHECK(plain->outcome()->reason == rs::vm::StopReason::InstantLimit);
  CHECK(plain->outcome()->message.find("wires") == std::string::npos);
}

TEST_CASE("a JMPIN right after the OUTSIG that a wire carries to its input reads the new value", "[cell][devices]") {
  // docs/language.md: a read sees every change due at the present
  // microsecond, the wire's from the robot's own OUTSIG included.
  const auto cell = cellOf("  WIRE OUT 1 TO IN 1\n  WIRE OUT 2 TO IN 2 INVERTED\n");
  const auto r = runOn(cell,
                      "        OUTSIG 1 ON\n"
                      "        JMPIN 1 ON seen\n"
                      "        OUTSIG 8 ON\n"  // not reached when the jump is taken
                      "seen:   OUTSIG 2 ON\n"
                      "        JMPIN 2 OFF gone\n"
                      "        OUTSIG 7 ON\n"
                      "gone:   END\n");
  REQUIRE(r.run->outcome());
  CHECK(r.run->outcome()->reason == rs::vm::StopReason::End);
  const rs::vm::IoMask outputs = r.run->rig().machine().outputs();
  CHECK(rs::vm::lineIsOn(outputs, 1));
  CHECK(rs::vm::lineIsOn(outputs, 2));
  CHECK_FALSE(rs::vm::lineIsOn(outputs, 8));
  CHECK_FALSE(rs::vm::lineIsOn(outputs, 7));
  CHECK(r.run->rig().clock() == 0);
  // The wire's change is in the trace at the instant, before END.
  INFO(r.trace);
  CHECK(r.trace.find("input 1 ON: wire from OUT 1") < r.trace.find("END"));
}

TEST_CASE("RESET takes the parts a feeder put out of the cell, and the feeder goes on", "[cell][devices]") {
  // Parts every 2 s onto a running belt: objects 3 (at 0 s) and 4 (at 2 s)
  // are in the cell when RESET at 3 s puts everything back where the
  // workcell placed it, which places no fed part; the part fed at 4 s is
  // the next number, 5.
  const auto cell = cellOf(
      "  CONVEYOR line SPEED 100 RUN ON\n"
      "  FEEDER f blk AT 100 10 30 EVERY 2\n");
  const auto r = runOn(cell, "        DELAY 3\n        RESET\n        DELAY 2.5\n        END\n");
  REQUIRE(r.run->outcome());
  REQUIRE(r.run->outcome()->ok());
  CHECK(r.run->rig().devices()->fed(0) == 3);
  std::vector<std::uint32_t> present;
  for (const rs::runtime::ObjectView& v : r.run->rig().objects())
    if (v.present) {
      present.push_back(v.number);
      CHECK(v.pose.translation().y() > -1000);  // nothing parked is shown
    }
  CHECK(present == std::vector<std::uint32_t>{1, 2, 5});
  // The devices hold the same: the slots of 3 and 4 are free again.
  std::vector<std::uint32_t> numbered;
  for (std::size_t o = 0; o < r.run->rig().objects().size(); ++o)
    if (const std::uint32_t n = r.run->rig().devices()->number(o)) numbered.push_back(n);
  std::sort(numbered.begin(), numbered.end());
  CHECK(numbered == std::vector<std::uint32_t>{1, 2, 5});
  CHECK(r.trace.find("     4.000  feeder f: blk (object 5) at (100, 10, 30)\n") != std::string::npos);
}

TEST_CASE("END right after RESET: the summary shows the cell after the devices' look at that instant",
          "[cell][devices]") {
  // The part fed at 0 s into the zone is the only thing the zone sees;
  // RESET at 1 s takes it out of the cell, and END at that same
  // microsecond must not end the run before the sensor sees it gone.
  const auto cell = cellOf(
      "  FEEDER f blk AT 100 10 30 EVERY 5 COUNT 1\n"
      "  SENSOR z ZONE 95 115 25 5 15 35\n");
  const auto r = runOn(cell, "        DELAY 1\n        RESET\n        END\n");
  REQUIRE(r.run->outcome());
  REQUIRE(r.run->outcome()->ok());
  INFO(r.trace);
  CHECK(r.trace.find("     0.000  sensor z ON\n") != std::string::npos);
  CHECK(r.trace.find("     1.000  sensor z OFF\n") != std::string::npos);
  CHECK_FALSE(r.run->rig().devices()->sensorOn(0));
  CHECK(r.run->rig().devices()->sensorCount(0) == 1);
}

TEST_CASE("END right after an output a feeder reads: a flood at that instant fails the run", "[cell][devices]") {
  // 64 rising edges of output 1, 0.03 s apart, each feed a part that the
  // belt carries 30 away (a part is 10 long): the feeder's 64 slots are
  // full. The 65th edge comes with END at the same microsecond: the
  // devices' look then feeds a 65th part, which has no slot.
  const auto cell = cellOf(
      "  CONVEYOR line SPEED 1000 RUN ON\n"
      "  FEEDER f blk AT 30 10 30 WHEN OUT 1\n");
  const std::string edges =
      "        SET N 0\n"
      "l:      OUTSIG 1 ON\n"
      "        DELAY 0.02\n"
      "        OUTSIG 1 OFF\n"
      "        DELAY 0.01\n"
      "        ADD N 1\n"
      "        JMPVAR N < 64 l\n";
  const auto r = runOn(cell, edges + "        OUTSIG 1 ON\n        END\n");
  REQUIRE(r.run->outcome());
  CHECK_FALSE(r.run->outcome()->ok());
  CHECK(r.run->outcome()->reason == rs::vm::StopReason::RuntimeError);
  CHECK(r.run->outcome()->message.find("feeder f has 64 parts in the cell at once") != std::string::npos);
  CHECK(r.run->rig().devices()->fed(0) == 64);
  CHECK(r.run->rig().clock() == 64 * 30'000);
  // One edge fewer at the end: the run ends as the program does.
  const auto fine = runOn(cell, edges + "        END\n");
  REQUIRE(fine.run->outcome());
  CHECK(fine.run->outcome()->ok());
  CHECK(fine.run->rig().devices()->fed(0) == 64);
}

TEST_CASE("a DELAY right after RESET: the devices look at RESET's instant, not at the DELAY's end",
          "[cell][devices]") {
  // As above, with a DELAY after RESET that nothing else in the cell
  // interrupts (the feeder is done): the robot's wait finishes alone on the
  // clock (SimMachine::finishAlone), and the devices must still see RESET
  // take the part at 1 s, not when the robot next waits on the cell.
  const auto cell = cellOf(
      "  FEEDER f blk AT 100 10 30 EVERY 5 COUNT 1\n"
      "  SENSOR z ZONE 95 115 25 5 15 35\n");
  const auto r = runOn(cell, "        DELAY 1\n        RESET\n        DELAY 2\n        END\n");
  REQUIRE(r.run->outcome());
  REQUIRE(r.run->outcome()->ok());
  INFO(r.trace);
  CHECK(r.trace.find("     1.000  sensor z OFF\n") != std::string::npos);
  CHECK(r.run->rig().devices()->sensorCount(0) == 1);
}
