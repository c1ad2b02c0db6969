#include "runtime/run/profile.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "vm/io_lines.h"

namespace rs::runtime {
namespace {

enum class Kind : std::uint8_t { Moving, Waiting, Gripper, Other };

void add(TimeSplit& split, Kind kind, vm::Micros t) {
  switch (kind) {
    case Kind::Moving: split.moving += t; break;
    case Kind::Waiting: split.waiting += t; break;
    case Kind::Gripper: split.gripper += t; break;
    case Kind::Other: split.other += t; break;
  }
}

// The label at instruction `index`, or null.
const vm::Label* labelAt(const vm::Image& image, std::uint32_t index) {
  auto it = std::lower_bound(image.labels.begin(), image.labels.end(), index,
                             [](const vm::Label& l, std::uint32_t i) { return l.index < i; });
  return it != image.labels.end() && it->index == index ? &*it : nullptr;
}

// The moves step `step` started, motor by motor: a cursor per motor walks
// each motor's list once over the whole run.
class MoveCursor {
 public:
  explicit MoveCursor(const RunLog& log) : log_(log), next_(log.moves.size(), 0) {}
  /// Calls f(motor, move) for each move of step `step` (steps asked in order).
  template <typename F>
  void each(std::uint32_t step, F&& f) {
    for (std::size_t m = 0; m < next_.size(); ++m) {
      const std::vector<MotorMove>& list = log_.moves[m];
      while (next_[m] < list.size() && list[next_[m]].step < step) ++next_[m];
      for (std::size_t i = next_[m]; i < list.size() && list[i].step == step; ++i) f(m, list[i]);
    }
  }

 private:
  const RunLog& log_;
  std::vector<std::size_t> next_;
};

// The subroutines being run (GOSUB targets), with how deep each is: a
// moment inside a recursive call counts once for it.
class CallStack {
 public:
  void push(std::size_t routine) {
    stack_.push_back(routine);
    if (depth_[routine]++ == 0) active_.push_back(routine);
  }
  void pop() {
    if (stack_.empty()) return;
    const std::size_t routine = stack_.back();
    stack_.pop_back();
    if (--depth_[routine] == 0) active_.erase(std::find(active_.begin(), active_.end(), routine));
  }
  const std::vector<std::size_t>& active() const { return active_; }

 private:
  std::vector<std::size_t> stack_, active_;
  std::map<std::size_t, int> depth_;
};

// Keeps the `count` longest moves, longest first, the earlier of two equal
// ones first: a few entries, whatever the length of the run.
void keepSlowest(std::vector<SlowMove>& slowest, std::size_t count, const SlowMove& move) {
  auto at = std::upper_bound(slowest.begin(), slowest.end(), move.duration,
                             [](vm::Micros d, const SlowMove& m) { return d > m.duration; });
  if (static_cast<std::size_t>(at - slowest.begin()) >= count) return;
  slowest.insert(at, move);
  if (slowest.size() > count) slowest.pop_back();
}

// What ended WAITFOR step `s` on input `input` (to `on`): the last change
// of that input to that state the log gives the step. `changes` walks the
// log's input changes once over the run (they are in step order).
class WaitDriver {
 public:
  explicit WaitDriver(const RunLog& log) : log_(log) {}
  std::string of(std::uint32_t s, int input, bool on) {
    const std::vector<InputRecord>& all = log_.inputChanges;
    while (next_ < all.size() && all[next_].step < s) ++next_;
    const InputCause* found = nullptr;
    for (std::size_t i = next_; i < all.size() && all[i].step == s; ++i)
      if (all[i].cause.input == input && all[i].cause.on == on) found = &all[i].cause;
    if (found) {
      InputCause grouped = *found;
      grouped.line = 0;  // every stimulus (every rule) together, whatever its line
      return inputCauseText(grouped);
    }
    // Nothing changed it: it was so already, or the run stopped in the wait.
    const vm::Micros start = log_.steps[s].start;
    const auto level = std::upper_bound(log_.inputs.begin(), log_.inputs.end(), start,
                                        [](vm::Micros t, const InputLevel& l) { return t < l.at; });
    const bool was = level != log_.inputs.begin() && vm::lineIsOn((level - 1)->inputs, input);
    if (was == on) return on ? "already ON" : "already OFF";
    return "nothing (the run stopped waiting)";
  }

