// The cache of straight-line plans (model/workcell/line_plan_cache.h): a
// plan answered from it is, knot for knot and word for word, the plan made
// afresh; and it never answers a line with another line's plan: not for
// another arm (placed elsewhere, a range changed), nor another start (a
// gripper's count too), nor another end, nor APPRO for DEPART, nor another
// instruction's words. Every plan here is compared with one made by a
// planner without a cache. Then the compiler: a program of 1,000 MOVES
// between two points plans two lines, and says what a compile without a
// shared cache says.
#include <catch2/catch.hpp>

#include <random>

#include "compiler/description/library.h"
#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "model/workcell/line_path.h"
#include "model/workcell/line_plan_cache.h"

namespace {

rs::workcell::PlacedRobot libraryArm(const std::string& name, const Eigen::Isometry3d& at = Eigen::Isometry3d::Identity()) {
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Robot> robot = lib.robot(name);
  REQUIRE(robot);
  REQUIRE(robot->chain);
  return {*robot, at};
}

struct PlanOf {
  std::vector<std::int32_t> knots;
  std::vector<std::uint32_t> leads;
  std::optional<rs::workcell::LineProblem> problem;
};

void requireSame(const PlanOf& a, const PlanOf& b) {
  REQUIRE(a.knots == b.knots);
  REQUIRE(a.leads == b.leads);
  REQUIRE(a.problem.has_value() == b.problem.has_value());
  if (a.problem) {
    CHECK(a.problem->message == b.problem->message);
    CHECK(a.problem->hint == b.problem->hint);
    CHECK(a.problem->code == b.problem->code);
    CHECK(a.problem->fraction == b.problem->fraction);
    CHECK(a.problem->position == b.problem->position);
  }
}

// A line planned by `planner`: to `end`, or (empty end) `distance` along the tool.
PlanOf planned(const rs::workcell::LinePlanner& planner, const std::vector<std::int32_t>& start,
               const std::vector<std::int32_t>& end, double distance = 0, std::string_view what = "MOVES") {
  rs::workcell::LinePath path(planner);
  PlanOf p;
  p.problem = end.empty() ? planner.planAlongTool(start, distance, path, what) : planner.planTo(start, end, path, what);
  for (std::size_t k = 0; k < path.size(); ++k) {
    const auto knot = path.knot(k);
    p.knots.insert(p.knots.end(), knot.begin(), knot.end());
    p.leads.push_back(path.lead(k));
  }
  return p;
}

}  // namespace

TEST_CASE("a plan from the cache is the plan made afresh, problems included", "[kinematics][straight][cache]") {
  for (const std::string name : {"abb-irb120", "rhino-scara", "rhino-xr4", "gantry"}) {
    INFO(name);
    const rs::workcell::PlacedRobot arm = libraryArm(name);
    rs::workcell::LinePlanCache cache;
    const rs::workcell::LinePlanner fresh(arm), cached(arm, &cache);
    const std::size_t motors = fresh.motorCount(), joints = arm.robot.joints.size();
    std::mt19937_64 rng(20261202);
    int problems = 0, lines = 0;
    for (int i = 0; i < 40; ++i) {
      std::vector<std::int32_t> start(motors, 0), end(motors, 0);
      for (std::size_t m = 0; m < joints; ++m) {
        const auto& j = arm.robot.joints[m];
        const double span = j.max - j.min;
        std::uniform_real_distribution<double> at(j.min + 0.1 * span, j.max - 0.1 * span), by(-0.05 * span, 0.05 * span);
        start[m] = static_cast<std::int32_t>(at(rng));
        end[m] = static_cast<std::int32_t>(std::clamp<double>(start[m] + by(rng), j.min, j.max));
      }
      const PlanOf want = planned(fresh, start, end);
      const PlanOf first = planned(cached, start, end);  // planned, and remembered
      const PlanOf again = planned(cached, start, end);  // from the cache
      requireSame(first, want);
      requireSame(again, want);
      (want.problem ? problems : lines)++;
      const PlanOf along = planned(fresh, start, {}, 25, "APPRO");
      requireSame(planned(cached, start, {}, 25, "APPRO"), along);
      requireSame(planned(cached, start, {}, 25, "APPRO"), along);
    }
    CHECK(lines > 0);
    CHECK(cache.hits() == 80);
    CHECK(cache.misses() == 80);
    INFO(problems << " of 40 lines refused");
  }
}

