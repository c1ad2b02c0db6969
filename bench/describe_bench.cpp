// describe_bench: what `robotsim describe` and the terminal pendant cost.
// The reach search (model/workcell/reach.h: a grid of ~10^5 poses over the
// motors' ranges, then a climb) for each library workcell, and laying out
// one terminal-pendant screen (tools/teach/tui/tui_screen.h) of 80x24 with five
// motors and 30 points; best and median of N runs. Run by `make bench`;
// figures in docs/performance.md. Not a test: it prints numbers.
//
//   describe_bench [--smoke] [REPS]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench_args.h"
#include "compiler/description/library.h"
#include "model/workcell/reach.h"
#include "tools/teach/pendant_state.h"
#include "tools/teach/tui/tui_screen.h"

namespace {

using Clock = std::chrono::steady_clock;

template <typename F>
void measure(const std::string& what, int reps, int inner, F&& f) {
  std::vector<double> times;
  for (int r = 0; r < reps; ++r) {
    const auto start = Clock::now();
    for (int i = 0; i < inner; ++i) f();
    times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count() / inner);
  }
  std::sort(times.begin(), times.end());
  fmt::print("  {:<44} best {:>10.1f} us   median {:>10.1f} us\n", what, times.front(), times[times.size() / 2]);
}

}  // namespace

constexpr rs::bench::CountArgument kDescribeCounts[] = {{"REPS", "runs (best and median printed)", 5, 1}};

int main(int argc, char** argv) {
  const rs::bench::BenchArguments args = rs::bench::parseBenchArguments(
      argc, argv, "describe_bench", "describe's reach search and a terminal-pendant screen (docs/performance.md).",
      kDescribeCounts);
  if (args.exitCode) return *args.exitCode;
  const int reps = static_cast<int>(args[0]);
  fmt::print("describe and the terminal pendant, best and median of {}\n", reps);
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  double sink = 0;  // keeps the work observable
  for (const char* name : {"scara-pick", "scorobot-cell", "puma-cell", "gantry-cell"}) {
    const std::optional<rs::workcell::Workcell> cell = library.workcell(name);
    if (!cell) {
      fmt::print("  {}: cannot load\n", name);
      return 1;
    }
    const rs::workcell::PlacedRobot& driven = *cell->drivenRobot();
    measure(fmt::format("reach of {} ({} motors)", name, driven.robot.joints.size()), reps, 1,
            [&] { sink += rs::workcell::reachOf(driven).max.x(); });
  }

  rs::teach::PendantState state;
  state.program = "examples/pick_and_place.rsp";
  state.cell = "scara-pick";
  for (char letter : {'E', 'D', 'C', 'B'}) state.motors.push_back({letter, rs::vm::JointKind::Revolute, 0.1, -1000, 1000, 400});
  state.motors.push_back({'A', rs::vm::JointKind::Gripper, 0.5, 0, 120, 200});
  state.encoders = {120, -40, 350, 0, 120};
  state.tcp = std::array<double, 3>{-180.25, 800.5, 45.125};
  state.gripper = rs::teach::GripperState::Closed;
  for (int p = 0; p < 30; ++p) state.points.push_back({fmt::format("P{}", p), {p, -p, 10 * p, 0, 120}, 10u + p, true});
  state.message = "taught P29 = 29 -29 290 0 120 (written to examples/pick_and_place.rsp)";
  const rs::teach::tui::Selection selection{.mode = rs::teach::JogMode::Joint, .motor = 0, .axis = 0, .point = 20, .step = 10, .help = false};
  measure("terminal pendant screen, 80x24, 30 points", reps, args.smoke ? 100 : 10000, [&] {
    sink += static_cast<double>(rs::teach::tui::layoutScreen(state, selection, {}, "", 80, 24).marks.size());
  });
  fmt::print("  (checksum {:.6g})\n", sink);
  return 0;
}
