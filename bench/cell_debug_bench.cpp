// The debugger of a cell of several robots going backwards (issue 36,
// `--only cell_debug`): tools/debug/cell_session.h re-runs the cell from
// its start to the moment it goes back to. On examples/two_robots/
// interlock.rsd, at every moment a `step` stops at (the two robots
// stepped in turn through the whole run, then each robot alone), one
// reverse step: the last ones re-run the cell nearly to its end. Targets: a
// reverse step median <= 1 ms, worst <= 10 ms (CPU).
#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "tools/debug/cell_session.h"

namespace rs::bench {
namespace {

double cellThreadCpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

}  // namespace

nlohmann::json benchCellDebug(const Options& options) {
  fmt::print("\n[cell_debug] Reverse step in the two-robot example (examples/two_robots/interlock.rsd)\n");
  launch::ProgramRequest request;
  request.cell = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/interlock.rsd";
  launch::CellPrograms programs;
  if (!launch::assignCellPrograms(request, {}, programs)) throw std::runtime_error("the interlock cell does not load");
  launch::compileAssignedPrograms(request, programs);
  std::vector<diag::Diagnostic> diags;
  const std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, {}, diags);
  if (!spec) throw std::runtime_error("the interlock cell's programs do not compile");
  std::vector<double> cpu, wall;
  std::uint64_t moments = 0;
  // Three ways through the run each repetition: the robots stepped in turn, then each robot alone.
  for (int rep = 0; rep < 3 * std::max(1, options.reps); ++rep) {
    debug::CellSession session(*spec);
    for (std::size_t turn = 0;; ++turn) {
      session.select(rep % 3 == 0 ? turn % session.size() : static_cast<std::size_t>(rep % 3 - 1));
      const auto stepped = session.step();
      if (!stepped || stepped->finished()) break;
      const Stopwatch clock;
      const double before = cellThreadCpu();
      session.reverseStep();
      cpu.push_back(cellThreadCpu() - before);
      wall.push_back(clock.stop().wall);
      session.step();  // back where it was
      ++moments;
    }
  }
  if (cpu.empty()) throw std::runtime_error("the interlock cell stopped nowhere");
  std::sort(cpu.begin(), cpu.end());
  std::sort(wall.begin(), wall.end());
  const double median = cpu[cpu.size() / 2], worst = cpu.back();
  fmt::print("  {} reverse steps: CPU median {:.3f} ms, worst {:.3f} ms (wall median {:.3f} ms, worst {:.3f} ms)\n",
             cpu.size(), median * 1e3, worst * 1e3, wall[wall.size() / 2] * 1e3, wall.back() * 1e3);
  fmt::print("  median {}, worst {}\n", verdict(median * 1e3, 1.0), verdict(worst * 1e3, 10.0));
  return {{"reverse_steps", moments},
          {"reverse_step_median_cpu_ms", median * 1e3},
          {"reverse_step_worst_cpu_ms", worst * 1e3},
          {"reverse_step_median_ms", wall[wall.size() / 2] * 1e3},
          {"reverse_step_worst_ms", wall.back() * 1e3}};
}

}  // namespace rs::bench
