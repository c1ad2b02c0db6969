// Numbers on the command line (tools/cli/lib/number_args.h): one reader, every
// command. Each number is finite, within what it counts and whole where it
// must be; a bad one is refused at its option with a hint, before anything
// is loaded or run.
#include <catch2/catch.hpp>
#include <sstream>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/number_args.h"

using rs::cli::NumberRead;
using rs::cli::parseNumberList;
using rs::cli::readNumber;
namespace numberRules = rs::cli::rules;
using rs::testing::runCli;

TEST_CASE("a number is read by its rule: decimals, signs, exponents, whole numbers exactly", "[cli][numbers]") {
  CHECK(readNumber("76", numberRules::kJointValue).value == 76.0);
  CHECK(readNumber("+72.5", numberRules::kJointValue).canonical == "72.5");
  CHECK(readNumber("-0", numberRules::kJointValue).canonical == "0");  // never "-0"
  CHECK(readNumber("1e3", numberRules::kEncoderCount).canonical == "1000");
  CHECK(readNumber("-2147483648", numberRules::kEncoderCount).canonical == "-2147483648");
  // Past 2^53 a double would change the number: whole numbers are read as integers.
  CHECK(readNumber("4611686018427387903", numberRules::kStepCount).canonical == "4611686018427387903");
  for (const NumberRead& good : {readNumber("1", numberRules::kZoom), readNumber("0.001", numberRules::kZoom)})
    CHECK(good.problem.empty());
}

TEST_CASE("a number that is none, not finite, out of range or not whole is refused with the reason", "[cli][numbers]") {
  CHECK(readNumber("nan", numberRules::kCoordinate).problem == "'nan' is not a number");
  CHECK(readNumber("", numberRules::kCoordinate).problem == "'' is not a number");
  CHECK(readNumber(" 1", numberRules::kCoordinate).problem == "' 1' is not a number");
  CHECK(readNumber("0x10", numberRules::kCoordinate).problem == "'0x10' is not a number");
  CHECK(readNumber("+-1", numberRules::kCoordinate).problem == "'+-1' is not a number");
  CHECK(readNumber("inf", numberRules::kCoordinate).problem ==
        "'inf' is out of range: a coordinate is from -1000000000 to 1000000000");
  CHECK(readNumber("1e308", numberRules::kEncoderCount).problem ==
        "'1e308' is out of range: an encoder count is a whole number from -2147483648 to 2147483647");
  CHECK(readNumber("1e999", numberRules::kCoordinate).problem.starts_with("'1e999' is out of range"));
  CHECK(readNumber("2147483648", numberRules::kEncoderCount).problem.starts_with("'2147483648' is out of range"));
  CHECK(readNumber("4611686018427387905", numberRules::kStepCount).problem.starts_with("'4611686018427387905' is out"));
  CHECK(readNumber("2.5", numberRules::kEncoderCount).problem ==
        "'2.5' is not a whole number (an encoder count is one)");
  CHECK(readNumber("0", numberRules::kZoom).problem == "'0' is out of range: a zoom is above 0 and at most 1000000");
  // What is quoted is printable and short.
  const std::string shown = readNumber(std::string("\x1b[2J") + std::string(1000, '7'), numberRules::kAngle).problem;
  CHECK(shown.find('\x1b') == std::string::npos);
  CHECK(shown.size() < 100);
}

TEST_CASE("a number list names the option, the item and the reason, with a hint", "[cli][numbers]") {
  std::vector<double> v{9.0};  // cleared first
  std::ostringstream err;
  REQUIRE(parseNumberList("76,+72.5,-90", "--theta", numberRules::kJointValue, v, err));
  CHECK(v == std::vector<double>{76.0, 72.5, -90.0});
  CHECK(err.str().empty());
  CHECK_FALSE(parseNumberList("1,,3", "--encoders", numberRules::kEncoderCount, v, err));
  CHECK(err.str() ==
        "--encoders: error: value 2 '' is not a number\n"
        "  hint: encoder counts are whole numbers within each motor's RANGE (robotsim describe CELL lists them)\n");
  err.str("");
  CHECK_FALSE(parseNumberList("1,2,nan", "--theta", numberRules::kJointValue, v, err));
  CHECK(err.str().starts_with("--theta: error: value 3 'nan' is not a number\n  hint: "));
}

