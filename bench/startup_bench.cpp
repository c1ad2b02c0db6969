// Issue 25's start-up targets, each paired with its peer in one run:
// `robotsim check` on a 3-line program and `robotsim help` against
// `luac5.4 -v` (target: 2 times its time), and the peak memory of a
// one-line `robotsim compile` (target: half of the 13 MiB it was).
#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/timing.h"

namespace rs::bench {

namespace {

constexpr double kStartupTargetRatio = 2.0;
constexpr double kFixedPeakBeforeMiB = 13.0;  // the one-line compile before issue 25 (docs/performance.md)
}  // namespace

nlohmann::json benchStartupPeers(const Options& options) {
  fmt::print("\n[3b] Start-up against luac5.4 -v: robotsim check on 3 lines, robotsim help; a one-line compile's memory\n");
  nlohmann::json out = {{"target_ratio", kStartupTargetRatio}};
  const std::string three = writeInput(options, "startup-3.rsp", "SET N 1\nADD N 2\nEND\n");
  const std::string one = writeInput(options, "startup-1.rsp", "END\n");
  const std::string image = options.workDir + "/startup-1.rsb";
  std::vector<Measurement> runs{processMeasurement({options.robotsim, "check", three}),
                                processMeasurement({options.robotsim, "help"})};
  const bool withLuac = canRun({options.luac, "-v"});
  if (withLuac) runs.push_back(processMeasurement({options.luac, "-v"}));
  progress(fmt::format("interleaved, 1 warm-up + {} rounds: robotsim check (3 lines), robotsim help{}", options.reps,
                       withLuac ? ", luac5.4 -v" : ""));
  const std::vector<Samples> s = interleave(runs, options.reps);
  row("robotsim check, 3 lines", s[0]);
  row("robotsim help", s[1]);
  out["check"] = toJson(s[0]);
  out["help"] = toJson(s[1]);
  if (withLuac) {
    row("luac5.4 -v", s[2]);
    out["luac"] = toJson(s[2]);
    for (const auto& [name, i] : {std::pair{"check", 0}, std::pair{"help", 1}}) {
      const double wall = s[i].best() / s[2].best(), cpu = s[i].cpuBest() / s[2].cpuBest();
      fmt::print("  ratio robotsim {} / luac5.4 -v: best {}; CPU {:.2f}; median {:.2f}\n", name,
                 verdict(wall, kStartupTargetRatio), cpu, s[i].median() / s[2].median());
      out[fmt::format("ratio_{}", name)] = {{"best", wall}, {"cpu", cpu}, {"median", s[i].median() / s[2].median()},
                                             {"target_met", wall <= kStartupTargetRatio}};
    }
  } else {
    fmt::print("  luac comparison skipped: cannot run {}\n", options.luac);
  }
  if (!canRun({kGnuTime, "-f", "%M", "true"})) {
    fmt::print("  peak memory skipped: cannot run {} (Debian's time)\n", kGnuTime);
    return out;
  }
  long least = 0;
  for (int i = 0; i < options.reps; ++i) {
    const long kib = peakRssKiBByGnuTime(options.workDir, {options.robotsim, "compile", one, "-o", image}, 0);
    least = least == 0 ? kib : std::min(least, kib);
  }
  const double mib = static_cast<double>(least) / 1024;
  fmt::print("  peak RSS of robotsim compile, one line: {:.1f} MiB; over the {:.0f} MiB before: {}\n", mib,
             kFixedPeakBeforeMiB, verdict(mib / kFixedPeakBeforeMiB, 0.5));
  out["compile_one_line_peak_kib"] = least;
  out["compile_target_met"] = mib <= kFixedPeakBeforeMiB / 2;
  return out;
}

}  // namespace rs::bench
