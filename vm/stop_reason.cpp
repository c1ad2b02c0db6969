#include "vm/stop_reason.h"

#include <array>

namespace rs::vm {

namespace {

// One row a reason, in the enum's order. An empty debugger word is the
// run's word; an empty adapter reason is the debugger's word.
struct StopWords {
  StopReason reason;
  std::string_view run;
  std::string_view debugger;
  std::string_view adapter;
};

constexpr std::array kStopWords{
    StopWords{StopReason::End, "finished", "end", ""},
    StopWords{StopReason::RuntimeError, "runtime error", "", "exception"},
    StopWords{StopReason::Deadlock, "deadlock", "", "exception"},
    StopWords{StopReason::StepLimit, "step limit", "limit", "exception"},
    StopWords{StopReason::TimeLimit, "time limit", "limit", "exception"},
    StopWords{StopReason::InstantLimit, "clock standing still", "limit", "exception"},
    StopWords{StopReason::KnotLimit, "knot limit", "limit", "exception"},
    StopWords{StopReason::Paused, "paused", "pause", ""},
    StopWords{StopReason::Step, "step", "", ""},
    StopWords{StopReason::Time, "time", "", "goto"},
    StopWords{StopReason::Breakpoint, "breakpoint", "", ""},
    StopWords{StopReason::Condition, "condition", "", "step"},
    StopWords{StopReason::Pause, "pause", "", ""},
    StopWords{StopReason::Entry, "entry", "", ""},
    StopWords{StopReason::Watch, "watch", "", "data breakpoint"},
    StopWords{StopReason::Start, "start", "", "step"},
};

constexpr bool inEnumOrder() {
  for (std::size_t i = 0; i < kStopWords.size(); ++i)
    if (static_cast<std::size_t>(kStopWords[i].reason) != i) return false;
  return kStopWords.size() == static_cast<std::size_t>(StopReason::Start) + 1;
}
static_assert(inEnumOrder(), "kStopWords has one row per StopReason, in the enum's order");

const StopWords& wordsOf(StopReason reason) {
  const auto i = static_cast<std::size_t>(reason);
  return kStopWords[i < kStopWords.size() ? i : 0];
}

}  // namespace

std::string_view stopReasonName(StopReason reason) { return wordsOf(reason).run; }

std::string_view debuggerName(StopReason reason) {
  const StopWords& w = wordsOf(reason);
  return w.debugger.empty() ? w.run : w.debugger;
}

std::string_view adapterReason(StopReason reason) {
  const StopWords& w = wordsOf(reason);
  return w.adapter.empty() ? debuggerName(reason) : w.adapter;
}

}  // namespace rs::vm
