#include "runtime/input_schedule.h"

#include <algorithm>

namespace rs::runtime {
namespace {

bool earlier(const InputChange& a, const InputChange& b) { return a.at < b.at; }

void applyChange(const InputChange& change, std::uint8_t& inputs) {
  const auto bit = lineBit(change.input);
  inputs = change.on ? static_cast<std::uint8_t>(inputs | bit)
                     : static_cast<std::uint8_t>(inputs & ~bit);
}

}  // namespace

InputSchedule::InputSchedule(std::span<const InputChange> timed, std::size_t room) {
  pending_.reserve(timed.size() + room);
  for (const auto& change : timed)
    if (lineBit(change.input) != 0) pending_.push_back(change);
  // Stable: equal times keep file order.
  std::stable_sort(pending_.begin(), pending_.end(), earlier);
}

void InputSchedule::schedule(const InputChange& change) {
  if (lineBit(change.input) == 0) return;
  if (pending_.size() == pending_.capacity()) dropApplied();
  // upper_bound: after every change already due at the same time.
  const auto at = std::upper_bound(pending_.begin() + static_cast<std::ptrdiff_t>(next_),
                                   pending_.end(), change, earlier);
  pending_.insert(at, change);
}

void InputSchedule::applyUntil(vm::Micros t, std::uint8_t& inputs) {
  while (next_ < pending_.size() && pending_[next_].at <= t) applyChange(pending_[next_++], inputs);
}

std::optional<vm::Micros> InputSchedule::whenReads(int input, bool on, std::uint8_t inputs) const {
  bool reads = (inputs & lineBit(input)) != 0;
  for (std::size_t i = next_; i < pending_.size(); ++i) {
    if (pending_[i].input == input) reads = pending_[i].on;
    const bool lastAtThisTime = i + 1 == pending_.size() || pending_[i + 1].at != pending_[i].at;
    if (lastAtThisTime && reads == on) return pending_[i].at;
  }
  return std::nullopt;
}

bool InputSchedule::hasPendingFor(int input) const {
  return std::any_of(pending_.begin() + static_cast<std::ptrdiff_t>(next_), pending_.end(),
                     [input](const InputChange& c) { return c.input == input; });
}

// Reuses the room of applied changes before the vector would have to grow.
void InputSchedule::dropApplied() {
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(next_));
  next_ = 0;
}

}  // namespace rs::runtime
