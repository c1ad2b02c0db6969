// robotsim_bench: the driver behind `make bench`. Prints readable figures
// and, with --json FILE, writes them as one JSON object. See bench/README.md
// and docs/performance.md.
#include <fmt/format.h>
#include <sys/utsname.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>

#include "base/file_io.h"
#include "bench/bench_args.h"
#include "bench/benchmarks.h"

namespace {

using rs::bench::Options;

constexpr std::string_view kModes[] = {"memory", "testrun", "dispatch", "compile",  "startup",    "snapshot",
                                       "test",   "errors",  "lsp",      "lsp_runs", "lsp_format", "debug", "moves", "cell", "devices", "robots", "cell_debug"};

constexpr std::string_view kUsage =
    "usage: robotsim_bench [--reps N] [--smoke] [--json FILE]\n"
    "                      [--only memory|testrun|dispatch|compile|startup|snapshot|test|errors|lsp|lsp_runs|lsp_format|debug|moves|cell|devices|robots|cell_debug]\n"
    "                      [--robotsim PATH] [--lua PATH] [--luajit PATH] [--luac PATH] [--workdir DIR]\n"
    "The benchmarks of docs/performance.md: prints their figures, and writes them to FILE as JSON.\n"
    "  --reps N      repetitions of each measurement, best and median printed (default 5)\n"
    "  --smoke       the smallest sizes: checks that every benchmark runs and prints (the test suite's\n"
    "                bench-smoke tests); the figures then measure nothing\n"
    "  --only MODE   one benchmark instead of all\n"
    "  --robotsim, --lua, --luajit, --luac   the programs compared (default: found in PATH; a peer that\n"
    "                cannot be run is skipped, and the output says so)\n"
    "  --workdir DIR where the generated inputs are written (default bench-work)\n";

std::string firstLine(const std::string& path, std::string_view prefix = {}) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (!line.starts_with(prefix)) continue;
    const std::size_t colon = prefix.empty() ? std::string::npos : line.find(':');
    return colon == std::string::npos ? line : line.substr(line.find_first_not_of(" \t", colon + 1));
  }
  return "unknown";
}

nlohmann::json machine() {
  utsname u{};
  uname(&u);
  return {{"cpus", std::thread::hardware_concurrency()},
          {"cpu_model", firstLine("/proc/cpuinfo", "model name")},
          {"kernel", u.release},
          {"compiler", __VERSION__}};
}

std::string loadAverage() { return firstLine("/proc/loadavg"); }

// Returns false (after printing why) on a bad command line.
bool parse(int argc, char** argv, Options& o, std::string& only) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--smoke") {
      o.smoke = true;
      continue;
    }
    if (i + 1 >= argc) {
      std::cerr << "robotsim_bench: error: " << arg << (arg.starts_with("--") ? " needs a value\n" : " is not an option\n");
      return false;
    }
    const std::string value = argv[++i];
    if (arg == "--reps") {
      const std::optional<long> n = rs::bench::parseCount(value);
      if (!n || *n > 1000) {
        std::cerr << "robotsim_bench: error: --reps takes a whole number from 1 to 1000, not '" << value << "'\n";
        return false;
      }
      o.reps = static_cast<int>(*n);
    } else if (arg == "--json") {
      o.jsonPath = value;
    } else if (arg == "--only") {
      only = value;
    } else if (arg == "--robotsim") {
      o.robotsim = value;
    } else if (arg == "--lua") {
      o.lua = value;
    } else if (arg == "--luajit") {
      o.luajit = value;
    } else if (arg == "--luac") {
      o.luac = value;
    } else if (arg == "--workdir") {
      o.workDir = value;
    } else {
      std::cerr << "robotsim_bench: error: unknown option " << arg << "\n";
      return false;
    }
  }
  if (!only.empty() && std::find(std::begin(kModes), std::end(kModes), only) == std::end(kModes)) {
    std::cerr << "robotsim_bench: error: --only takes memory, testrun, dispatch, compile, startup, snapshot, test, "
                 "errors, lsp, lsp_runs, lsp_format, debug, moves, cell, devices, robots or cell_debug, not '"
              << only << "'\n";
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::string only;
  if (argc == 2 && (std::string_view(argv[1]) == "-h" || std::string_view(argv[1]) == "--help")) {
    std::cout << kUsage;
    return 0;
  }
  if (!parse(argc, argv, options, only)) {
    std::cerr << kUsage;
    return 2;
  }
  nlohmann::json summary = {{"machine", machine()}, {"reps", options.reps}, {"load_start", loadAverage()}};
  summary["smoke"] = options.smoke;
  fmt::print("robotsim_bench: wall time, best (minimum) and median of {} repetitions{}\n", options.reps,
             options.smoke ? " (--smoke: the smallest sizes, the figures measure nothing)" : "");
  fmt::print("machine: {} CPUs, {}, Linux {}, built by {}\n", summary["machine"]["cpus"].get<unsigned>(),
             summary["machine"]["cpu_model"].get<std::string>(), summary["machine"]["kernel"].get<std::string>(),
             summary["machine"]["compiler"].get<std::string>());
  fmt::print("load average at start: {}\n", loadAverage());
  try {
    if (only.empty() || only == "memory") summary["memory"] = rs::bench::benchMemory(options);
    if (only.empty() || only == "testrun") summary["testrun"] = rs::bench::benchTestRun(options);
    if (only.empty() || only == "dispatch") summary["dispatch"] = rs::bench::benchDispatch(options);
    if (only.empty() || only == "compile") summary["compile"] = rs::bench::benchCompile(options);
    if (only.empty() || only == "startup") summary["startup"] = rs::bench::benchStartup(options);
    if (only.empty() || only == "snapshot") summary["snapshot"] = rs::bench::benchSnapshot(options);
    if (only.empty() || only == "test") summary["test"] = rs::bench::benchTestSuite(options);
    if (only.empty() || only == "errors") summary["errors"] = rs::bench::benchErrors(options);
    if (only.empty() || only == "lsp") summary["lsp"] = rs::bench::benchLsp(options);
    if (only.empty() || only == "lsp_runs") summary["lsp_runs"] = rs::bench::benchLspRuns(options);
    if (only.empty() || only == "lsp_format") summary["lsp_format"] = rs::bench::benchLspFormat(options);
    if (only.empty() || only == "debug") summary["debug"] = rs::bench::benchDebug(options);
    if (only.empty() || only == "moves") summary["moves"] = rs::bench::benchMoves(options);
    if (only.empty() || only == "cell") summary["cell"] = rs::bench::benchCell(options);
    if (only.empty() || only == "devices") summary["devices"] = rs::bench::benchDevices(options);
    if (only.empty() || only == "robots") summary["robots"] = rs::bench::benchRobots(options);
    if (only.empty() || only == "cell_debug") summary["cell_debug"] = rs::bench::benchCellDebug(options);
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::cerr << "robotsim_bench: error: " << e.what() << "\n";
    return 1;
  }
  summary["load_end"] = loadAverage();
  fmt::print("\nload average at end: {}\n", loadAverage());
  if (!options.jsonPath.empty()) {
    std::string error;
    if (!rs::base::writeFileAtomically(options.jsonPath, summary.dump(2) + "\n", error)) {
      std::cerr << "robotsim_bench: error: cannot write " << options.jsonPath << ": " << error << "\n";
      return 1;
    }
    fmt::print("summary written to {}\n", options.jsonPath);
  }
  return 0;
}
