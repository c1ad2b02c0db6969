// The comma-separated number lists of where's --theta/--encoders and ik's
// --approach/--normal/--from (cli/lib/number_list.h).
#include <catch2/catch.hpp>
#include <sstream>

#include "cli/lib/number_list.h"
#include "tests/cli/cli_support.h"

using rs::cli::parseNumberList;
using rs::testing::runCli;

TEST_CASE("a number list reads signed decimals separated by commas", "[cli][numbers]") {
  std::vector<double> v{9.0};  // cleared first
  std::ostringstream err;
  REQUIRE(parseNumberList("76,+72.5,-90", "--theta", v, err));
  CHECK(v == std::vector<double>{76.0, 72.5, -90.0});
  CHECK(err.str().empty());
}

TEST_CASE("a number list names the option, the item and its text when one is no number", "[cli][numbers]") {
  std::vector<double> v;
  std::ostringstream err;
  CHECK_FALSE(parseNumberList("1,,3", "--encoders", v, err));
  CHECK(err.str() == "robotsim: error: --encoders: value 2 '' is not a number\n");
  err.str("");
  CHECK_FALSE(parseNumberList("1,2,inf", "--theta", v, err));
  CHECK(err.str() == "robotsim: error: --theta: value 3 'inf' is not a number\n");
  err.str("");
  CHECK_FALSE(parseNumberList("1 ", "--from", v, err));
  CHECK(err.str() == "robotsim: error: --from: value 1 '1 ' is not a number\n");
}

TEST_CASE("where reports a bad --theta item without printing its control characters", "[cli][numbers]") {
  const auto r = runCli({"where", "puma560", "--theta", "0,\x1b[2J,0,0,0,0"});
  CHECK(r.code == 2);
  CHECK(r.err.find("--theta: value 2 '") != std::string::npos);
  CHECK(r.err.find('\x1b') == std::string::npos);
}
