// The debugger's backwards steps (tools/debug/timeline.h): how the snapshot
// interval K trades memory for the time of one reverse step, on a run of
// about 1,000,000 instructions on the library's scara-pick cell (moves, a
// subroutine, outputs, the world's grasping). For each K: the run forwards
// to the end with snapshots, the snapshots' memory, and one reverse step
// at 200 spread-out moments (the worst and the median). Targets: a reverse
// step within 10 ms, snapshots under 64 MiB (docs/performance.md).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>

#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "tools/debug/debug_session.h"
#include "launch/program.h"
#include "tools/teach/run_source.h"

namespace rs::bench {

namespace {

constexpr long kLoops = 111'111;  // 9 instructions a loop: 1,000,001 in all, with SET

runtime::RunSpec debugSpec(long loops) {
  compiler::Library library(compiler::librarySearchPath({}));
  const std::optional<workcell::Workcell> found = library.workcell("scara-pick");
  if (!found) throw std::runtime_error("the library has no scara-pick workcell");
  const diag::SourceFile source(
      "reverse.rsp", fmt::format("SET N 0\nloop: ADD N 1\nMOVE 10 0 0 0 0\nMOVE -10 0 0 0 60\nGOSUB sub\n"
                                 "MOVE 0 0 0 0 -60\nJMPVAR N < {} loop\nEND\nsub: OUTSIG 1 ON\nOUTSIG 1 OFF\nRETURN\n",
                                 loops));
  compiler::CompileResult compiled = compiler::compile(source, launch::cellTarget(*found));
  if (!compiled.image) throw std::runtime_error("the reverse-step program did not compile");
  runtime::RunSpec spec;
  spec.image = std::make_shared<const vm::Image>(*compiled.image);
  spec.cell = std::make_shared<const workcell::Workcell>(*found);
  spec.limits.maxTime = vm::Micros{1'000'000} * 1'000'000;  // the loops take about 17 simulated hours
  return spec;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// This thread's CPU time: on a loaded machine a wall-clock worst case is
// mostly the time the thread waited for a core.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// What `debug --view` adds to every stop: the live view's publish of the
// stopped moment (tools/teach/run_source.h: the run's view as the page's JSON),
// at 200 moments spread over the run.
nlohmann::json benchViewPublish(const runtime::RunSpec& spec) {
  debug::DebugSession session(spec);
  teach::RunSource source("", "reverse.rsp");
  std::vector<double> publish;
  for (int i = 0; i < 200; ++i) {
    session.step(5'000);
    const auto t = std::chrono::steady_clock::now();
    source.publish(session.run(), "step done");
    publish.push_back(secondsSince(t));
  }
  std::sort(publish.begin(), publish.end());
  const double median = publish[publish.size() / 2], worst = publish.back();
  const std::size_t bytes = source.state().size();
  fmt::print("  the live view (debug --view): publishing a stop median {:.1f} us, worst {:.1f} us, {} bytes of JSON\n",
             median * 1e6, worst * 1e6, bytes);
  return {{"publish_median_us", median * 1e6}, {"publish_worst_us", worst * 1e6}, {"state_bytes", bytes}};
}

}  // namespace

nlohmann::json benchDebug(const Options& options) {
  const long loops = sized(options, kLoops, kLoops / 1000);
  const std::uint64_t moments = sized<std::uint64_t>(options, 200, 10);
  fmt::print("\n[9] Reverse steps: a {}-loop program on scara-pick, one snapshot every K instructions\n", loops);
  const runtime::RunSpec spec = debugSpec(loops);
  nlohmann::json out = nlohmann::json::object();
  double plainBest = 1e9;
  for (int rep = 0; rep < std::max(1, options.reps / 2); ++rep) {
    runtime::Run run(spec);
    const auto start = std::chrono::steady_clock::now();
    if (!run.runToEnd().ok()) throw std::runtime_error("the reverse-step program failed");
    plainBest = std::min(plainBest, secondsSince(start));
  }
  fmt::print("  without the debugger: to the end {:.2f} ms\n", plainBest * 1e3);
  out["plain_ms"] = plainBest * 1e3;
  out["intervals"] = nlohmann::json::array();
  for (const std::uint64_t k : {1024ULL, 4096ULL, 16384ULL, 65536ULL}) {
    double forwardBest = 1e9;
    std::vector<double> reverse, reverseCpu;
    std::uint64_t steps = 0;
    std::size_t memory = 0, count = 0;
    for (int rep = 0; rep < std::max(1, options.reps / 2); ++rep) {
      debug::DebugSession session(spec, {k, debug::kDefaultSnapshotBudget});
      const auto start = std::chrono::steady_clock::now();
      const debug::Stop end = session.resume();
      forwardBest = std::min(forwardBest, secondsSince(start));
      if (end.reason != debug::StopReason::End) throw std::runtime_error("the reverse-step program failed: " + end.message);
      steps = session.run().interpreter().steps();
      memory = session.timeline().snapshotMemory();
      count = session.timeline().snapshotCount();
      // 200 moments spread over the run: every other one a multiple of K
      // (the worst case: the step back re-runs K - 1 instructions), the
      // others a little after a spread-out place. The session gets there
      // from where it is, forwards or by the timeline (a restore and at
      // most K instructions), as a debugger does, not from the start.
      session.reverseStep(UINT64_MAX);
      for (std::uint64_t i = 0; i < moments; ++i) {
        const std::uint64_t base = steps * i / moments;
        std::uint64_t at = i % 2 == 0 ? std::max<std::uint64_t>(k, base / k * k) : base + (i * 7919) % k + 1;
        at = std::min(at, steps);
        const std::uint64_t now = session.run().interpreter().steps();
        if (at > now) session.step(at - now);
        else if (at < now) session.reverseStep(now - at);
        const auto t = std::chrono::steady_clock::now();
        const double cpu = threadCpuSeconds();
        session.reverseStep();
        reverseCpu.push_back(threadCpuSeconds() - cpu);
        reverse.push_back(secondsSince(t));
      }
    }
    std::sort(reverse.begin(), reverse.end());
    std::sort(reverseCpu.begin(), reverseCpu.end());
    const double worst = reverse.back(), median = reverse[reverse.size() / 2], worstCpu = reverseCpu.back();
    const double medianCpu = reverseCpu[reverseCpu.size() / 2];
    fmt::print("  K = {:>6}: forwards {:7.2f} ms ({} steps), {:>4} snapshots {:6.2f} MiB, one reverse step "
               "median {:.3f} ms, worst {:.3f} ms [cpu median {:.3f} ms, worst {:.3f} ms]\n",
               k, forwardBest * 1e3, steps, count, static_cast<double>(memory) / (1 << 20), median * 1e3, worst * 1e3,
               medianCpu * 1e3, worstCpu * 1e3);
    out["intervals"].push_back({{"interval", k},
                   {"steps", steps},
                   {"forward_ms", forwardBest * 1e3},
                   {"snapshots", count},
                   {"snapshot_mib", static_cast<double>(memory) / (1 << 20)},
                   {"reverse_step_median_ms", median * 1e3},
                   {"reverse_step_worst_ms", worst * 1e3},
                   {"reverse_step_median_cpu_ms", medianCpu * 1e3},
                   {"reverse_step_worst_cpu_ms", worstCpu * 1e3}});
  }
  fmt::print("  default K = {} (tools/debug/timeline.h); targets: a reverse step median <= 1 ms and worst <= 10 ms of CPU, "
             "snapshots < 64 MiB, all of this in under 10 s; collisions on (the default)\n",
             debug::kDefaultSnapshotInterval);
  out["view"] = benchViewPublish(spec);
  return out;
}

}  // namespace rs::bench
