#include "runtime/run/cell_log.h"

#include <algorithm>

namespace rs::runtime {

namespace {

// p's step in force at time t: the first that ends at or after t.
std::uint32_t stepAt(const RunLog& log, vm::Micros t) {
  if (log.steps.empty()) return 0;
  const auto it = std::lower_bound(log.steps.begin(), log.steps.end(), t,
                                   [](const StepRecord& s, vm::Micros v) { return s.end < v; });
  return static_cast<std::uint32_t>(it == log.steps.end() ? log.steps.size() - 1 : it - log.steps.begin());
}

// Records of every log, robot p's as they are, the others' re-keyed to
// p's steps; stably by time (at one time, in the cell's order of robots).
template <class Record, class At>
std::vector<Record> merged(const CellRun& run, std::size_t p, std::vector<Record> RunLog::*list, At at) {
  const RunLog& own = *run.robot(p).log();
  std::vector<Record> all;
  for (std::size_t q = 0; q < run.size(); ++q) {
    const RunLog* log = run.robot(q).log();
    if (!log) continue;
    for (Record r : (*log).*list) {
      if (q != p) r.step = stepAt(own, at(r));
      all.push_back(r);
    }
  }
  std::stable_sort(all.begin(), all.end(), [&](const Record& a, const Record& b) {
    return a.step != b.step ? a.step < b.step : at(a) < at(b);
  });
  return all;
}

}  // namespace

RunLog cellLogOf(const CellRun& run, std::size_t p) {
  const RunLog* own = run.robot(p).log();
  if (!own) return {};
  RunLog log = *own;
  log.devices = merged(run, p, &RunLog::devices, [](const DeviceRecord& r) { return r.event.at; });
  log.motions = merged(run, p, &RunLog::motions, [](const MotionRecord& r) { return r.motion.at; });
  return log;
}

}  // namespace rs::runtime
