// --collisions=warn reports each colliding move once (docs/cli.md): a
// straight line is one move, however many knots it is run in. A colliding
// APPRO was reported once per knot (18 warnings for one instruction).
//
// xr4-cell's front block stands at x 220..260, y 780..820, z -60..-20. With
// the gripper closed (GRIP 115) the fingers meet under the tool centre
// point, so APPRO 45 from 870, pointing down over the block's middle,
// drives them into its top near the end of the line and keeps them in it
// for every knot after, down to 825: above the block, so the gripper is not
// let overlap it as it is where a line ends in the block it will grip.
// Before, that was 16 warnings for the one APPRO. DEPART 45 starts in it.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

constexpr const char* kClosedApproach =
    "        MOVEP ABOVE             ; closed, 60 above the grasp\n"
    "        APPRO 45                ; down into the block's top\n"
    "        DEPART 45\n"
    "        END\n"
    "POINTS\n"
    "ABOVE   AT 240 870 -40 APPROACH 0 -1 0 GRIP 115\n";

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("with --collisions=warn a straight line that collides over many knots is one warning, with its first contact",
          "[collision][cli][straight]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("closed.rsp", kClosedApproach);
  const auto r = rs::testing::runCli({"run", program, "--cell", "xr4-cell", "--collisions=warn", "--format=json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  // APPRO collides; DEPART starts with the fingers in the block and collides too: one each.
  REQUIRE(j.at("collisions").size() == 2);
  CHECK(j["collisions"][0]["line"] == 2);
  CHECK(j["collisions"][1]["line"] == 3);
  CHECK(occurrences(r.err, "warning: collision at ") == 2);
  CHECK(occurrences(r.err, program + ":2:9: warning: collision at ") == 1);
  // With its first contact: where --collisions=error stops the same run (the first knot that collides, at
  // its first check that sees the overlap).
  const auto stop = rs::testing::runCli({"run", program, "--cell", "xr4-cell", "--format=json"});
  CHECK(stop.code == 1);
  const auto e = nlohmann::json::parse(stop.out);
  REQUIRE(e.at("collisions").size() == 1);
  CHECK(e["collisions"][0]["line"] == 2);
  CHECK(e["collisions"][0]["time"] == j["collisions"][0]["time"]);
  CHECK(e["collisions"][0]["part"] == j["collisions"][0]["part"]);
  CHECK(e["collisions"][0]["hits"] == "object 3 (block)");
}
