// The animation page's frames (runtime/render/frames.h): a long run cut down
// to what a screen can show, every event kept, every frame exact.
//
// The run: the gantry of the gantry cell takes block 1 (the pick of
// examples/gantry_pick.rsp), lifts it, jiggles it 600 times along x by one
// count (1 ms a move at 1000 counts/s), switches output 2, turns the view,
// jiggles again, lowers the block 0.5 mm into its pallet (a collision, kept
// going with --collisions=warn) and lets go: some 4,800 steps in about
// 10.7 s, cut down here with a rule of 50 slots.
#include <algorithm>
#include <catch2/catch.hpp>

#include "render_test_util.h"
#include "runtime/render/frames.h"
#include "runtime/run/run_log.h"

using rs::render::FrameRule;
using rs::render::Frames;
using rs::render::framesOf;
using rs::runtime::RunLog;
using rs::runtime::RunState;

namespace {

const char* const kJiggle =
    "        MOVETO -2800 2800 0 0\n"  // over block 1
    "        MOVE 0 0 1490 0\n"        // down
    "        MOVE 0 0 0 100\n"         // close: takes block 1
    "        MOVE 0 0 -1490 0\n"       // up with it
    "one:    MOVE 1 0 0 0\n"
    "        MOVE -1 0 0 0\n"
    "        ADD N 1\n"
    "        JMPVAR N < 600 one\n"
    "        OUTSIG 2 ON\n"
    "        VIEW 10 0 0\n"
    "two:    MOVE 1 0 0 0\n"
    "        MOVE -1 0 0 0\n"
    "        ADD N 1\n"
    "        JMPVAR N < 1200 two\n"
    "        MOVE 0 0 1498 0\n"  // down 149.8 mm: the block 0.8 mm into the pallet's deck, beyond the rest
                                 // tolerance (0.5; its fingers, 1 mm shorter, stay above it)
    "        MOVE 0 0 0 -100\n"  // open: lets go
    "        END\n";

struct Jiggled {
  RunLog log;
  std::vector<std::uint32_t> collisionSteps;
};

Jiggled jiggled() {
  const rs::workcell::Workcell cell = rendertest::cell("gantry-cell");
  const auto run =
      rendertest::runOf(rendertest::compileText(kJiggle, cell), &cell, {}, true, rs::runtime::CollisionMode::Warn);
  REQUIRE(run->runToEnd().ok());
  Jiggled j{*run->log(), {}};
  for (const rs::runtime::CollisionEvent& e : run->rig().collisions())
    for (std::uint32_t s = 0; s < j.log.steps.size(); ++s)
      if (j.log.steps[s].index == e.instruction && j.log.steps[s].start <= e.at && e.at <= j.log.steps[s].end)
        j.collisionSteps.push_back(s);
  return j;
}

void checkSameState(const RunState& frame, const RunState& run) {
  CHECK(frame.encoders == run.encoders);
  CHECK(frame.outputs == run.outputs);
  CHECK(frame.inputs == run.inputs);
  CHECK(frame.view == run.view);
  CHECK(frame.window == run.window);
}

bool isFrame(const Frames& f, std::uint32_t step) { return std::binary_search(f.stepOf.begin(), f.stepOf.end(), step); }

}  // namespace

TEST_CASE("a run of few steps keeps every step as a frame", "[render][frames]") {
  const Jiggled j = jiggled();
  REQUIRE(j.log.steps.size() > 4800);
  const Frames all = framesOf(j.log, j.collisionSteps, FrameRule{1'000'000, 1'667, 20'000});
  CHECK_FALSE(all.decimated());
  CHECK(all.log.steps.size() == j.log.steps.size());
  REQUIRE(all.log.moves.size() == j.log.moves.size());
  for (std::size_t m = 0; m < j.log.moves.size(); ++m) {
    REQUIRE(all.log.moves[m].size() == j.log.moves[m].size());
    for (std::size_t i = 0; i < j.log.moves[m].size(); ++i) {
      const rs::runtime::MotorMove &a = all.log.moves[m][i], &b = j.log.moves[m][i];
      CHECK((a.step == b.step && a.from == b.from && a.to == b.to && a.start == b.start && a.end == b.end));
    }
  }
  CHECK(all.stepOf.back() == j.log.steps.size() - 1);
}

