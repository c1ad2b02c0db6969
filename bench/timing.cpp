#include "bench/timing.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <fstream>
#include <stdexcept>

extern char** environ;

namespace rs::bench {

namespace {

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; }

}  // namespace

double Samples::best() const { return minimum(seconds); }
double Samples::cpuBest() const { return minimum(cpuSeconds); }

double Samples::median() const {
  if (seconds.empty()) return 0.0;
  std::vector<double> s = seconds;
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  return n % 2 == 1 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

Stopwatch::Stopwatch() : wall_(std::chrono::steady_clock::now()), cpu_(processCpuSeconds()) {}

Sample Stopwatch::stop() const {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
  return {wall, processCpuSeconds() - cpu_};
}

namespace {

std::string commandLine(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& a : argv) line += (line.empty() ? "" : " ") + a;
  return line;
}

// posix_spawn's file actions (stdio on /dev/null), released on every path.
struct SpawnSetup {
  posix_spawn_file_actions_t actions{};
  SpawnSetup() {
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  }
  ~SpawnSetup() { posix_spawn_file_actions_destroy(&actions); }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

}  // namespace

ProcessRun runProcess(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  SpawnSetup setup;

  const Stopwatch clock;
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &setup.actions, nullptr, args.data(), environ);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot run {}: {}", argv[0], std::strerror(rc)));

  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0) {
    if (errno != EINTR) throw std::runtime_error(fmt::format("wait4 failed: {}", std::strerror(errno)));
  }
  ProcessRun run;
  run.seconds = clock.stop().wall;
  run.cpuSeconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.maxRssKiB = usage.ru_maxrss;  // Linux: kibibytes
  return run;
}

std::vector<Samples> interleave(const std::vector<Measurement>& measurements, int reps) {
  std::vector<Samples> samples(measurements.size());
  for (int round = -1; round < reps; ++round) {  // round -1: warm-up
    for (std::size_t m = 0; m < measurements.size(); ++m) {
      const Sample sample = measurements[m]();
      if (round < 0) continue;
      samples[m].seconds.push_back(sample.wall);
      samples[m].cpuSeconds.push_back(sample.cpu);
    }
  }
  return samples;
}

Measurement processMeasurement(std::vector<std::string> argv) {
  return [argv = std::move(argv)] {
    const ProcessRun run = runProcess(argv);
    if (run.exitCode != 0)
      throw std::runtime_error(fmt::format("`{}` failed (exit {})", commandLine(argv), run.exitCode));
    return Sample{run.seconds, run.cpuSeconds};
  };
}

long selfPeakRssKiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

long peakRssKiBByGnuTime(const std::string& workDir, const std::vector<std::string>& argv, int exitCode) {
  const std::string report = workDir + "/peak-rss.txt";
  std::vector<std::string> timed{kGnuTime, "-f", "%M", "-o", report};
  timed.insert(timed.end(), argv.begin(), argv.end());
  const ProcessRun run = runProcess(timed);
  if (run.exitCode != exitCode)
    throw std::runtime_error(fmt::format("{} exited {}, not {}", argv.front(), run.exitCode, exitCode));
  return gnuTimePeakKiB(report);
}

long gnuTimePeakKiB(const std::string& report) {
  // The last line: GNU time writes "Command exited with non-zero status N" before it.
  std::ifstream in(report);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  long kib = 0;
  try {
    kib = std::stol(last);
  } catch (const std::exception&) {
    kib = 0;
  }
  if (kib <= 0) throw std::runtime_error("GNU time (/usr/bin/time) wrote no peak RSS to " + report);
  return kib;
}

}  // namespace rs::bench