TEST_CASE("the cache never answers a line with another's plan", "[kinematics][straight][cache]") {
  // The IRB 120 from home straight to a pose 300 in front of it.
  const rs::workcell::PlacedRobot home = libraryArm("abb-irb120");
  Eigen::Isometry3d elsewhere = Eigen::Isometry3d::Identity();
  elsewhere.translate(Eigen::Vector3d(0, 750, 0));
  const rs::workcell::PlacedRobot moved = libraryArm("abb-irb120", elsewhere);
  rs::workcell::PlacedRobot narrow = home;
  narrow.robot.joints[1].max = 500;  // motor F may not go as far

  rs::workcell::LinePlanCache cache;
  const rs::workcell::LinePlanner homePlans(home, &cache), movedPlans(moved, &cache), narrowPlans(narrow, &cache);
  const rs::workcell::LinePlanner homeFresh(home), movedFresh(moved), narrowFresh(narrow);
  const std::size_t motors = homeFresh.motorCount();
  std::vector<std::int32_t> start(motors, 0), end(motors, 0);
  start = {0, 1000, 1500, 0, 2000, 0, 0};
  end = {2000, 1800, 2300, 0, 1500, -2000, 0};
  REQUIRE(start.size() == motors);

  const PlanOf atHome = planned(homePlans, start, end);
  REQUIRE_FALSE(atHome.problem);
  REQUIRE(atHome.knots.size() / motors > 10);
  // The same counts on the arm placed 750 higher: its own plan (the same
  // knots, as the arm moves the same, but its problem would name other
  // world coordinates; its narrower twin refuses the line).
  requireSame(planned(movedPlans, start, end), planned(movedFresh, start, end));
  const PlanOf narrowed = planned(narrowPlans, start, end);
  requireSame(narrowed, planned(narrowFresh, start, end));
  REQUIRE(narrowed.problem);
  CHECK(narrowed.problem->code == "line-out-of-range");
  // One count of the gripper more at the start: every knot carries it.
  std::vector<std::int32_t> gripping = start;
  gripping.back() = 30;
  const PlanOf withGrip = planned(homePlans, gripping, end);
  requireSame(withGrip, planned(homeFresh, gripping, end));
  REQUIRE(withGrip.knots.size() == atHome.knots.size());
  CHECK(withGrip.knots[motors - 1] == 30);
  // One count more at the end.
  std::vector<std::int32_t> further = end;
  further[0] += 1;
  const PlanOf longer = planned(homePlans, start, further);
  requireSame(longer, planned(homeFresh, start, further));
  CHECK(longer.knots != atHome.knots);
  // APPRO and DEPART the same distance: opposite ways.
  const PlanOf in = planned(homePlans, start, {}, 40, "APPRO"), out = planned(homePlans, start, {}, -40, "DEPART");
  requireSame(in, planned(homeFresh, start, {}, 40, "APPRO"));
  requireSame(out, planned(homeFresh, start, {}, -40, "DEPART"));
  CHECK(in.knots != out.knots);
  // A refused line in another instruction's words.
  const PlanOf asMoves = planned(narrowPlans, start, end, 0, "MOVES");
  const PlanOf asOther = planned(narrowPlans, start, end, 0, "LINE");
  REQUIRE(asOther.problem);
  CHECK(asOther.problem->message.starts_with("LINE "));
  CHECK(asMoves.problem->message.starts_with("MOVES "));
  // And the first plan is still the first plan.
  requireSame(planned(homePlans, start, end), atHome);
}

TEST_CASE("compiling 1,000 MOVES between two points plans two lines", "[compiler][straight][cache]") {
  // On the XR-4: 1,000 lines between a point over a block and the grasp
  // below it, then the line of tests/runtime/test_straight_line.cpp across
  // the base's axis, which the arm cannot follow.
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  std::optional<rs::workcell::Workcell> cell = lib.workcell("xr4-cell");
  REQUIRE(cell);
  std::string text = "        MOVEP ABOVE\n";
  for (int i = 0; i < 1000; ++i) text += i % 2 ? "        MOVES ABOVE\n" : "        MOVES GRASP\n";
  text += "        MOVEP A\n        MOVES B\n        END\nPOINTS\nABOVE AT 240 870 -40 APPROACH 0 -1 0\n"
          "GRASP AT 240 810 -40 APPROACH 0 -1 0\nA AT 120 950 -120 APPROACH 0 -1 0\nB AT -120 950 120 APPROACH 0 -1 0\n";
  const rs::diag::SourceFile source("moves.rsp", text);
  rs::compiler::Target shared = rs::launch::cellTarget(*cell);
  REQUIRE(shared.linePlans);
  const rs::compiler::CompileResult once = rs::compiler::compile(source, shared);
  CHECK(shared.linePlans->misses() == 3);
  CHECK(shared.linePlans->hits() == 998);
  REQUIRE_FALSE(once.ok());
  REQUIRE(once.diagnostics.size() == 1);
  CHECK(once.diagnostics[0].pos.line == 1003);
  CHECK(once.diagnostics[0].message.find("along the line") != std::string::npos);
  // The same words as a compile with a cache of its own.
  rs::compiler::Target alone = rs::launch::cellTarget(*cell);
  alone.linePlans = nullptr;
  const rs::compiler::CompileResult apart = rs::compiler::compile(source, alone);
  REQUIRE(apart.diagnostics.size() == 1);
  CHECK(once.diagnostics[0].message == apart.diagnostics[0].message);
  CHECK(once.diagnostics[0].hint == apart.diagnostics[0].hint);
  CHECK(once.diagnostics[0].code == apart.diagnostics[0].code);
  // Compiled again with the shared cache: nothing planned.
  const rs::compiler::CompileResult twice = rs::compiler::compile(source, shared);
  CHECK(shared.linePlans->misses() == 3);
  REQUIRE(twice.diagnostics.size() == 1);
  CHECK(twice.diagnostics[0].message == once.diagnostics[0].message);
}