TEST_CASE("a long run is cut down to its slots, keeping every event and exact at every frame", "[render][frames]") {
  const Jiggled j = jiggled();
  const RunLog& log = j.log;
  REQUIRE(j.collisionSteps.size() == 1);  // the block into the pallet
  const FrameRule rule{100, 1'667, 50};
  const Frames f = framesOf(log, j.collisionSteps, rule);
  REQUIRE(f.decimated());
  CHECK(f.runSteps == log.steps.size());
  CHECK(f.slot == (log.end + 49) / 50);  // the run's time over 50 slots: longer than 1/600 s
  // At most one frame for each slot a step starts in, one for each step that
  // lasts a slot or more, and the events: 2 grasps, 2 gripper moves (the
  // same steps), an output, a VIEW, the collision, the first and the last.
  const std::size_t events = 2 + 1 + 1 + 1 + 2;
  CHECK(f.log.steps.size() <= 2 * (rule.slots + 1) + events);
  CHECK(f.log.steps.size() * 20 < log.steps.size());
  CHECK(f.stepOf.size() == f.log.steps.size());
  CHECK(std::is_sorted(f.stepOf.begin(), f.stepOf.end()));

  // Every event is a frame of its own, and the renumbered lists name it.
  for (const auto& o : log.outputs) CHECK(isFrame(f, o.step));
  for (const auto& c : log.cameras) CHECK(isFrame(f, c.step));
  for (const auto& g : log.grasps) CHECK(isFrame(f, g.step));
  for (const auto& m : log.moves[3]) CHECK(isFrame(f, m.step));  // the gripper A
  CHECK(isFrame(f, j.collisionSteps[0]));
  CHECK(f.stepOf.front() == 0);
  CHECK(f.stepOf.back() == log.steps.size() - 1);
  REQUIRE(f.log.outputs.size() == log.outputs.size());
  REQUIRE(f.log.cameras.size() == log.cameras.size());
  REQUIRE(f.log.grasps.size() == log.grasps.size());
  for (std::size_t i = 0; i < log.outputs.size(); ++i) {
    CHECK(f.stepOf[f.log.outputs[i].step] == log.outputs[i].step);
    CHECK(f.log.outputs[i].outputs == log.outputs[i].outputs);
  }
  for (std::size_t i = 0; i < log.grasps.size(); ++i) CHECK(f.stepOf[f.log.grasps[i].step] == log.grasps[i].step);
  CHECK(f.log.inputs.size() == log.inputs.size());
  CHECK(f.log.end == log.end);

  // Each frame is its step: the same instruction and times, and every motor,
  // output and camera where the run had them at its start, in its middle
  // and at its end (a move of a frame is exact at any instant of it).
  std::size_t jumps = 0;
  for (const auto& moves : f.log.moves)
    for (const auto& m : moves) jumps += m.start == m.end;
  CHECK(jumps > 0);  // the jiggles left out come back as jumps
  for (std::size_t k = 0; k < f.log.steps.size(); ++k) {
    const rs::runtime::StepRecord& frame = f.log.steps[k];
    const rs::runtime::StepRecord& step = log.steps[f.stepOf[k]];
    INFO("frame " << k << ", step " << f.stepOf[k]);
    CHECK(frame.index == step.index);
    CHECK(frame.start == step.start);
    CHECK(frame.end == step.end);
    for (const rs::vm::Micros t : {step.start, (step.start + step.end) / 2, step.end})
      checkSameState(rs::runtime::stateAtStep(f.log, k, t), rs::runtime::stateAtStep(log, f.stepOf[k], t));
    checkSameState(rs::runtime::stateAt(f.log, step.start), rs::runtime::stateAt(log, step.start));
  }
}
