// The animation page's frames: a run's log cut down to what a screen can
// show, every event kept (docs/render.md, "Frames").
//
// Why: the page embeds every step it can show. A run of a million steps
// made a 43.7 MB page (397 MB of memory to write it) although no screen
// shows a million moments of one run: playback at 60 frames a second
// shows at most 600 moments of a simulated second (at the slowest speed,
// 0.1x), and no scrub bar has 20,000 pixels. So a long run keeps, as
// frames: every event (an output change, a VIEW or WINDOW, a take or
// let-go, any move of the gripper, a collision, the first and the last
// step), every step that lasts at least one slot (a long move stays exact,
// any instant of it), and the first step to start in each slot. The
// motors' moves of the steps left out become one jump each to where they
// got, at the next frame, so that the page shows every motor where it was
// at the start and the end of every frame. A straight line's knots, which
// may be thousands in one step, are merged within slots too, in every
// page: a motor has at most about three moves a slot in a line.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "runtime/run/run_log.h"

namespace rs::render {

struct FrameRule {
  std::size_t keepAll = 20'000;  ///< a run of at most this many steps keeps every step
  vm::Micros minSlot = 1'667;    ///< the shortest slot: 1/600 s, a 60 Hz frame at 0.1x
  std::size_t slots = 20'000;    ///< at most this many slots over the run's time
};

struct Frames {
  /// The frames as a log: `steps` are the steps kept, in order, and every
  /// list that names steps is renumbered to them; a motor's jump (start ==
  /// end, 1 µs before its frame) stands for the moves of the steps left
  /// out before that frame. Inputs are as they were; variables are left
  /// out (the page never shows them).
  runtime::RunLog log;
  std::vector<std::uint32_t> stepOf;  ///< the run's step of each frame
  std::size_t runSteps = 0;           ///< the steps of the run
  vm::Micros slot = 0;                ///< the slot's length; 0 when every step is kept
  /// The slot straight lines' knots are merged within (runtime::thinLineMoves),
  /// whether or not every step is kept: the slot the steps would be cut to.
  vm::Micros lineSlot = 0;
  bool decimated() const { return slot != 0; }
};

/// The frames of `log` by `rule`; `eventSteps` (steps of `log`, in any
/// order) are events besides those the log itself names.
Frames framesOf(const runtime::RunLog& log, std::span<const std::uint32_t> eventSteps, const FrameRule& rule = {});

}  // namespace rs::render
