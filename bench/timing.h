// Timing for the benchmark driver: wall time (std::chrono::steady_clock) of
// repeated runs, summarised as best (minimum) and median, with the CPU time
// beside it; child processes spawned with posix_spawn and reaped with wait4
// (for their exit status, CPU time and peak RSS).
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace rs::bench {

/// One run: wall seconds, and CPU seconds (user + system) it used. On a
/// loaded machine wall time includes waiting for a core; CPU time does not.
struct Sample {
  double wall = 0;
  double cpu = 0;
};

/// Repetitions of the same measurement.
struct Samples {
  std::vector<double> seconds;     // wall
  std::vector<double> cpuSeconds;  // CPU, same order
  double best() const;             // minimum wall: the least disturbed run
  double median() const;           // middle wall value (mean of the two middle ones)
  double cpuBest() const;          // minimum CPU time
};

/// Measures in-process work: started at construction, read by stop().
class Stopwatch {
 public:
  Stopwatch();
  Sample stop() const;

 private:
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

/// One finished child process.
struct ProcessRun {
  double seconds = 0;     // wall time from spawn to reaped
  double cpuSeconds = 0;  // user + system time of the child
  int exitCode = -1;      // -1 when it did not exit normally (signal)
  long maxRssKiB = 0;     // peak resident set size, as wait4 reports it (below)
};

// About ProcessRun::maxRssKiB: posix_spawn's child shares the driver's
// memory until it calls exec, and Linux then records that memory's peak as
// the child's. wait4 thus reports max(child's peak, driver's peak so far):
// it is the child's own only when larger than selfPeakRssKiB() was.
long selfPeakRssKiB();

/// The child's own peak RSS in KiB, as GNU time (/usr/bin/time, Debian's
/// `time`) reads it with wait4 from a child it forked itself (so not
/// raised to this driver's, as ProcessRun::maxRssKiB is). Its report goes
/// to a file in `workDir`. Throws when the command does not exit with
/// `exitCode` or GNU time reports nothing.
inline constexpr const char* kGnuTime = "/usr/bin/time";
long peakRssKiBByGnuTime(const std::string& workDir, const std::vector<std::string>& argv, int exitCode);
/// The peak RSS that `/usr/bin/time -f %M -o REPORT` wrote, in KiB; throws if none.
long gnuTimePeakKiB(const std::string& report);

/// Runs argv[0] (searched in PATH when it has no slash) with stdin, stdout
/// and stderr on /dev/null and waits for it. Throws std::runtime_error when
/// it cannot be spawned.
ProcessRun runProcess(const std::vector<std::string>& argv);

/// One measurement: runs once and returns its times.
using Measurement = std::function<Sample()>;

/// Runs one untimed warm-up round (page cache, dynamic loader, allocator),
/// then `reps` rounds that each run every measurement once, in order. On a
/// shared, noisy machine a change of load then hits all of them alike, so
/// their ratios hold better than their absolute times. Returns one Samples
/// per measurement.
std::vector<Samples> interleave(const std::vector<Measurement>& measurements, int reps);

/// A measurement that runs a process (runProcess) and throws
/// std::runtime_error, naming the command, if it exits non-zero: a benchmark
/// must not silently time a failure.
Measurement processMeasurement(std::vector<std::string> argv);

}  // namespace rs::bench
