// The swept check's bound at every speed a description allows (docs/models.md,
// "Collisions"): the checks are spaced by how far the parts move, not by
// the clock. A carriage 40 wide slides 100 along x in one move, through a
// rail 40 thick standing across its way: at 1,000,000 counts a second the
// move takes 1 ms and the checks step through it; at 1,000,000,000 it takes
// a single microsecond, so the clock has only its two ends, where the
// carriage is clear of the rail on either side. It must collide all the
// same, up to the largest speed a description can write (1,000,000,000)
// and the largest an image can carry (2,147,483,647, which the verifier
// lets through), and a move that passes beside the rail must not.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "../render/render_test_util.h"
#include "compiler/description/library.h"
#include "runtime/run/run.h"
#include "vm/verify.h"

namespace {

// The carriage: x -20..20 at home, y 0..40, z -20..20, sliding along x
// (frame 0's z axis points along world x). The rail: x 30..70, y -30..70,
// z from `railZ` - 50 to `railZ` + 50. The carriage ends at x 80..120.
std::string fastCell(std::int64_t speed, int railZ) {
  return fmt::format(R"(
LINK fast_base
  BOX -10 10 -10 0 10 -10
END
LINK fast_carriage
  BOX -20 20 0 40 20 -20
END
ROBOT fast
  LINK fast_base      FRAME ORIGIN 0 0 0  XAXIS 0 100 0  ZAXIS 100 0 0
  LINK fast_carriage  FRAME ORIGIN 0 0 0  XAXIS 0 100 0  ZAXIS 100 0 0
  JOINT 1 PRISMATIC  LETTER X  PRECISION 0.1  RANGE -2000 2000  SPEED {}
END
OBJECT fast_rail
  BOX 0 40 0 100 0 -100
END
WORKCELL fast-cell
  FLOOR NONE
  ROBOT fast AT 0 0 0
  OBJECT fast_rail AT 30 -30 {}
END
)",
                     speed, railZ + 50);
}

struct FastRun {
  rs::vm::RunOutcome outcome;
  std::size_t collisions = 0;
  std::vector<std::int32_t> at;  // the motors at the first collision
};

// The description says `speed` (at most its 1e9); the image's motor table
// says `imageSpeed`.
FastRun slideThrough(std::int64_t imageSpeed, int railZ = 0) {
  const std::int64_t speed = std::min<std::int64_t>(imageSpeed, 1'000'000'000);
  const rs::testing::TempDir dir;
  const std::string file = dir.write("fast-cell.rsd", fastCell(speed, railZ));
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> cell = library.workcell(file);
  for (const auto& d : library.diagnostics()) INFO(d.message);
  REQUIRE(cell);
  REQUIRE(library.diagnostics().empty());
  REQUIRE(cell->robots.front().robot.joints.front().speed == speed);
  rs::vm::Image image = rendertest::compileText("        MOVETO 1000\n        END\n", *cell);
  REQUIRE(image.motors.size() == 1);
  image.motors[0].speed = static_cast<std::int32_t>(imageSpeed);
  REQUIRE(rs::vm::verify(image).message.empty());
  const std::unique_ptr<rs::runtime::Run> run =
      rendertest::runOf(image, &*cell, {}, false, rs::runtime::CollisionMode::Warn);
  FastRun r;
  r.outcome = run->runToEnd();
  r.collisions = run->rig().collisions().size();
  if (r.collisions) r.at = run->rig().collisions().front().encoders;
  return r;
}

}  // namespace

TEST_CASE("a carriage cannot pass through a rail in one move at any speed an image allows",
          "[collision][sweep]") {
  for (const std::int64_t speed : {1'000'000LL, 1'000'000'000LL, 2'147'483'647LL}) {
    INFO("SPEED " << speed);
    const FastRun r = slideThrough(speed);
    CHECK(r.outcome.ok());  // --collisions=warn: the run goes on
    CHECK(r.collisions == 1);
    // The first contact: the carriage's front (x = 20 + X/10) within the
    // sweep bound (1 unit, 10 counts) past the rail's face at x 30.
    REQUIRE(r.at.size() == 1);
    CHECK(r.at[0] >= 100);
    CHECK(r.at[0] <= 100 + 10 + 1);
  }
}

TEST_CASE("a fast carriage beside the rail finds nothing, in a few checks", "[collision][sweep]") {
  // The rail moved 100 along z: the carriage (z -20..20) passes 30 from it.
  for (const std::int64_t speed : {1'000'000LL, 1'000'000'000LL, 2'147'483'647LL}) {
    INFO("SPEED " << speed);
    const FastRun r = slideThrough(speed, 100);
    CHECK(r.outcome.ok());
    CHECK(r.collisions == 0);
  }
}
