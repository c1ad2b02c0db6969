// Several robots on one clock (issue 36, `--only robots`): two XR-4s 3000
// apart, each running a loop of waist moves, never interacting (no wire).
// Paired in one run: the two together in a cell run, against each alone in
// the same cell (the other standing still, still an obstacle). Target: the
// pair costs at most 1.3x the sum of the two alone.
#include <fmt/format.h>

#include <stdexcept>
#include <string>

#include "base/seconds.h"
#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "launch/cell_programs.h"
#include "launch/run_request.h"
#include "runtime/run/cell_run.h"

namespace rs::bench {
namespace {

std::string loopProgram(int turns, int reach) {
  return fmt::format(
      "; the robots bench (bench/robots_bench.cpp)\n        SET N 0\nagain:  MOVE {} 0 0 0 0 0\n"
      "        MOVE {} 0 0 0 0 0\n        ADD N 1\n        JMPVAR N < {} again\n        END\n",
      reach, -reach, turns);
}

runtime::CellRunSpec specOf(const std::string& cellPath, const std::vector<std::string>& assignments) {
  launch::ProgramRequest request;
  request.cell = cellPath;
  launch::CellPrograms programs;
  if (!launch::assignCellPrograms(request, assignments, programs)) throw std::runtime_error("the bench cell does not load");
  launch::compileAssignedPrograms(request, programs);
  std::vector<diag::Diagnostic> diags;
  std::optional<runtime::CellRunSpec> spec = launch::prepareCellRun(programs, {}, diags);
  if (!spec) throw std::runtime_error("the bench cell's programs do not compile");
  spec->limits.maxTime = vm::Micros{1} << 50;
  return *spec;
}

}  // namespace

nlohmann::json benchRobots(const Options& options) {
  const int turns = sized(options, 2000, 10);
  fmt::print("\n[robots] Two robots on one clock that never interact: two XR-4s, {} waist turns each\n", turns);
  const std::string left = writeInput(options, "robots_left.rsp", loopProgram(turns, 300));
  const std::string right = writeInput(options, "robots_right.rsp", loopProgram(turns, 450));
  // The cell names no PROGRAM: each measurement gives its own.
  const std::string cell = writeInput(options, "robots.rsd",
                                      "WORKCELL robots\n  ROBOT rhino-xr4 AT 0 750 0 AS left\n"
                                      "  ROBOT rhino-xr4 AT 3000 750 0 AS right\nEND\n");
  const runtime::CellRunSpec both = specOf(cell, {"left=" + left, "right=" + right});
  runtime::CellRunSpec leftAlone = both, rightAlone = both;
  leftAlone.programs.resize(1);
  rightAlone.programs.erase(rightAlone.programs.begin());
  const auto timed = [](const runtime::CellRunSpec& spec, const char* what) {
    return [&spec, what]() {
      runtime::CellRun run(spec);
      const Stopwatch clock;
      const vm::RunOutcome outcome = run.runToEnd();
      const Sample sample = clock.stop();
      if (!outcome.ok()) throw std::runtime_error(fmt::format("the {} run failed: {}", what, outcome.message));
      return sample;
    };
  };
  progress(fmt::format("interleaved, 1 warm-up + {} rounds: the two together, left alone, right alone", options.reps));
  const std::vector<Samples> s =
      interleave({timed(both, "pair"), timed(leftAlone, "left"), timed(rightAlone, "right")}, options.reps);
  row("the two together", s[0]);
  row("left alone", s[1]);
  row("right alone", s[2]);
  const double ratio = s[0].cpuBest() / (s[1].cpuBest() + s[2].cpuBest());
  fmt::print("  ratio together / sum alone (CPU) {}\n", verdict(ratio, 1.3));
  return {{"turns", turns},
          {"together", toJson(s[0])},
          {"left_alone", toJson(s[1])},
          {"right_alone", toJson(s[2])},
          {"cpu_ratio", ratio}};
}

}  // namespace rs::bench
