// Collision messages say how deep the parts are in each other, and where
// a move ends in what it hits by a little, the distance to go.
//
// The gantry cell, worked out by hand (examples/gantry_pick.rsp): the tool
// centre point is at (500 + X/10, 200 - Y/10, 400 + Z/10); block 1 (object 2)
// is the 40 mm cube x 200..240, y 30..70, z 660..700 on the pallet (object 1,
// its top at y 30). Taken with the tool centre point 1 above the cube's
// middle (Y 1490: y 51), the block rides 21 below it; set down again at Y 1497
// (y 50.3) its bottom would be at 29.3: 0.7 into the pallet, all along y,
// more than the rest tolerance (0.5, docs/models.md) a part may be put into
// its support.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <regex>

#include "tests/cli/cli_support.h"
#include "tests/teach/gantry_pendant.h"

namespace {

constexpr const char* kLowDown =
    "        MOVETO -2800 2800 1000 0    ; over block 1, open\n"
    "        MOVE 0 0 490 0              ; down round it: the centre 1 above the block's middle\n"
    "        MOVE 0 0 0 100              ; close: it takes the block\n"
    "        MOVE 0 0 -490 0             ; up with it\n"
    "        MOVE 0 0 497 0              ; down again, 0.7 lower than it was taken\n"
    "        END\n";

// The number after `before` in `text` (or NaN).
double numberAfter(const std::string& text, const std::string& before) {
  const std::size_t at = text.find(before);
  if (at == std::string::npos) return NAN;
  return std::stod(text.substr(at + before.size()));
}

}  // namespace

TEST_CASE("a block set down 0.7 too low: the collision says how deep, the hint how much higher to end",
          "[collision][depth]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("low.rsp", kLowDown);
  const auto r = rs::testing::runCli({"run", program, "--cell", "gantry-cell"});
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(r.err.find(program + ":5:9: error: runtime error: collision at ") != std::string::npos);
  CHECK(r.err.find(": object 2 (block) hits object 1 (pallet), ") != std::string::npos);
  // Found at the first check that saw it more than the rest tolerance in: some way into the last 0.2 of the move.
  const double depth = numberAfter(r.err, "hits object 1 (pallet), ");
  CHECK(depth > 0.5);
  CHECK(depth <= 0.7 + 1e-9);
  CHECK(r.err.find(" deep (instruction 5)") != std::string::npos);
  CHECK(r.err.find("hint: the move ends with object 2 (block) 0.7 into object 1 (pallet): end it 0.7 higher") !=
        std::string::npos);
  // The JSON summary has the depth as a number.
  const auto j = rs::testing::runCli({"run", program, "--cell", "gantry-cell", "--format=json"});
  const auto s = nlohmann::json::parse(j.out);
  REQUIRE(s.at("collisions").size() == 1);
  CHECK(s["collisions"][0]["depth"].get<double>() == Approx(depth).margin(0.005));
}

TEST_CASE("a move that passes through a part says how deep it is and gives no distance to go", "[collision][depth]") {
  // Open, straight down round block 1 from 50 above it: the fingers pass either side of it. Y 1600 puts the
  // tool centre point at y 40, in the block (which the gripper may overlap there), and the fingers' tips 20
  // below it, 10 into the pallet: far beyond the little the hint is for.
  const rs::testing::TempDir dir;
  const std::string program = dir.write("through.rsp",
                                        "        MOVETO -2800 2800 1000 0\n"
                                        "        MOVE 0 0 600 0\n"
                                        "        END\n");
  const auto r = rs::testing::runCli({"run", program, "--cell", "gantry-cell"});
  INFO(r.err);
  CHECK(r.code == 1);
  const std::smatch m = [&] {
    std::smatch found;
    static const std::regex deep(R"(collision at [0-9.]+ s: .* hits .*, ([0-9.]+) deep \(instruction 2\))");
    std::regex_search(r.err, found, deep);
    return found;
  }();
  REQUIRE(m.size() == 2);
  CHECK(std::stod(m[1].str()) > 0);
  CHECK(r.err.find("the move ends with") == std::string::npos);
}

TEST_CASE("the pendant's refusal of a block set down too low says how much higher to end", "[collision][depth][teach]") {
  rs::testing::GantryPendant f("low.rsp", "        END\nPOINTS\n");
  rs::teach::Pendant& p = *f.pendant;
  REQUIRE(p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1000, 0}).ok);
  REQUIRE(p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1490, 0}).ok);
  REQUIRE(p.gripper(true).message == "gripper closed: holds block");
  REQUIRE(p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1000, 104}).ok);
  // 0.2 too low is within the rest tolerance (0.5): it stands on the pallet; 0.7 too low is refused.
  REQUIRE(p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1492, 104}).ok);
  REQUIRE(p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1000, 104}).ok);
  const rs::teach::Outcome o = p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1497, 104});
  INFO(o.message);
  CHECK_FALSE(o.ok);
  CHECK(p.state().limit == "collision");
  CHECK(o.message.find("object 2 (block) hits object 1 (pallet), ") != std::string::npos);
  CHECK(o.message.find(" deep; nothing moved (the move ends with object 2 (block) 0.7 into object 1 (pallet): end it "
                       "0.7 higher)") != std::string::npos);
  // 0.7 higher, it stands on the pallet.
  CHECK(p.moveTo(std::vector<std::int32_t>{-2800, 2800, 1490, 104}).ok);
}