 private:
  const RunLog& log_;
  std::size_t next_ = 0;
};

}  // namespace

Profile profileOf(const vm::Image& image, const RunLog& log, std::size_t slowestCount) {
  Profile p;
  std::map<std::uint32_t, LineTime> lines;
  std::map<std::uint32_t, NamedTime> labels;       // by the region's first instruction
  std::map<std::uint32_t, NamedTime> subroutines;  // by the GOSUB target
  std::vector<std::uint32_t> routineTarget;        // CallStack id -> target
  std::map<std::uint32_t, std::size_t> routineId;
  CallStack calls;
  MoveCursor cursor(log);
  WaitDriver driver(log);
  std::map<std::pair<int, std::string>, InputWait> waits;
  const auto nameAt = [&](std::uint32_t index) {
    const vm::Label* l = labelAt(image, index);
    return l ? std::string(image.labelName(*l)) : "instruction " + std::to_string(index + 1);
  };

  for (std::size_t s = 0; s < log.steps.size(); ++s) {
    const StepRecord& step = log.steps[s];
    const vm::Instr& in = image.code[step.index];
    const vm::Micros t = step.end - step.start;
    Kind kind = Kind::Other;
    if (vm::has(in.op, vm::kWaits)) kind = Kind::Waiting;
    if (vm::has(in.op, vm::kMovesMotors)) {
      bool arm = false, any = false;
      const MotorMove* last = nullptr;
      std::size_t lastMotor = 0;
      cursor.each(static_cast<std::uint32_t>(s), [&](std::size_t m, const MotorMove& mv) {
        if (mv.from == mv.to) return;
        any = true;
        arm = arm || log.motors[m].kind != vm::JointKind::Gripper;
        if (!last || mv.end > last->end) last = &mv, lastMotor = m;
      });
      kind = any && !arm ? Kind::Gripper : Kind::Moving;
      if (any) ++p.moves;
      if (last && t > 0) keepSlowest(p.slowest, slowestCount,
                                     {static_cast<std::uint32_t>(s), step.index, image.lines[step.index], step.start, t,
                                      log.motors[lastMotor].letter, last->from, last->to});
    }
    add(p.total, kind, t);
    if (vm::has(in.op, vm::kWaits) && vm::info(in.op).format == vm::Format::Input) {  // WAITFOR: a=input, b=state
      const int input = in.a;
      const std::string by = driver.of(static_cast<std::uint32_t>(s), input, in.b != 0);
      InputWait& w = waits[{input, by}];
      w.input = input, w.driver = by, ++w.waits, w.time += t;
    }

    LineTime& line = lines[image.lines[step.index]];
    line.line = image.lines[step.index], ++line.steps, add(line.time, kind, t);

    // The label region: the last label at or before the instruction.
    auto above = std::upper_bound(image.labels.begin(), image.labels.end(), step.index,
                                  [](std::uint32_t i, const vm::Label& l) { return i < l.index; });
    const std::uint32_t first = above == image.labels.begin() ? 0 : (above - 1)->index;
    NamedTime& region = labels[first];
    if (region.count++ == 0) {
      region.name = above == image.labels.begin() ? "(start)" : std::string(image.labelName(*(above - 1)));
      region.line = image.lines[first];
    }
    add(region.time, kind, t);

    for (std::size_t routine : calls.active()) add(subroutines[routineTarget[routine]].time, kind, t);
    // A GOSUB that went through (the next step is its target) enters the
    // subroutine; a RETURN leaves the innermost one.
    if (vm::has(in.op, vm::kCalls) && s + 1 < log.steps.size() &&
        log.steps[s + 1].index == static_cast<std::uint32_t>(in.d)) {
      const auto target = static_cast<std::uint32_t>(in.d);
      auto [it, fresh] = routineId.try_emplace(target, routineTarget.size());
      if (fresh) routineTarget.push_back(target);
      NamedTime& routine = subroutines[target];
      if (routine.count++ == 0) routine.name = nameAt(target), routine.line = image.lines[target];
      calls.push(it->second);
    } else if (vm::has(in.op, vm::kReturns)) {
      calls.pop();
    }
  }

  for (auto& [_, l] : lines) p.lines.push_back(l);
  for (auto& [_, l] : labels) p.labels.push_back(std::move(l));
  for (auto& [_, r] : subroutines) p.subroutines.push_back(std::move(r));
  for (auto& [_, w] : waits) p.inputWaits.push_back(std::move(w));
  return p;
}

}  // namespace rs::runtime
