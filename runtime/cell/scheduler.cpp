#include "runtime/cell/scheduler.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "base/seconds.h"

namespace rs::runtime {

std::uint32_t Scheduler::add(CellProcess& process) {
  processes_.push_back(&process);
  wokenNow_.push_back(0);
  return static_cast<std::uint32_t>(processes_.size() - 1);
}

bool Scheduler::schedule(vm::Micros at, std::uint32_t process, std::uint32_t tag) {
  if (at < state_.now || state_.queue.size() >= kMaxCellEvents || process >= processes_.size()) return false;
  state_.queue.insert({at, state_.nextSeq++, process, tag});
  return true;
}

bool Scheduler::cancel(vm::Micros at, std::uint64_t seq) {
  // The order compares time and sequence number alone.
  return state_.queue.erase(CellEvent{at, seq, 0, 0}) != 0;
}

std::optional<vm::Micros> Scheduler::nextTime() const {
  if (state_.queue.empty()) return std::nullopt;
  return state_.queue.begin()->at;
}

vm::Status Scheduler::advanceTo(vm::Micros t) {
  while (!state_.queue.empty() && state_.queue.begin()->at <= t) {
    const vm::Micros at = state_.queue.begin()->at;
    state_.now = at;
    if (vm::Status s = runInstant(at); !s) return s;
  }
  if (t > state_.now) state_.now = t;
  return vm::Status::ok();
}

// One instant, delta by delta: evaluate the events queued before the delta
// began, then update every process; what either scheduled for this instant
// runs in the next delta.
vm::Status Scheduler::runInstant(vm::Micros at) {
  std::vector<std::uint32_t>& woken = woken_;  // in the latest delta: a loop's error names them
  for (std::uint64_t delta = 0;; ++delta) {
    const auto due = [&] { return !state_.queue.empty() && state_.queue.begin()->at == at; };
    if (!due()) {
      lastDeltas_ = delta;
      return vm::Status::ok();
    }
    if (delta == kMaxDeltas) {
      for (auto it = state_.queue.begin(); it != state_.queue.end() && it->at == at; ++it) woken.push_back(it->process);
      std::sort(woken.begin(), woken.end());
      woken.erase(std::unique(woken.begin(), woken.end()), woken.end());
      std::string names;
      for (std::uint32_t p : woken) names += (names.empty() ? "" : ", ") + processes_[p]->name();
      return vm::Status::fault(fmt::format("more than {} rounds of changes at {} s without end: {} keep changing each other",
                                           kMaxDeltas, base::formatSeconds(at), names));
    }
    woken.clear();
    const std::uint64_t deltaEnd = state_.nextSeq;
    toUpdate_.clear();
    while (due() && state_.queue.begin()->seq < deltaEnd) {
      const CellEvent e = *state_.queue.begin();
      state_.queue.erase(state_.queue.begin());
      if (woken.size() < 64) woken.push_back(e.process);
      if (!std::exchange(wokenNow_[e.process], 1)) toUpdate_.push_back(e.process);
      processes_[e.process]->wake(e, *this);
    }
    // The processes woken, in the model's order.
    std::sort(toUpdate_.begin(), toUpdate_.end());
    for (const std::uint32_t p : toUpdate_) {
      wokenNow_[p] = 0;
      processes_[p]->update(*this);
    }
  }
}

}  // namespace rs::runtime
