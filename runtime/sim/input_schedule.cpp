#include "runtime/sim/input_schedule.h"

#include <algorithm>

namespace rs::runtime {

InputSchedule::InputSchedule(std::span<const stimuli::InputChange> timed) {
  auto sorted = std::make_shared<std::vector<stimuli::InputChange>>();
  sorted->reserve(timed.size());
  for (const auto& change : timed)
    if (lineBit(change.input) != 0) sorted->push_back(change);
  // Stable: equal times keep file order.
  std::stable_sort(sorted->begin(), sorted->end(),
                   [](const stimuli::InputChange& a, const stimuli::InputChange& b) { return a.at < b.at; });
  timed_ = std::move(sorted);
}

bool InputSchedule::schedule(const stimuli::InputChange& change, InputCause::Kind cause) {
  if (lineBit(change.input) == 0) return true;
  if (reactive_.size() >= kMaxPendingReactive) return false;
  reactive_.insert(reactive_.end(),
                   Pending{change.at, nextSeq_++, change.input, change.on, change.line, cause == InputCause::Kind::Set});
  return true;
}

// Visits the pending changes in effect order: (time, input, on).
template <typename Visit>
void InputSchedule::forEachPending(Visit&& visit) const {
  std::size_t t = nextTimed_;
  auto r = reactive_.begin();
  while (t < timed_->size() || r != reactive_.end()) {
    const bool timedFirst = t < timed_->size() && (r == reactive_.end() || (*timed_)[t].at <= r->at);
    const stimuli::InputChange c = timedFirst ? (*timed_)[t++] : stimuli::InputChange{r->at, r->input, r->on};
    if (!timedFirst) ++r;
    const bool more = t < timed_->size() || r != reactive_.end();
    const vm::Micros nextAt = !more ? c.at
                              : (t < timed_->size() && (r == reactive_.end() || (*timed_)[t].at <= r->at))
                                  ? (*timed_)[t].at
                                  : r->at;
    if (!visit(c, !more || nextAt != c.at)) return;
  }
}

std::optional<vm::Micros> InputSchedule::whenReads(int input, bool on, vm::IoMask inputs) const {
  bool reads = (inputs & lineBit(input)) != 0;
  std::optional<vm::Micros> when;
  forEachPending([&](const stimuli::InputChange& c, bool lastAtThisTime) {
    if (c.input == input) reads = c.on;
    if (lastAtThisTime && reads == on) {
      when = c.at;
      return false;
    }
    return true;
  });
  return when;
}

bool InputSchedule::hasPendingFor(int input) const {
  bool found = false;
  forEachPending([&](const stimuli::InputChange& c, bool) {
    found = c.input == input;
    return !found;
  });
  return found;
}

}  // namespace rs::runtime
