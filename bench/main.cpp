// robotsim_bench: the driver behind `make bench`. Prints readable figures
// and, with --json FILE, writes them as one JSON object. See bench/README.md
// and docs/performance.md.
#include <fmt/format.h>
#include <sys/utsname.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>

#include "bench/benchmarks.h"

namespace {

using rs::bench::Options;

constexpr std::string_view kUsage =
    "usage: robotsim_bench [--reps N] [--json FILE]\n"
    "                      [--only memory|testrun|dispatch|compile|startup|snapshot|test|errors|lsp|lsp_runs|lsp_format|debug]\n"
    "                      [--robotsim PATH] [--lua PATH] [--luac PATH] [--workdir DIR]\n";

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
    if (i + 1 >= argc) {
      std::cerr << "robotsim_bench: " << arg << " needs a value\n";
      return false;
    }
    const std::string value = argv[++i];
    if (arg == "--reps")
      o.reps = std::atoi(value.c_str());
    else if (arg == "--json")
      o.jsonPath = value;
    else if (arg == "--only")
      only = value;
    else if (arg == "--robotsim")
      o.robotsim = value;
    else if (arg == "--lua")
      o.lua = value;
    else if (arg == "--luac")
      o.luac = value;
    else if (arg == "--workdir")
      o.workDir = value;
    else {
      std::cerr << "robotsim_bench: unknown option " << arg << "\n";
      return false;
    }
  }
  if (o.reps < 1) {
    std::cerr << "robotsim_bench: --reps must be at least 1\n";
    return false;
  }
  if (!only.empty() && only != "memory" && only != "testrun" && only != "dispatch" && only != "compile" &&
      only != "startup" && only != "snapshot" && only != "test" && only != "errors" && only != "lsp" &&
      only != "lsp_runs" && only != "lsp_format" && only != "debug") {
    std::cerr << "robotsim_bench: --only takes memory, testrun, dispatch, compile, startup, snapshot, test, errors, lsp, "
                 "lsp_runs, lsp_format or debug\n";
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
  fmt::print("robotsim_bench: wall time, best (minimum) and median of {} repetitions\n", options.reps);
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
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::cerr << "robotsim_bench: error: " << e.what() << "\n";
    return 1;
  }
  summary["load_end"] = loadAverage();
  fmt::print("\nload average at end: {}\n", loadAverage());
  if (!options.jsonPath.empty()) {
    std::ofstream out(options.jsonPath, std::ios::trunc);
    out << summary.dump(2) << "\n";
    if (!out.flush()) {
      std::cerr << "robotsim_bench: error: cannot write " << options.jsonPath << "\n";
      return 1;
    }
    fmt::print("summary written to {}\n", options.jsonPath);
  }
  return 0;
}
