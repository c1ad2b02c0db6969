// The input changes still to come in a run, in the order they take effect:
// by time, and at equal times the timed stimuli first (in file order), then
// the changes reactive rules scheduled (in the order the rules fired).
//
// The timed changes are fixed when the run starts and shared (a snapshot
// keeps only a cursor into them); the reactive ones are few in any sane
// run but unbounded in a program that switches an output faster than a
// rule's delay, so they live in an ordered set (logarithmic inserts) of at
// most kMaxPendingReactive entries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <vector>

#include "compiler/stimuli/stimuli.h"
#include "runtime/cell/input_cause.h"
#include "vm/io_lines.h"

namespace rs::runtime {

/// Reactive changes that may wait to happen at once; one more is a runtime
/// error (docs/stimuli.md).
inline constexpr std::size_t kMaxPendingReactive = 100'000;

class InputSchedule {
 public:
  /// Starts with the timed changes (those naming an input outside
  /// 1..vm::kIoCount are dropped).
  explicit InputSchedule(std::span<const stimuli::InputChange> timed);

  /// Adds a change after every pending one due at the same time, made by
  /// `cause` (a rule of `change.line`, or the debugger's set). Callers
  /// never schedule before the time they last applied. False (and nothing
  /// added) when kMaxPendingReactive changes already wait.
  bool schedule(const stimuli::InputChange& change, InputCause::Kind cause = InputCause::Kind::Rule);

  /// Applies, in order, every pending change due at or before `t` to the
  /// input mask `inputs` (bit 0 = input 1) and forgets it. `onChange`, when
  /// given, hears each change that altered the mask: (time, mask after,
  /// the change's cause).
  template <typename OnChange>
  void applyUntil(vm::Micros t, vm::IoMask& inputs, OnChange&& onChange);
  void applyUntil(vm::Micros t, vm::IoMask& inputs) {
    applyUntil(t, inputs, [](vm::Micros, vm::IoMask, const InputCause&) {});
  }

  /// The earliest pending time after whose changes `input` reads `on`,
  /// starting from the mask `inputs`; nullopt when no pending change does it.
  /// A pulse that starts and ends at the same time is never seen.
  std::optional<vm::Micros> whenReads(int input, bool on, vm::IoMask inputs) const;

  /// True when some pending change names `input`.
  bool hasPendingFor(int input) const;
  std::size_t pendingReactive() const { return reactive_.size(); }

  /// What changes during a run: a snapshot is a cursor and the (few)
  /// reactive changes that wait.
  struct State {
    std::size_t nextTimed = 0;
    std::uint64_t nextSeq = 0;
    struct Pending {
      vm::Micros at;
      std::uint64_t seq;  // scheduling order, for ties
      int input;
      bool on;
      std::uint32_t line = 0;  // the rule's line in the stimuli file
      bool set = false;        // the debugger's set, not a rule
      bool operator<(const Pending& o) const { return at != o.at ? at < o.at : seq < o.seq; }
      bool operator==(const Pending&) const = default;
    };
    std::set<Pending> reactive;
    bool operator==(const State&) const = default;
  };
  State state() const { return {nextTimed_, nextSeq_, reactive_}; }
  void restore(const State& s) { nextTimed_ = s.nextTimed, nextSeq_ = s.nextSeq, reactive_ = s.reactive; }

 private:
  using Pending = State::Pending;
  // The next change in effect order: a timed one wins a tie.
  const stimuli::InputChange* nextTimed() const { return nextTimed_ < timed_->size() ? &(*timed_)[nextTimed_] : nullptr; }
  template <typename Visit>
  void forEachPending(Visit&& visit) const;

  std::shared_ptr<const std::vector<stimuli::InputChange>> timed_;  // sorted by time, stable
  std::size_t nextTimed_ = 0;
  std::uint64_t nextSeq_ = 0;
  std::set<Pending> reactive_;
};

// The masks' helpers live in vm/io_lines.h; the front ends still name
// them here (runtime::lineBit) until they move (issue 33).
using vm::lineBit;
using vm::withLine;

template <typename OnChange>
void InputSchedule::applyUntil(vm::Micros t, vm::IoMask& inputs, OnChange&& onChange) {
  while (true) {
    const stimuli::InputChange* timed = nextTimed();
    const bool timedDue = timed && timed->at <= t;
    const bool reactiveDue = !reactive_.empty() && reactive_.begin()->at <= t;
    if (!timedDue && !reactiveDue) return;
    vm::Micros at;
    vm::IoMask after;
    InputCause cause;
    if (timedDue && (!reactiveDue || timed->at <= reactive_.begin()->at)) {
      at = timed->at, after = withLine(inputs, timed->input, timed->on);
      cause.kind = timed->bySession ? InputCause::Kind::Set : InputCause::Kind::Stimulus;
      cause.input = timed->input, cause.on = timed->on, cause.line = timed->line;
      ++nextTimed_;
    } else {
      const Pending& p = *reactive_.begin();
      at = p.at, after = withLine(inputs, p.input, p.on);
      cause.kind = p.set ? InputCause::Kind::Set : InputCause::Kind::Rule;
      cause.input = p.input, cause.on = p.on, cause.line = p.line;
      reactive_.erase(reactive_.begin());
    }
    if (after != inputs) {
      inputs = after;
      onChange(at, inputs, cause);
    }
  }
}

}  // namespace rs::runtime
