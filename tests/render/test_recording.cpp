// RunLog and stateAt: a logged run answers "where was everything at time t"
// exactly as the machine itself would (momentOf a fresh run), inputs
// included, and keeps what the animation shows (steps, outputs, camera).
#include <catch2/catch.hpp>

#include "render_test_util.h"
#include "runtime/render/moment.h"
#include "runtime/run/run_log.h"

using rs::runtime::RunLog;
using rs::vm::Micros;

namespace {

constexpr Micros kSecondUs = 1'000'000;

struct Recorded {
  RunLog rec;
  rs::vm::RunOutcome outcome;
};

Recorded record(const rs::vm::Image& image, const rs::stimuli::Stimuli& stimuli) {
  const auto run = rendertest::runOf(image, nullptr, stimuli, /*log=*/true);
  Recorded r;
  r.outcome = run->runToEnd();
  r.rec = *run->log();
  return r;
}

// Every 37 ms, and at every step boundary: the recording and the machine agree.
void checkAgainstMachine(const rs::vm::Image& image, const rs::stimuli::Stimuli& stimuli) {
  const Recorded r = record(image, stimuli);
  std::vector<Micros> times;
  for (Micros t = 0; t <= r.rec.end + kSecondUs / 10; t += 37'000) times.push_back(t);
  for (const auto& s : r.rec.steps) times.insert(times.end(), {s.start, s.end, s.end - 1, s.end + 1});
  for (const Micros t : times) {
    if (t < 0) continue;
    INFO("t = " << t);
    const rs::runtime::RunState state = rs::runtime::stateAt(r.rec, t);
    const rs::render::Moment m = rs::render::momentOf(*rendertest::runOf(image, nullptr, stimuli), t);
    REQUIRE(m.reached);
    CHECK(state.encoders == m.encoders);
    CHECK(state.view == m.view);
    CHECK(state.window == m.window);
  }
}

}  // namespace

TEST_CASE("A recorded run agrees with the machine at every moment", "[render]") {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  for (const char* example : {"workcell_view.rsp", "first_moves.rsp", "counted_loop.rsp", "soft_home.rsp"}) {
    INFO(example);
    checkAgainstMachine(rendertest::compile(rendertest::kSourceDir + "/examples/" + example, cell), {});
  }
}

TEST_CASE("VIEW, WINDOW, outputs and RESET are recorded at their steps", "[render]") {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  const rs::vm::Image image = rendertest::compileText(
      "VIEW 10 0 0\nMOVETO 400 0 0 0 0\nOUTSIG 2 ON\nWINDOW 0 5 0\nRESET\nDELAY 1\nEND\n", cell);
  const Recorded r = record(image, {});
  REQUIRE(r.outcome.ok());
  const RunLog& rec = r.rec;
  REQUIRE(rec.steps.size() == 7);
  CHECK(rec.steps[1].start == 0);
  CHECK(rec.steps[1].end == kSecondUs);  // E: 400 units at 400/s
  CHECK(rec.end == 2 * kSecondUs);
  REQUIRE(rec.cameras.size() == 2);
  CHECK(rec.cameras[0].step == 0);
  CHECK(rec.cameras[0].view == rs::runtime::CameraTriple{10, 0, 0});
  CHECK(rec.cameras[1].window == rs::runtime::CameraTriple{0, 5, 0});
  REQUIRE(rec.outputs.size() == 1);
  CHECK(rec.outputs[0].step == 2);
  CHECK(rec.outputs[0].outputs == 0b10);
  // E moved once, then jumped back to 0 at RESET; the others never moved.
  REQUIRE(rec.moves[0].size() == 2);
  CHECK(rec.moves[0][1].step == 4);
  CHECK(rec.moves[0][1].start == rec.moves[0][1].end);
  for (std::size_t m = 1; m < rec.moves.size(); ++m) CHECK(rec.moves[m].empty());
  // Half-way through the move, and at its end (where the instructions that
  // take no time have all run: the state after RESET).
  CHECK(rs::runtime::stateAt(rec, kSecondUs / 2).encoders[0] == 200);
  CHECK(rs::runtime::stateAt(rec, kSecondUs / 2).step == std::optional<std::size_t>(1));
  CHECK(rs::runtime::stateAt(rec, kSecondUs).encoders[0] == 0);
  CHECK(rs::runtime::stateAt(rec, kSecondUs).step == std::optional<std::size_t>(5));
  // Step by step, as the page's buttons do: after OUTSIG, E is still at 400.
  const rs::runtime::RunState afterOut = rs::runtime::stateAtStep(rec, 2, kSecondUs);
  CHECK(afterOut.encoders[0] == 400);
  CHECK(afterOut.outputs == 0b10);
  CHECK(afterOut.window == rs::runtime::CameraTriple{});
}

TEST_CASE("Inputs change at their stimulus times, even inside a DELAY", "[render]") {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  const rs::vm::Image image = rendertest::compileText("OUTSIG 1 ON\nDELAY 5\nOUTSIG 1 OFF\nDELAY 1\nEND\n", cell);
  rs::stimuli::Stimuli stimuli;
  stimuli.changes = {{2 * kSecondUs, 3, true}, {kSecondUs * 7 / 2, 3, false}};
  stimuli.rules = {{1, true, 2, true, kSecondUs * 3 / 2}, {1, false, 2, false, 0}};
  const Recorded r = record(image, stimuli);
  REQUIRE(r.outcome.ok());
  const std::vector<std::pair<Micros, int>> expected = {
      {0, 0}, {kSecondUs * 3 / 2, 0b010}, {2 * kSecondUs, 0b110}, {kSecondUs * 7 / 2, 0b010}, {5 * kSecondUs, 0}};
  REQUIRE(r.rec.inputs.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    CHECK(r.rec.inputs[i].at == expected[i].first);
    CHECK(r.rec.inputs[i].inputs == expected[i].second);
  }
  CHECK(rs::runtime::stateAt(r.rec, 2 * kSecondUs - 1).inputs == 0b010);
  CHECK(rs::runtime::stateAt(r.rec, 2 * kSecondUs).inputs == 0b110);
}

TEST_CASE("The instruction that stops a run is the recording's last step", "[render]") {
  const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
  const rs::vm::Image image = rendertest::compileText("MOVE 100 0 0 0 0\nWAITFOR 4 ON\nEND\n", cell);
  const Recorded r = record(image, {});
  CHECK(r.outcome.reason == rs::vm::StopReason::Deadlock);
  REQUIRE(r.rec.steps.size() == 2);
  CHECK(r.rec.steps.back().index == 1);
  CHECK(r.rec.steps.back().start == r.rec.steps.back().end);
  const rs::render::Moment m = rs::render::momentOf(*rendertest::runOf(image, nullptr), 10 * kSecondUs);
  CHECK_FALSE(m.reached);
}

TEST_CASE("one positionAt for the machine and the recording, segments compared by value", "[render]") {
  const rs::vm::MotorSpec speed3{'A', rs::vm::JointKind::Revolute, 1.0, -100, 100, 3};  // 3 units/s
  const rs::runtime::MotorSegment up{0, 7, 0, 2'333'334};
  CHECK(rs::runtime::positionAt(up, speed3, 999'999) == 2);
  CHECK(rs::runtime::positionAt(rs::runtime::MotorSegment{7, 0, 0, 2'333'334}, speed3, 999'999) == 5);
  CHECK(rs::runtime::positionAt(up, speed3, -5) == 0);
  CHECK(rs::runtime::positionAt(up, speed3, 9'000'000) == 7);
  CHECK(up == rs::runtime::MotorSegment{0, 7, 0, 2'333'334});
  CHECK_FALSE(up == rs::runtime::MotorSegment{0, 7, 0, 2'333'335});
  CHECK_FALSE(up == rs::runtime::MotorSegment{1, 7, 0, 2'333'334});
  // A machine's answer is the free function's on its latest segment.
  rs::runtime::SimMachine machine({{'A', rs::vm::JointKind::Revolute, 1.0, -100, 100, 3}}, {});
  const bool moved = static_cast<bool>(machine.moveTo(std::vector<std::int32_t>{7}));
  REQUIRE(moved);
  for (const Micros t : {Micros{0}, Micros{999'999}, Micros{1'000'000}, Micros{2'333'333}, Micros{5'000'000}})
    CHECK(machine.positionAt(0, t) == rs::runtime::positionAt(machine.segment(0), speed3, t));
}

TEST_CASE("positionAt rounds toward the segment's start, as SimMachine does", "[render]") {
  const rs::vm::MotorSpec speed3{'A', rs::vm::JointKind::Revolute, 1.0, -100, 100, 3};  // 3 units/s
  const rs::runtime::MotorMove up{0, 0, 7, 0, 2'333'334}, down{0, 7, 0, 0, 2'333'334};
  CHECK(rs::runtime::positionAt(up, speed3, 1'000'000) == 3);
  CHECK(rs::runtime::positionAt(up, speed3, 999'999) == 2);
  CHECK(rs::runtime::positionAt(down, speed3, 999'999) == 5);
  CHECK(rs::runtime::positionAt(up, speed3, -5) == 0);
  CHECK(rs::runtime::positionAt(up, speed3, 9'000'000) == 7);
}
