// The debugger counts work, not instructions (tools/debug/timeline.h): a
// straight line is one instruction and hundreds or thousands of small
// moves, so the snapshots come every K = 4,096 instructions or W = 4,096
// knots, whichever is first, and the debug adapter reads what arrives
// between slices of as much. Measured in work, not in time: a reverse step
// on a loop of MOVES re-runs at most W knots and the line that passes
// them (counted by the moves the collision check is asked about, which no
// restore winds back); `pause` on a MOVES loop is answered after a few
// dozen lines, not 4,096; and on a gantry whose every line is 65,536 knots,
// `pause` and `disconnect` are answered after the line under way.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <regex>
#include <sstream>

#include "../render/render_test_util.h"
#include "bench/big_gantry.h"
#include "model/workcell/line_path.h"
#include "tests/cli/cli_support.h"
#include "tools/dap/serve.h"
#include "tools/debug/debug_session.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace {

using rs::wire::Json;

// On the XR-4: down to the grasp and back up, forever. Each line is
// planned here (its knots), and the run's spec made for a session.
const std::string kLoop =
    "        MOVEP ABOVE\nloop:   MOVES GRASP\n        MOVES ABOVE\n        GOTO loop\nPOINTS\n"
    "ABOVE AT 240 870 -40 APPROACH 0 -1 0\nGRASP AT 240 810 -40 APPROACH 0 -1 0\n";

struct Loop {
  rs::runtime::RunSpec spec;
  std::size_t longest = 0;  // the knots of the longer line
};

Loop xr4Loop() {
  const rs::workcell::Workcell cell = rendertest::cell("xr4-cell");
  const rs::vm::Image image = rendertest::compileText(kLoop, cell);
  const rs::workcell::LinePlanner planner(cell.robots.front());
  rs::workcell::LinePath path(planner);
  Loop loop;
  REQUIRE_FALSE(planner.planTo(image.points[0].values, image.points[1].values, path));
  loop.longest = path.size();
  REQUIRE_FALSE(planner.planTo(image.points[1].values, image.points[0].values, path));
  loop.longest = std::max(loop.longest, path.size());
  REQUIRE(loop.longest >= 10);
  loop.spec.image = std::make_shared<const rs::vm::Image>(image);
  loop.spec.cell = std::make_shared<const rs::workcell::Workcell>(cell);
  return loop;
}

std::string dapWorkRequest(int seq, const std::string& command, Json arguments) {
  return rs::wire::frameMessage(
      Json{{"seq", seq}, {"type", "request"}, {"command", command}, {"arguments", std::move(arguments)}}.dump());
}

struct WorkServed {
  std::vector<Json> messages;
  int code = -1;
};

WorkServed dapWorkServe(const std::string& bytes) {
  std::istringstream in(bytes);
  std::ostringstream out, log;
  rs::wire::StreamInput input(in);
  rs::wire::StreamOutput output(out);
  WorkServed s;
  s.code = rs::dap::serve(input, output, log);
  for (const rs::wire::Frame& f : rs::wire::parseFrames(out.str())) s.messages.push_back(Json::parse(f.body));
  return s;
}

const Json* dapWorkResponse(const std::vector<Json>& messages, int seq) {
  for (const Json& m : messages)
    if (m.value("type", "") == "response" && m.value("request_seq", -1) == seq) return &m;
  return nullptr;
}

// The Clock scope's "steps" in the response to request `seq`.
std::uint64_t stepsShown(const std::vector<Json>& messages, int seq) {
  const Json* r = dapWorkResponse(messages, seq);
  REQUIRE(r);
  for (const Json& v : r->at("body").at("variables"))
    if (v.at("name") == "steps") return std::stoull(v.at("value").get<std::string>());
  FAIL("no steps in the Clock scope");
  return 0;
}

}  // namespace

