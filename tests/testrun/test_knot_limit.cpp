// The knot limit (vm::RunLimits::maxKnots): a straight line is one
// instruction and hundreds of small moves, so a run's work is bounded by
// the knots it makes, not only by its instructions and its simulated time.
// The run stops right after the line that takes the count past the limit,
// with the knot limit as its reason; grading (`robotsim test --spec`) sets
// one of its own, so that a submission that loops over straight lines on a
// cell whose motors make a line take no time is stopped after 200,000
// knots, not a million lines.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "../render/render_test_util.h"
#include "model/workcell/line_path.h"
#include "runtime/run/run.h"
#include "tests/cli/cli_support.h"
#include "tools/testrun/test_file.h"

namespace {

using rs::testing::CliResult;
using rs::testing::runCli;
using rs::testing::TempDir;

// The knots of each of the loop's two lines, planned here.
std::pair<std::size_t, std::size_t> loopKnots(const rs::workcell::Workcell& cell, const rs::vm::Image& image) {
  const rs::workcell::LinePlanner planner(cell.robots.front());
  rs::workcell::LinePath path(planner);
  REQUIRE(image.points.size() == 2);
  REQUIRE_FALSE(planner.planTo(image.points[0].values, image.points[1].values, path));
  const std::size_t down = path.size();
  REQUIRE_FALSE(planner.planTo(image.points[1].values, image.points[0].values, path));
  return {down, path.size()};
}

// The stdlib gantry with every joint at 1,000,000,000 counts a second: a
// line takes a few microseconds, so the 120 s grading limit never comes.
std::string fastGantry() {
  std::ifstream in(rendertest::kSourceDir + "/stdlib/robots/gantry.rsd");
  std::stringstream text;
  text << in.rdbuf();
  std::string rsd = std::regex_replace(text.str(), std::regex("(JOINT [^\\n]*SPEED )[0-9]+"), "$011000000000");
  rsd = std::regex_replace(rsd, std::regex("ROBOT gantry\\n"), "ROBOT fast-gantry\n");
  REQUIRE(rsd.find("SPEED 1000000000") != std::string::npos);
  return rsd + "WORKCELL fast-cell\n  ROBOT fast-gantry AT 0 1000 0\nEND\n";
}

std::uint64_t knotsMade(const std::string& out) {
  std::smatch m;
  REQUIRE(std::regex_search(out, m, std::regex("knot limit of [0-9]+ straight-line moves passed \\(([0-9]+) made\\)")));
  return std::stoull(m[1]);
}

}  // namespace

TEST_CASE("a run stops after the straight line that takes its knots past the limit", "[runtime][straight][limits]") {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const rs::vm::Image image = rendertest::compileText(
      "        MOVEP ABOVE\nloop:   MOVES GRASP\n        MOVES ABOVE\n        GOTO loop\nPOINTS\n"
      "ABOVE AT 240 870 -40 APPROACH 0 -1 0\nGRASP AT 240 810 -40 APPROACH 0 -1 0\n",
      cell);
  const auto [down, up] = loopKnots(cell, image);
  REQUIRE(down > 2);
  REQUIRE(up > 2);
  // Five rounds and half the next line: the sixth line down passes it.
  const std::uint64_t limit = 5 * (down + up) + down / 2;
  rs::runtime::RunSpec spec;
  spec.image = std::make_shared<const rs::vm::Image>(image);
  spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  spec.limits.maxKnots = limit;
  rs::runtime::Run run(spec);
  const rs::vm::RunOutcome outcome = run.runToEnd();
  CHECK(outcome.reason == rs::vm::StopReason::KnotLimit);
  CHECK(rs::vm::isLimit(outcome.reason));
  CHECK(outcome.index == 1);  // the MOVES GRASP
  CHECK(run.knots() == 6 * down + 5 * up);
  CHECK(outcome.message == fmt::format("knot limit of {} straight-line moves passed ({} made)", limit,
                                       6 * down + 5 * up));
  CHECK(outcome.steps == 1 + 6 + 5 + 5);  // MOVEP, six lines down, five up, five GOTOs
  // Exactly at a line's end is not past it: the run goes on to the next line.
  spec.limits.maxKnots = 5 * (down + up);
  rs::runtime::Run exact(spec);
  CHECK(exact.runToEnd().reason == rs::vm::StopReason::KnotLimit);
  CHECK(exact.knots() == 6 * down + 5 * up);
}

TEST_CASE("grading stops a submission of straight lines on fast motors at 200,000 knots, and says how to raise it",
          "[testrun][limits][cli]") {
  const TempDir dir;
  const std::string spec = dir.write("assignment.rstest", "scenario it ends\nexpect: finished\n");
  const std::string raised =
      dir.write("raised.rstest", "scenario it ends\ntest: max-knots 5000\nexpect: finished\n");
  std::filesystem::create_directories(dir.path() / "s");
  dir.write("s/fast.rsd", fastGantry());
  dir.write("s/forever.rsp",
            "; cell: fast.rsd\nloop:   MOVES A\n        MOVES B\n        GOTO loop\nPOINTS\nA 0 0 0 0\nB 3000 3000 0 0\n");
  const CliResult r = runCli({"test", "--spec", spec, (dir.path() / "s").string()});
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK(r.out.find("FAILED") != std::string::npos);
  CHECK(r.out.find("it ended: knot limit at line") != std::string::npos);
  CHECK(r.out.find("hint: grading stops a run after 200000 knots of straight lines") != std::string::npos);
  // The work done: the limit and at most the line that passed it (a
  // diagonal of 300 by 300 on the gantry: a few hundred knots).
  const std::uint64_t made = knotsMade(r.out);
  CHECK(made > rs::testrun::kGradingMaxKnots);
  CHECK(made <= rs::testrun::kGradingMaxKnots + 1000);
  // A scenario that sets its own: that one, and no grading hint.
  const CliResult own = runCli({"test", "--spec", raised, (dir.path() / "s").string()});
  INFO(own.out);
  CHECK(own.out.find("knot limit of 5000 straight-line moves passed") != std::string::npos);
  CHECK(own.out.find("grading stops a run after") == std::string::npos);
  CHECK(knotsMade(own.out) <= 5000 + 1000);
}
