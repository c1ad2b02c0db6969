// The description reader's speed on device lines (issue 35, `--only
// devices`): a workcell of 100,000 device and wire lines, all valid (40,000
// sensors, 30,000 sinks, 29,992 feeders, 8 wires), and one of 50,000
// sensors and 50,000 wires where every wire past the eighth is a second
// source (49,992 errors). Each read in-process (Library::workcell, as
// `check` and the language server do) and through `robotsim describe`, a
// process. Target: under 1 s of CPU for each.
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "compiler/description/library.h"

namespace rs::bench {
namespace {

// A part to feed and a fixture 1000 x 1000 (its top y 10) that the devices
// stand over, so every sensor and sink is in the cell.
constexpr const char* kObjects =
    "OBJECT blk\n  PART\n  BOX 0 10 10 0 10 0\nEND\n"
    "OBJECT table\n  BOX 0 1000 10 0 1000 0\nEND\n";

std::string validCell(int lines) {
  const int sensors = lines * 2 / 5, sinks = lines * 3 / 10, feeders = lines - sensors - sinks - 8;
  std::string text = std::string(kObjects) + "WORKCELL devices\n  OBJECT table AT 0 0 1000\n";
  for (int i = 0; i < sensors; ++i) {
    const int x = i % 99 * 10, z = i / 99 % 99 * 10;
    if (i % 2 == 0) text += fmt::format("  SENSOR s{} ZONE {} {} 30 10 {} {}\n", i, x, x + 10, z + 10, z);
    else text += fmt::format("  SENSOR s{} BEAM {} 15 {}  {} 15 {}\n", i, x, z, x + 10, z);
  }
  for (int i = 0; i < sinks; ++i) text += fmt::format("  SINK k{} ZONE {} {} 40 10 {} {}\n", i, i % 99 * 10, i % 99 * 10 + 10, 1000, 990);
  for (int i = 0; i < feeders; ++i) text += fmt::format("  FEEDER f{} blk AT {} 10 {} EVERY 5 COUNT 1\n", i, i % 99 * 10, 20);
  for (int n = 1; n <= 8; ++n) text += fmt::format("  WIRE s{} TO IN {}\n", n, n);
  return text + "END\n";
}

// As tests/models/test_description_devices.cpp's: half sensors, half wires,
// each input wired again and again.
std::string erroneousCell(int lines) {
  const int each = lines / 2;
  std::string text = std::string(kObjects) + "WORKCELL devices\n  OBJECT table AT 0 0 1000\n";
  for (int i = 0; i < each; ++i) text += fmt::format("  SENSOR s{} ZONE 0 10 20 10 10 0\n", i);
  for (int i = 0; i < each; ++i) text += fmt::format("  WIRE s{} TO IN {}\n", each - 1 - i, i % 8 + 1);
  return text + "END\n";
}

// Library::workcell on the file: a fresh library each time, as a command has.
Measurement inProcess(const std::string& path, bool valid, std::size_t errors) {
  return [path, valid, errors] {
    compiler::Library library(compiler::librarySearchPath({}));
    const Stopwatch clock;
    const bool read = library.workcell(path).has_value();
    const Sample sample = clock.stop();
    if (read != valid || library.diagnostics().size() != errors)
      throw std::runtime_error(fmt::format("{}: read {}, {} diagnostics (expected {})", path, read,
                                           library.diagnostics().size(), errors));
    return sample;
  };
}

// `robotsim describe FILE`, which exits 2 on a cell with errors.
Measurement describe(const Options& options, const std::string& path, int exitCode) {
  return [argv = std::vector<std::string>{options.robotsim, "describe", path}, exitCode] {
    const ProcessRun run = runProcess(argv);
    if (run.exitCode != exitCode)
      throw std::runtime_error(fmt::format("robotsim describe {} exited {}, not {}", argv[2], run.exitCode, exitCode));
    return Sample{run.seconds, run.cpuSeconds};
  };
}

}  // namespace

nlohmann::json benchDevices(const Options& options) {
  const int lines = sized(options, 100'000, 1'000);
  fmt::print("\n[devices] The description reader on {} device and wire lines\n", lines);
  const std::string valid = writeInput(options, "devices_valid.rsd", validCell(lines));
  const std::string erroneous = writeInput(options, "devices_errors.rsd", erroneousCell(lines));
  const std::size_t errors = static_cast<std::size_t>(lines / 2 - 8);
  progress(fmt::format("interleaved, 1 warm-up + {} rounds: in-process and robotsim describe, valid and with {} errors",
                       options.reps, errors));
  const std::vector<Samples> s = interleave({inProcess(valid, true, 0), inProcess(erroneous, false, errors),
                                             describe(options, valid, 0), describe(options, erroneous, 2)},
                                            options.reps);
  row("in-process, valid", s[0]);
  row(fmt::format("in-process, {} errors", errors), s[1]);
  row("robotsim describe, valid", s[2]);
  row(fmt::format("robotsim describe, {} errors", errors), s[3]);
  double worst = 0;
  for (const Samples& each : s) worst = std::max(worst, each.cpuBest());
  fmt::print("  slowest of the four, CPU seconds: {}\n", verdict(worst, 1.0));
  return {{"lines", lines},
          {"errors", errors},
          {"in_process_valid", toJson(s[0])},
          {"in_process_errors", toJson(s[1])},
          {"describe_valid", toJson(s[2])},
          {"describe_errors", toJson(s[3])},
          {"cpu_worst_s", worst}};
}

}  // namespace rs::bench
