// A point written as a tool pose without GRIP leaves the gripper as it is
// when the move starts (docs/language.md, "Points as tool poses"). It took
// the gripper count of the point written above it in the file: a MOVEP
// through such a point opened the gripper mid-carry and dropped the block.
#include <catch2/catch.hpp>

#include <string>

#include "../render/render_test_util.h"
#include "runtime/run/run.h"
#include "vm/disasm.h"
#include "vm/image_file.h"
#include "vm/verify.h"

namespace {

// xr4-cell's front block (x 220..260, y 780..820, z -60..-20) taken 10 below
// its top, lifted 50, then carried by a joint move to CARRY, 90 above where
// it was taken. CARRY is written under ABOVE, whose GRIP is 0 (open), and
// writes no GRIP itself.
const std::string kCarry =
    "; cell: xr4-cell\n"
    "        MOVEP ABOVE\n"
    "        MOVES GRASP\n"
    "        MOVEP TAKE\n"
    "        DEPART 50\n"
    "        MOVEP CARRY\n"
    "        END\n"
    "POINTS\n"
    "ABOVE   AT 240 870 -40 APPROACH 0 -1 0 GRIP 0\n"
    "CARRY   AT 240 900 -40 APPROACH 0 -1 0\n"
    "GRASP   AT 240 810 -40 APPROACH 0 -1 0\n"
    "TAKE    AT 240 810 -40 APPROACH 0 -1 0 GRIP 115\n";

constexpr std::size_t kBlock = 2;    // object 3
constexpr std::size_t kGripper = 5;  // motor A, after F E D C B

void carriesToCarry(const rs::vm::Image& image, const rs::workcell::Workcell& cell) {
  auto run = rendertest::runOf(image, &cell);
  const Eigen::Vector3d placed = cell.objects[kBlock].F_world_design.translation();
  const rs::vm::RunOutcome outcome = run->runToEnd();
  INFO(outcome.message);
  REQUIRE(outcome.ok());
  CHECK(run->rig().collisions().empty());
  // The gripper still closed (115, TAKE's), the block still in it, 90 above where it stood.
  CHECK(run->rig().motors()[kGripper] == 115);
  CHECK(run->rig().world()->held() == std::optional<std::size_t>(kBlock));
  const Eigen::Vector3d moved = run->rig().world()->objectPose(kBlock, run->rig().motors()).translation() - placed;
  INFO("block moved by (" << moved.x() << ", " << moved.y() << ", " << moved.z() << ")");
  CHECK(moved.y() == Approx(90).margin(1.5));  // the arm's counts round the pose by a few tenths
  CHECK(std::abs(moved.x()) < 1.5);
  CHECK(std::abs(moved.z()) < 1.5);
}

}  // namespace

TEST_CASE("a MOVEP through a pose point without GRIP carries the block on, the gripper as it was",
          "[runtime][pose][grip]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const rs::vm::Image image = rendertest::compileText(kCarry, cell);
  // MOVEP CARRY says so in its instruction; MOVEP TAKE (GRIP written) does not.
  CHECK(image.code[4].a == rs::vm::kPointKeepsGripper);
  CHECK(image.code[2].a == 0);
  CHECK(image.code[0].a == 0);
  carriesToCarry(image, cell);
  SECTION("the same from the compiled image (.rsb)") {
    const std::vector<std::uint8_t> bytes = rs::vm::writeImage(image);
    const auto loaded = rs::vm::loadImage(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    REQUIRE(loaded);
    CHECK(loaded->code[4].a == rs::vm::kPointKeepsGripper);
    carriesToCarry(*loaded, cell);
  }
  SECTION("the listing writes the kept gripper as '='") {
    const std::string listing = rs::vm::instructionComment(image, 4);
    INFO(listing);
    CHECK(listing.rfind("CARRY = ", 0) == 0);
    CHECK(listing.find(" = (from AT 240 900 -40 APPROACH 0 -1 0)") != std::string::npos);
    CHECK(rs::vm::instructionComment(image, 2).find(" 115 (from AT 240 810 -40 APPROACH 0 -1 0 GRIP 115)") !=
          std::string::npos);
  }
  SECTION("the verifier knows the flag and no other") {
    rs::vm::Image bad = image;
    bad.code[4].a = 2;
    CHECK(rs::vm::verify(bad).message == "instruction 5 (MOVEP): point flags 2 unknown");
  }
}

TEST_CASE("a pose point without GRIP opens nothing that is closed, closes nothing that is open", "[runtime][pose][grip]") {
  // With the gripper open the same point leaves it open: what the move starts with, not a count of its own.
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const rs::vm::Image image = rendertest::compileText(
      "; cell: xr4-cell\n"
      "        MOVEP SHUT\n"
      "        MOVEP UP\n"
      "        MOVEP OPEN\n"
      "        MOVEP UP\n"
      "        END\n"
      "POINTS\n"
      "SHUT    AT 240 900 -40 APPROACH 0 -1 0 GRIP 60\n"
      "OPEN    AT 240 900 -40 APPROACH 0 -1 0 GRIP 0\n"
      "UP      AT 240 950 -40 APPROACH 0 -1 0\n",
      cell);
  auto run = rendertest::runOf(image, &cell);
  rs::runtime::RunUntil two;
  two.steps = 2;
  REQUIRE(run->runUntil(two).paused());
  CHECK(run->rig().motors()[kGripper] == 60);
  const rs::vm::RunOutcome outcome = run->runToEnd();
  INFO(outcome.message);
  REQUIRE(outcome.ok());
  CHECK(run->rig().motors()[kGripper] == 0);
}
