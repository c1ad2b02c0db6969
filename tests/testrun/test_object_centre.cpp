// Objects by their centres (issue 24): `robotsim test`'s `object N centre
// at X Y Z`, the failure that names the object by number and name, and
// the run summary (text and JSON) that shows each object's centre beside
// its AT corner.
//
// Worked out by hand from stdlib/workcells/gantry-cell.rsd and
// stdlib/robots/gantry.rsd: a block is a 40 cube drawn with its AT corner
// (least x, least y, greatest z) at (0, 0, 40), so its centre is its AT
// corner + (20, 20, -20): block 1 (object 2) AT 200 30 700 has its centre
// at (220, 50, 680), block 2 (object 3) AT 280 30 700 at (300, 50, 680);
// pallet 1 (object 1), 240 x 30 x 160 AT 150 0 760, at (270, 15, 680). The
// gantry's tool centre point is (500 + X/10, 200 - Y/10, 400 + Z/10):
// MOVETO -2800 2800 1500 0 puts it at block 1's centre, the close takes
// the block, and MOVE 0 0 -1000 0 lifts it 100, the block's centre with it
// to (220, 150, 680), its AT corner to (200, 130, 700). Times: 2.8 s (X,
// Z 2800 at 1000/s, Y 1500 at 800/s: 1.875 s), + 0.5 s (A 100 at 200/s),
// + 1.25 s (Y 1000 at 800/s) = 4.55 s.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>

#include "tests/cli/cli_support.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

const char* const kCentreLift =
    "MOVETO -2800 2800 1500 0\n"
    "MOVE 0 0 0 100\n"
    "MOVE 0 0 -1000 0\n"
    "END\n";

}  // namespace

TEST_CASE("robotsim test: object N centre at X Y Z, and failures that name the object", "[testrun][cli][centre]") {
  const TempDir dir;
  const std::string program = dir.write("c.rsp",
                                        std::string("; test: cell gantry-cell\n"
                                                    "; expect: object 2 centre at 220 150 680 within 0.001\n"
                                                    "; expect: object block centre at 300 50 680 within 0.001\n"
                                                    "; expect: object 1 centre at 270 15 680 within 0.001\n"
                                                    "; expect: object 3 centre at 300 150 680\n"
                                                    "; expect: object 2 at 220 150 680\n"
                                                    "; expect: object 3 held\n"
                                                    "; expect: object block centre at 0 0 0\n") +
                                            kCentreLift);
  const CliResult r = runCli({"test", program, "--collisions=off"});  // the fingers graze the pallet
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  // Lines 2 to 4 hold: the centres worked out above.
  CHECK(r.out.find(":2:3:") == std::string::npos);
  CHECK(r.out.find(":3:3:") == std::string::npos);
  CHECK(r.out.find(":4:3:") == std::string::npos);
  CHECK(r.out.find(program + ":5:3: error: expected object 3 (block) centre at (300.00, 150.00, 680.00) within 0.5 at "
                             "the end; its centre is at (300.00, 50.00, 680.00) (the run ended at line 12, 4.550 s)\n") !=
        std::string::npos);
  CHECK(r.out.find(program + ":6:3: error: expected object 2 (block) at (220.00, 150.00, 680.00) within 0.5 at the "
                             "end; it is at (200.00, 130.00, 700.00)") != std::string::npos);
  CHECK(r.out.find(program + ":7:3: error: expected object 3 (block) held at the end; it is not held") !=
        std::string::npos);
  CHECK(r.out.find(program + ":8:3: error: expected objects 2, 3 (block) centre at (0.00, 0.00, 0.00) within 0.5 at "
                             "the end; their centres are at (220.00, 150.00, 680.00), (300.00, 50.00, 680.00)") !=
        std::string::npos);
}

TEST_CASE("robotsim test: a malformed centre expectation is an error at its line", "[testrun][cli][centre]") {
  const TempDir dir;
  const std::string program =
      dir.write("m.rsp", "; test: cell gantry-cell\n; expect: object 2 centre 220 50 680\nEND\n");
  const CliResult r = runCli({"test", program});
  INFO(r.out << r.err);
  CHECK(r.code != 0);
  CHECK(r.out.find("expected 'at', got '220'") != std::string::npos);
}

TEST_CASE("robotsim run: the summary shows each object's centre beside its AT corner", "[cli][centre]") {
  const TempDir dir;
  const std::string program = dir.write("lift.rsp", kCentreLift);
  const CliResult text = runCli({"run", program, "--cell", "gantry-cell", "--collisions=off"});
  INFO(text.out << text.err);
  CHECK(text.code == 0);
  CHECK(text.out.find("  object 1        pallet at (150, 0, 760), centre (270, 15, 680)\n") != std::string::npos);
  CHECK(text.out.find("  object 2        block at (200, 130, 700), centre (220, 150, 680), held\n") != std::string::npos);
  CHECK(text.out.find("  object 3        block at (280, 30, 700), centre (300, 50, 680)\n") != std::string::npos);
  const CliResult json = runCli({"run", program, "--cell", "gantry-cell", "--collisions=off", "--format=json"});
  CHECK(json.code == 0);
  const nlohmann::json j = nlohmann::json::parse(json.out);
  REQUIRE(j.at("objects").size() == 4);
  CHECK(j["objects"][1]["centre"] == nlohmann::json::array({220, 150, 680}));
  CHECK(j["objects"][1]["at"] == nlohmann::json::array({200, 130, 700}));
  CHECK(j["objects"][0]["centre"] == nlohmann::json::array({270, 15, 680}));
  CHECK(j["objects"][3]["centre"] == nlohmann::json::array({730, 15, 180}));  // pallet 2 AT 610 0 260
}
