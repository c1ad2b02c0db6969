#include "runtime/render/frames.h"

#include <algorithm>

namespace rs::render {

namespace {

// Steps that are frames whatever the slots say.
std::vector<bool> eventsOf(const runtime::RunLog& log, std::span<const std::uint32_t> eventSteps) {
  const std::size_t n = log.steps.size();
  std::vector<bool> event(n, false);
  const auto mark = [&](std::size_t step) {
    if (step < n) event[step] = true;
  };
  for (const std::uint32_t s : eventSteps) mark(s);
  for (const runtime::OutputChange& o : log.outputs) mark(o.step);
  for (const runtime::CameraChange& c : log.cameras) mark(c.step);
  for (const runtime::GraspRecord& g : log.grasps) mark(g.step);
  for (const runtime::DeviceRecord& d : log.devices) mark(d.step);  // a sensor's edge, a part fed or taken
  for (const runtime::MotionRecord& m : log.motions) mark(m.step);  // a belt starts or stops a part
  for (std::size_t m = 0; m < log.motors.size() && m < log.moves.size(); ++m)
    if (log.motors[m].kind == vm::JointKind::Gripper)  // a close that takes nothing is an event too
      for (const runtime::MotorMove& move : log.moves[m]) mark(move.step);
  mark(0);
  mark(n - 1);
  return event;
}

// Which steps are frames, by the rule's slots.
std::vector<std::uint32_t> keptSteps(const runtime::RunLog& log, const std::vector<bool>& event, vm::Micros slot) {
  std::vector<std::uint32_t> kept;
  vm::Micros lastSlot = -1;
  for (std::size_t i = 0; i < log.steps.size(); ++i) {
    const runtime::StepRecord& s = log.steps[i];
    if (event[i] || s.end - s.start >= slot || s.start / slot != lastSlot) {
      kept.push_back(static_cast<std::uint32_t>(i));
      lastSlot = s.start / slot;
    }
  }
  return kept;
}

// A list of records with a `step`, every one of a kept step: renumbered.
template <typename T>
std::vector<T> renumbered(const std::vector<T>& items, const std::vector<std::uint32_t>& kept) {
  std::vector<T> out;
  out.reserve(items.size());
  for (T item : items) {
    const auto it = std::lower_bound(kept.begin(), kept.end(), item.step);
    if (it == kept.end() || *it != item.step) continue;  // never expected: events are kept
    item.step = static_cast<std::uint32_t>(it - kept.begin());
    out.push_back(item);
  }
  return out;
}

// One motor's moves over the frames: those of kept steps as they were, and
// before a frame a jump to where the moves left out took the motor.
std::vector<runtime::MotorMove> framedMoves(const std::vector<runtime::MotorMove>& moves,
                                            const std::vector<std::uint32_t>& kept,
                                            const std::vector<runtime::StepRecord>& steps) {
  std::vector<runtime::MotorMove> out;
  std::int32_t shown = 0, real = 0;  // where the frames leave the motor, where the run did (both start at 0)
  std::size_t next = 0;
  for (std::uint32_t f = 0; f < kept.size(); ++f) {
    const std::uint32_t step = kept[f];
    for (; next < moves.size() && moves[next].step < step; ++next) real = moves[next].to;  // left out
    if (real != shown) {
      const vm::Micros at = steps[step].start - 1;
      out.push_back({f, shown, real, at, at});
      shown = real;
    }
    for (; next < moves.size() && moves[next].step == step; ++next) {
      runtime::MotorMove m = moves[next];
      m.step = f;
      out.push_back(m);
      shown = real = m.to;
    }
  }
  return out;
}

}  // namespace

Frames framesOf(const runtime::RunLog& log, std::span<const std::uint32_t> eventSteps, const FrameRule& rule) {
  Frames frames;
  frames.runSteps = log.steps.size();
  const auto slots = static_cast<vm::Micros>(std::max<std::size_t>(rule.slots, 1));
  const vm::Micros slot = std::max(rule.minSlot, (log.end + slots - 1) / slots);
  // A straight line's knots, at most about one a slot and motor: no screen
  // shows more of a line, and a loop of lines would otherwise put every
  // knot in the page.
  frames.lineSlot = slot;
  if (log.steps.size() <= rule.keepAll) {
    frames.log = log;
    frames.stepOf.resize(log.steps.size());
    for (std::uint32_t s = 0; s < frames.stepOf.size(); ++s) frames.stepOf[s] = s;
    for (std::vector<runtime::MotorMove>& moves : frames.log.moves) runtime::thinLineMoves(moves, slot);
    return frames;
  }
  frames.slot = slot;
  const std::vector<std::uint32_t> kept = keptSteps(log, eventsOf(log, eventSteps), frames.slot);
  runtime::RunLog& out = frames.log;
  out.motors = log.motors;
  out.steps.reserve(kept.size());
  for (const std::uint32_t s : kept) out.steps.push_back(log.steps[s]);
  for (const std::vector<runtime::MotorMove>& moves : log.moves) {
    out.moves.push_back(framedMoves(moves, kept, log.steps));
    runtime::thinLineMoves(out.moves.back(), slot);
  }
  out.outputs = renumbered(log.outputs, kept);
  out.cameras = renumbered(log.cameras, kept);
  out.grasps = renumbered(log.grasps, kept);
  out.devices = renumbered(log.devices, kept);
  out.motions = renumbered(log.motions, kept);
  out.inputs = log.inputs;
  out.end = log.end;
  frames.stepOf = kept;
  return frames;
}

}  // namespace rs::render