// The regressions of issue 26: `ik ... nan` answered "near-singular pose",
// `where --encoders 1e308` printed a 300-digit number.
TEST_CASE("ik refuses a coordinate that is not a number before solving", "[cli][numbers]") {
  const auto r = runCli({"ik", "scara-pick", "nan", "800", "0"});
  CHECK(r.code == 2);
  CHECK(r.err.starts_with("xyz: error: 'nan' is not a number\n  hint: in the workcell's length units"));
  CHECK(r.err.find("singular") == std::string::npos);
  CHECK(
      runCli({"ik", "scara-pick", "--", "-130", "1e300", "0"}).err.starts_with("xyz: error: '1e300' is out of range"));
  CHECK(runCli({"ik", "scara-pick", "-130", "800", "0", "--grip", "1e308"}).err.starts_with("--grip: error: '1e308'"));
  CHECK(runCli({"ik", "scara-pick", "-130", "800", "0", "--approach", "0,0,nan"})
            .err.starts_with("--approach: error: value 3 'nan' is not a number"));
  CHECK(runCli({"ik", "scara-pick", "-130", "800", "0", "--solution", "9"}).err.starts_with("--solution: error: '9'"));
}

TEST_CASE("where and matrix refuse numbers out of range at the option, printing no long number", "[cli][numbers]") {
  const auto r = runCli({"where", "scara-pick", "--encoders", "1e308,0,0,0"});
  CHECK(r.code == 2);
  CHECK(
      r.err.starts_with("--encoders: error: value 1 '1e308' is out of range: an encoder count is a whole number "
                        "from -2147483648 to 2147483647\n  hint: "));
  CHECK(r.err.size() < 400);
  CHECK(r.out.empty());
  CHECK(runCli({"where", "scara-pick", "--encoders", "10.5,0,0,0"})
            .err.starts_with("--encoders: error: value 1 '10.5' is not a whole number"));
  CHECK(runCli({"matrix", "scorobot", "2", "5", "--theta", "76,1e300,-90,34,-49"})
            .err.starts_with("--theta: error: value 2 '1e300' is out of range: a joint value is from"));
  CHECK(runCli({"matrix", "scorobot", "2", "1e10"}).err.starts_with("j: error: '1e10' is out of range"));
  // A range the robot sets is still the command's to check, with its own words.
  CHECK(runCli({"where", "scara-pick", "--encoders", "100000,0,0,0"}).err.find("outside the motor's range") !=
        std::string::npos);
}

TEST_CASE("every command's numbers go through the same reader", "[cli][numbers]") {
  const auto refused = [](const std::vector<std::string>& args, const std::string& start) {
    const auto r = runCli(args);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.starts_with(start));
    CHECK(r.err.find("  hint: ") != std::string::npos);
  };
  refused({"render", "scara-pick", "--zoom", "nan", "--dump-lines"}, "--zoom: error: 'nan' is not a number");
  refused({"render", "scara-pick", "--zoom", "0", "--dump-lines"}, "--zoom: error: '0' is out of range");
  refused({"render", "scara-pick", "--view", "1,2,inf", "--dump-lines"},
          "--view: error: value 3 'inf' is out of range");
  refused({"render", "scara-pick", "--center", "0,nan,0", "--dump-lines"}, "--center: error: value 2 'nan'");
  refused({"render", "scara-pick", "--size", "1e9x10", "--dump-lines"}, "--size: error: '1e9' is out of range");
  refused({"render", "scara-pick", "--program", "x.rsp", "--at", "nan", "--dump-lines"}, "--at: error: bad time 'nan'");
  refused({"animate", "x.rsp", "-o", "x.html", "--window", "1e300,0,0"}, "--window: error: value 1 '1e300'");
  refused({"run", "x.rsp", "--max-steps", "1e30"}, "--max-steps: error: '1e30' is out of range");
  refused({"run", "x.rsp", "--max-steps", "-1"}, "--max-steps: error: '-1' is out of range");
  refused({"check", "x.rsp", "--max-errors", "2.5"}, "--max-errors: error: '2.5' is not a whole number");
  refused({"test", "x.rsp", "--jobs", "nan"}, "--jobs: error: 'nan' is not a number");
  refused({"emulate", "--latency", "nan"}, "--latency: error: 'nan' is not a number");
  refused({"emulate", "--speed", "1e9"}, "--speed: error: '1e9' is out of range");
}
