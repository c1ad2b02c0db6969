// The swept check's bound (docs/models.md, "Collisions"): between two
// checks of a move no point of the robot moves more than kSweepStep, so a
// plate thicker than kSweepStep + 2 × kContactTolerance cannot be passed
// through unseen — and a plate much thinner can (the checks are spaced, not
// continuous). A blade of no thickness, 505 long, sweeps 90 degrees about a
// vertical axis through plates standing across its path at many angles, at
// its tip, where points move fastest: the blade's tip moves exactly as far
// as the bound allows, so the checks are as far apart as they ever get.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "../render/render_test_util.h"
#include "compiler/description/library.h"
#include "model/workcell/collision_model.h"
#include "runtime/run/run.h"
#include "runtime/sim/sweep_motion.h"

namespace {

using rs::workcell::kContactTolerance;
using rs::workcell::kSweepStep;

constexpr const char* kSweeper = R"(
LINK sweeper_base
  BOX -10 10 0 -10 10 -10
END
LINK sweeper_blade
  BOX 0 505 10 0 0 0
END
ROBOT sweeper
  LINK sweeper_base   FRAME ORIGIN 0 0 0  XAXIS 100 0 0  ZAXIS 0 100 0
  LINK sweeper_blade  FRAME ORIGIN 0 0 0  XAXIS 100 0 0  ZAXIS 0 100 0
  JOINT 1 REVOLUTE  LETTER A  PRECISION 0.01  RANGE -18000 18000  SPEED 3000
END
WORKCELL sweep-cell
  FLOOR NONE
  ROBOT sweeper AT 0 0 0
END
)";

rs::workcell::Workcell sweepCell() {
  const rs::testing::TempDir dir;
  const std::string file = dir.write("sweep-cell.rsd", kSweeper);
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> cell = library.workcell(file);
  for (const auto& d : library.diagnostics()) INFO(d.message);
  REQUIRE(cell);
  REQUIRE(library.diagnostics().empty());
  return *cell;
}

// A plate `thickness` thick (tangentially), across the blade's path at
// `degrees` (the blade turns from +x towards -z), from radius 450 to 505.
rs::workcell::PlacedObject plate(double thickness, double degrees) {
  rs::workcell::ConvexPiece piece;
  piece.box = true;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) piece.points.emplace_back(i ? 505.0 : 450.0, j ? 15.0 : -5.0, (k ? 0.5 : -0.5) * thickness);
  rs::workcell::PlacedObject o;
  o.shape.name = "plate";
  o.shape.collision.push_back(piece);
  o.F_world_design = Eigen::Isometry3d(Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d::UnitY()));
  return o;
}

struct Sweep {
  std::size_t collisions = 0;
  std::uint64_t checks = 0;
};

Sweep sweepThrough(const rs::workcell::Workcell& base, const rs::vm::Image& image, double thickness, double degrees) {
  rs::workcell::Workcell cell = base;
  cell.objects.push_back(plate(thickness, degrees));
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.collisions = rs::runtime::CollisionMode::Warn;
  rs::runtime::Run run(std::move(spec));
  REQUIRE(run.runToEnd().ok());
  REQUIRE(run.rig().collisionWatch());
  for (const rs::runtime::CollisionEvent& e : run.rig().collisions()) {
    CHECK(e.contact.a == rs::workcell::BodyRef{rs::workcell::BodyKind::Link, 1});
    CHECK(e.contact.b == rs::workcell::BodyRef{rs::workcell::BodyKind::Object, 0});
  }
  return {run.rig().collisions().size(), run.rig().collisionWatch()->checks()};
}

}  // namespace

TEST_CASE("no plate thicker than the sweep bound is passed through unseen, thinner ones can be", "[collision][sweep]") {
  const rs::workcell::Workcell cell = sweepCell();
  const rs::vm::Image image = rendertest::compileText("        MOVETO 9000\n        END\n", cell);
  // The model's weight for the one motor: 0.01 degree per count at a reach
  // of 505 from the axis.
  const rs::workcell::CollisionModel model(cell);
  REQUIRE(model.motorWeights().size() == 1);
  CHECK(model.motorWeights()[0] == Approx(0.01 * M_PI / 180 * 505).epsilon(1e-3));

  const double thick = kSweepStep + 2 * kContactTolerance + 0.005;
  int missedThin = 0, caughtThin = 0;
  constexpr int kAngles = 60;
  for (int k = 0; k < kAngles; ++k) {
    // Angles 5..85 degrees, offset by an irrational fraction of a step.
    const double degrees = 5 + 80 * (k + std::fmod(k * 0.6180339887, 1.0)) / kAngles;
    INFO("plate at " << degrees << " degrees");
    const Sweep thickSweep = sweepThrough(cell, image, thick, degrees);
    CHECK(thickSweep.collisions == 1);
    (sweepThrough(cell, image, 0.3 * kSweepStep, degrees).collisions ? caughtThin : missedThin)++;
  }
  CHECK(missedThin > 5);
  CHECK(caughtThin > 5);
  // A whole move with the plate out of the way (behind the blade): the
  // tip covers 505 × π/2 ≈ 793 in the move, which the sampling check
  // checked every 1 (793 checks or more); conservative advancement sees
  // the plate farther than the blade can go: a few checks at most.
  const Sweep clear = sweepThrough(cell, image, thick, 180);
  CHECK(clear.collisions == 0);
  CHECK(clear.checks <= 4);
  // With the plate across the path, the checks come close only near it:
  // far fewer than one per unit of the tip's travel up to it.
  const Sweep near = sweepThrough(cell, image, thick, 45);
  CHECK(near.collisions == 1);
  CHECK(near.checks < 100);
}