TEST_CASE("a reverse step on a loop of MOVES re-runs at most W knots and one line", "[debug][straight]") {
  Loop loop = xr4Loop();
  loop.spec.limits.maxTime = rs::vm::Micros{1'000'000} * 1'000'000;
  rs::debug::DebugSession session(loop.spec);
  const rs::runtime::CollisionWatch* watch = session.run().rig().collisionWatch();
  REQUIRE(watch);
  session.step(3000);  // about 2,000 lines
  REQUIRE(session.view().steps == 3000);
  REQUIRE(session.run().knots() > 20 * rs::debug::kDefaultSnapshotKnots);
  std::uint64_t worst = 0;
  for (int i = 0; i < 25; ++i) {
    const std::uint64_t before = watch->moves();
    const std::uint64_t steps = session.view().steps;
    session.reverseStep();
    CHECK(session.view().steps == steps - 1);
    worst = std::max(worst, watch->moves() - before);
  }
  INFO("the most knots a reverse step re-ran: " << worst);
  // At most W knots from the snapshot, the line that passed them, and the
  // one the step goes back over.
  CHECK(worst <= rs::debug::kDefaultSnapshotKnots + 2 * loop.longest);
  CHECK(session.timeline().snapshotCount() >= 20);
}

TEST_CASE("dap: pause on a loop of MOVES is answered after a slice of W knots, not 4,096 lines",
          "[debug][dap][straight]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("loop.rsp", "; cell: xr4-cell\n" + kLoop);
  const Loop loop = xr4Loop();
  const WorkServed s = dapWorkServe(
      dapWorkRequest(1, "initialize", {{"adapterID", "robotsim"}}) +
      dapWorkRequest(2, "launch", {{"program", program}, {"maxTime", 1000000}}) +
      dapWorkRequest(3, "configurationDone", Json::object()) + dapWorkRequest(4, "pause", {{"threadId", 1}}) +
      dapWorkRequest(5, "variables", {{"variablesReference", 5}}) + dapWorkRequest(6, "disconnect", Json::object()));
  CHECK(s.code == 0);
  bool paused = false;
  for (const Json& m : s.messages)
    if (m.value("event", "") == "stopped") paused = m.at("body").at("reason") == "pause";
  CHECK(paused);
  // Each line is at least loop.longest / 2 knots (the shorter of the two is
  // within a factor of two of the longer here): a slice of W knots is at
  // most this many lines, and a line takes two steps at most.
  const std::uint64_t steps = stepsShown(s.messages, 5);
  CHECK(steps >= 1);
  CHECK(steps <= 2 * (2 * rs::debug::kDefaultSnapshotKnots / loop.longest + 2) + 2);
}

TEST_CASE("dap: pause and disconnect are answered after the 65,536-knot line under way", "[debug][dap][straight][slow]") {
  const rs::testing::TempDir dir;
  dir.write("big.rsd", std::string(rs::bench::kBigGantry));
  const std::string program = dir.write(
      "big.rsp", "; cell: big.rsd\nloop:   MOVETO -7000000\n        MOVES FAR\n        GOTO loop\nPOINTS\nFAR 7000000\n");
  {
    // The line's knots, as the planner makes them.
    rs::compiler::Library library(rs::compiler::librarySearchPath({}));
    const std::optional<rs::workcell::Workcell> cell = library.workcell((dir.path() / "big.rsd").string());
    REQUIRE(cell);
    const rs::workcell::LinePlanner planner(cell->robots.front());
    rs::workcell::LinePath path(planner);
    REQUIRE_FALSE(planner.planTo(std::vector<std::int32_t>{-7'000'000}, std::vector<std::int32_t>{7'000'000}, path));
    REQUIRE(path.size() == 65'536);
  }
  const std::string start = dapWorkRequest(1, "initialize", {{"adapterID", "robotsim"}}) +
                            dapWorkRequest(2, "launch", {{"program", program}, {"maxTime", 1000000}}) +
                            dapWorkRequest(3, "configurationDone", Json::object());
  const WorkServed paused = dapWorkServe(start + dapWorkRequest(4, "pause", {{"threadId", 1}}) +
                                     dapWorkRequest(5, "variables", {{"variablesReference", 5}}) +
                                     dapWorkRequest(6, "disconnect", Json::object()));
  CHECK(paused.code == 0);
  // The first slice: the MOVETO and the line (or the GOTO after it).
  const std::uint64_t steps = stepsShown(paused.messages, 5);
  CHECK(steps >= 2);
  CHECK(steps <= 3);
  const WorkServed gone = dapWorkServe(start + dapWorkRequest(4, "disconnect", Json::object()));
  CHECK(gone.code == 0);
  CHECK(dapWorkResponse(gone.messages, 4));
}
