// The input changes still to come in a run, in the order they take effect:
// by time, and at equal times in the order they were scheduled (the timed
// stimuli first, in file order, then reactive changes as rules fire).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "runtime/stimuli.h"

namespace rs::runtime {

class InputSchedule {
 public:
  /// Starts with the timed changes; `room` more fit without allocating.
  /// Changes naming an input outside 1..8 are dropped.
  InputSchedule(std::span<const InputChange> timed, std::size_t room);

  /// Adds a change after every pending one due at the same time. Callers
  /// never schedule before the time they last applied.
  void schedule(const InputChange& change);

  /// Applies, in order, every pending change due at or before `t` to the
  /// input mask `inputs` (bit 0 = input 1) and forgets it.
  void applyUntil(vm::Micros t, std::uint8_t& inputs);

  /// The earliest pending time after whose changes `input` reads `on`,
  /// starting from the mask `inputs`; nullopt when no pending change does it.
  /// A pulse that starts and ends at the same time is never seen.
  std::optional<vm::Micros> whenReads(int input, bool on, std::uint8_t inputs) const;

  /// True when some pending change names `input`.
  bool hasPendingFor(int input) const;

 private:
  void dropApplied();

  std::vector<InputChange> pending_;  // sorted by time, ties in scheduling order
  std::size_t next_ = 0;              // pending_[0, next_) are already applied
};

/// The bit of line n (1..8) in an input or output mask; 0 outside 1..8.
constexpr std::uint8_t lineBit(int n) {
  return n >= 1 && n <= 8 ? static_cast<std::uint8_t>(1u << (n - 1)) : 0;
}

}  // namespace rs::runtime