// A check looks no farther than MotionBounds::kLookAhead: a plate behind
// the blade's start (60 and 100 degrees behind, 450 and more from the
// blade at radius 450) never counts in a check of the quarter turn, so
// the turn is checked at the same times with it there, elsewhere, or not
// at all (with a look as far as the whole turn, 793 at the tip, the plate
// would be counted and the checks would hang on where it stands); and the
// turn is checked at least once per kLookAhead of the tip's way.
TEST_CASE("a check looks no farther than the look-ahead: what stands beyond it bears on nothing",
          "[collision][sweep]") {
  const rs::workcell::Workcell cell = sweepCell();
  const rs::vm::Image image = rendertest::compileText("        MOVETO 9000\n        END\n", cell);
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.collisions = rs::runtime::CollisionMode::Warn;
  rs::runtime::Run bare(std::move(spec));
  REQUIRE(bare.runToEnd().ok());
  const std::uint64_t alone = bare.rig().collisionWatch()->checks();
  const double tipWay = 505 * M_PI / 2;
  CHECK(alone >= static_cast<std::uint64_t>(std::ceil(tipWay / rs::runtime::MotionBounds::kLookAhead)));
  for (const double behind : {-60.0, -100.0}) {
    INFO("plate at " << behind << " degrees");
    const Sweep s = sweepThrough(cell, image, 20, behind);
    CHECK(s.collisions == 0);
    CHECK(s.checks == alone);
  }
}

// A move's key by what it can reach (CollisionWatch::reachKeyOf) leaves
// out the objects it cannot come near (CollisionData::reachBoxes, outOfReach): a plate the blade's tip passes
// close to counts, plates far round the turn do not, until the turn is
// long enough to come near them.
TEST_CASE("the objects out of a move's reach are the ones it cannot come near", "[collision][sweep]") {
  rs::workcell::Workcell cell = sweepCell();
  cell.objects.push_back(plate(1, 2));    // 15 from the blade at the start
  cell.objects.push_back(plate(1, 30));   // about 225
  cell.objects.push_back(plate(1, -90));  // 450, behind it
  const rs::workcell::CollisionModel model(cell, 0);
  rs::workcell::CollisionData data(model);
  rs::runtime::MotionBounds bounds(model);
  bounds.startMove(std::nullopt);
  std::vector<Eigen::Isometry3d> poses;
  for (const rs::workcell::PlacedObject& o : cell.objects) poses.push_back(o.F_world_design);
  rs::workcell::CollisionQuery query;
  query.objectPoses = poses;
  const auto outOfReach = [&](std::int32_t counts) {
    const std::vector<std::int32_t> from{0}, to{counts};
    std::vector<double> travel;
    for (std::size_t p = 0; p <= model.robotBodies().size(); ++p) travel.push_back(bounds.mostTravel(p, from, to));
    // The blade's tip goes 505 times the turn, and the bound is no less.
    CHECK(*std::max_element(travel.begin(), travel.end()) >= 505 * counts * 0.01 * M_PI / 180);
    // The move as one stretch, measured as CollisionWatch::moveReach does:
    // twice a part's travel plus how far a check looks (the look-ahead, or
    // what the part can still go).
    std::vector<Eigen::AlignedBox3d> boxes;
    data.reachBoxes(from, query, boxes);
    REQUIRE(boxes.size() == travel.size());
    std::vector<char> out;
    for (std::size_t o = 0; o < poses.size(); ++o) {
      bool far = true;
      for (std::size_t p = 0; p < boxes.size(); ++p)
        far = far && rs::workcell::CollisionData::outOfReach(
                         boxes[p], 2 * travel[p] + std::min(rs::runtime::MotionBounds::kLookAhead, travel[p]),
                         data.objectHull(o, poses[o]));
      out.push_back(far);
    }
    return out;
  };
  const std::vector<char> degree = outOfReach(100);  // 1 degree: the tip goes 8.8
  CHECK(!degree[0]);
  CHECK(degree[1]);
  CHECK(degree[2]);
  const std::vector<char> twenty = outOfReach(2000);  // 20 degrees: 176
  CHECK(!twenty[0]);
  CHECK(!twenty[1]);
  CHECK(!twenty[2]);
}
