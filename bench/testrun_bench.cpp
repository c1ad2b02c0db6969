// `robotsim test` hardened (benchTestRun): the peak memory of a test whose
// run is 100,000,000 instructions long, against the same loop kept as a
// RunLog (what the runner kept before); one `; expect: motors` line of 10k,
// 100k and 1M terms (linear: 10x a step); and a submission that never ends
// under `--spec`, with grading's default limits against the run limits
// grading had before (3,600 s), on the scara-pick cell (every pose of every
// move checked for collisions).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "bench/benchmarks.h"

namespace rs::bench {

using nlohmann::json;

namespace {

// 20,000,000 rounds of 5 instructions, 1 ms each, with expectations on
// moments, windows, pulses, an order and a bound all through the run
// (tests/testrun/test_testrun_memory.cpp works them out).
std::string longProgram(const std::string& steps) {
  return fmt::format(
      "; test: input 1=ON@5\n; test: max-time 30000\n; test: max-steps {}\n; expect: step limit\n"
      "; expect: variable N = 1 during 0..0.001\n; expect: output 1 on before input 1 on\n"
      "; expect: input 1 off during 0..5\n; expect: output 2 off during 0..30\n; expect: motor E never above 0\n"
      "LOOP:   ADD N 1\n        OUTSIG 1 ON\n        OUTSIG 1 OFF\n        DELAY 0.001\n        GOTO LOOP\n",
      steps);
}

ProcessRun runExpecting(const std::vector<std::string>& argv, int exitCode) {
  const ProcessRun run = runProcess(argv);
  if (run.exitCode != exitCode)
    throw std::runtime_error(fmt::format("{} {} exited {}, not {}", argv[0], argv[1], run.exitCode, exitCode));
  return run;
}

double mib(long kib) { return static_cast<double>(kib) / 1024; }

}  // namespace

json benchTestRun(const Options& options) {
  fmt::print("\n[11] robotsim test: memory of a long run, a long expectation line, a submission that never ends\n");
  json out;
  std::filesystem::create_directories(std::filesystem::path(options.workDir) / "testrun" / "submissions");

  const long instructions = sized(options, 100'000'000L, 100'000L), logged10 = instructions / 10;
  progress(fmt::format("robotsim test on {} instructions; run --profile (a RunLog) on {} of the same loop",
                       instructions, logged10));
  const std::string program = writeInput(options, "testrun/long.rsp", longProgram(std::to_string(instructions)));
  const ProcessRun tested = runExpecting({options.robotsim, "test", program}, 0);
  const ProcessRun logged = runExpecting({options.robotsim, "run", program, "--profile", "--max-steps",
                                          std::to_string(logged10), "--max-time", "30000"},
                                         1);
  if (tested.maxRssKiB <= selfPeakRssKiB()) fmt::print("  (the driver's own peak hides robotsim test's)\n");
  const double logBytes = static_cast<double>(logged.maxRssKiB) * 1024 / static_cast<double>(logged10);
  fmt::print("  robotsim test, {:.0e} instructions: peak {:.1f} MiB, {:.2f} s CPU; target < 100 MB: {}\n",
             static_cast<double>(instructions), mib(tested.maxRssKiB), tested.cpuSeconds,
             tested.maxRssKiB * 1024 < 100'000'000 ? "met" : "missed");
  fmt::print(
      "  the same loop logged (run --profile), {:.0e} instructions: peak {:.1f} MiB, {:.1f} bytes an "
      "instruction (1e8: {:.2f} GB)\n",
      static_cast<double>(logged10), mib(logged.maxRssKiB), logBytes, logBytes * 1e8 / 1e9);
  out["long_run"] = {{"instructions", instructions},
                     {"test_max_rss_kib", tested.maxRssKiB},
                     {"test_cpu_s", tested.cpuSeconds},
                     {"logged_instructions", logged10},
                     {"logged_max_rss_kib", logged.maxRssKiB},
                     {"logged_bytes_per_instruction", logBytes}};

  const int largest = sized(options, 1'000'000, 1'000);
  progress(fmt::format("one '; expect: motors' line of {}, {} and {} terms, robotsim test, whole process",
                       largest / 100, largest / 10, largest));
  json terms = json::array();
  double previous = 0;
  for (const int n : {largest / 100, largest / 10, largest}) {
    std::string line = "; expect: motors";
    for (int i = 0; i < n; ++i) line += i % 2 ? " D=0" : " E=100";
    const std::string path =
        writeInput(options, fmt::format("testrun/motors-{}.rsp", n), line + "\nMOVE 100 0 0 0 0\nEND\n");
    const std::vector<Samples> s = interleave({processMeasurement({options.robotsim, "test", path})}, options.reps);
    const double growth = previous > 0 ? s[0].best() / previous : 0;
    row(fmt::format("{} terms ({:.1f} MB line)", n, static_cast<double>(line.size()) / 1e6), s[0],
        previous > 0 ? fmt::format("growth x{:.1f} (linear: 10)", growth) : std::string());
    terms.push_back({{"terms", n}, {"run", toJson(s[0])}, {"growth", growth}});
    previous = s[0].best();
  }
  out["motors_line"] = terms;
  fmt::print("  {} terms: target < 1 s: {}\n", largest, previous < 1.0 ? "met" : "missed");

  progress("a submission that never ends, robotsim test --spec on scara-pick: grading's limits, and 3,600 s");
  writeInput(options, "testrun/submissions/forever.rsp",
             "; swings the arm over the cell for ever\nLOOP:   MOVE 300 -300 0 0 0\n        MOVE -300 300 0 0 0\n"
             "        GOTO LOOP\n");
  writeInput(options, "testrun/submissions/polls.rsp", "LOOP:   JMPIN 1 ON DONE\n        GOTO LOOP\nDONE:   END\n");
  const std::string grading =
      writeInput(options, "testrun/grading.rstest", "scenario on the cell\ntest: cell scara-pick\nexpect: finished\n");
  const std::string before = writeInput(options, "testrun/before.rstest",
                                        fmt::format("scenario on the cell\ntest: cell scara-pick\ntest: max-time {}\n"
                                                    "test: max-steps 100000000\nexpect: finished\n",
                                                    sized(options, 3600, 36)));
  const std::string folder = options.workDir + "/testrun/submissions";
  std::vector<double> gradingCpu, beforeCpu;
  for (int r = 0; r < options.reps; ++r) {
    gradingCpu.push_back(runExpecting({options.robotsim, "test", "--spec", grading, folder, "-j", "1"}, 1).cpuSeconds);
    beforeCpu.push_back(runExpecting({options.robotsim, "test", "--spec", before, folder, "-j", "1"}, 1).cpuSeconds);
  }
  const double g = *std::min_element(gradingCpu.begin(), gradingCpu.end());
  const double b = *std::min_element(beforeCpu.begin(), beforeCpu.end());
  fmt::print(
      "  grading's limits (120 s, 1,000,000 instructions, 100,000 at one instant): {:.3f} s CPU for both "
      "submissions; target <= 1 s: {}\n",
      g, g <= 1.0 ? "met" : "missed");
  fmt::print("  3,600 s and 100,000,000 instructions (before): {:.3f} s CPU; ratio {:.1f}\n", b, b / g);
  out["never_ending"] = {{"grading_cpu_s", g}, {"before_cpu_s", b}, {"target_met", g <= 1.0}};
  return out;
}

}  // namespace rs::bench
