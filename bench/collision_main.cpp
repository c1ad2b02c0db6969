// Collision benchmark (issues 14 and 23), `collision_bench`, run by `make
// bench`; figures go to docs/performance.md ("Collisions"):
//  - gjk: robotsim's own GJK on point hulls (model/workcell/gjk.h) against
//    libfcl 0.7 (Debian's libfcl-dev, when found at configure time) on the
//    same random box pairs;
//  - sweep: the swept check of a whole run, a SCARA program over the whole
//    range on scara-pick: poses checked and the time of each move, answered
//    from memory and swept afresh;
//  - runs: the targets of issue 23, a run with --collisions=error against
//    the same run with off (CPU time), for a long loop and a long
//    pick-and-place on scara-pick, puma-cell and xr4-cell, and simulated
//    seconds per CPU second (bench/collision_runs.cpp);
//  - test: `robotsim test -j 2` on 1,000 copies of the examples, with
//    collisions and without (needs --robotsim).
#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "bench/collision_runs.h"

namespace {

constexpr const char* kUsage =
    "usage: collision_bench [--smoke] [--reps N] [--only gjk|sweep|runs|test] [--robotsim PATH] [--workdir DIR] [REPS]\n"
    "  --reps N         repetitions of each measurement, best kept (default 5)\n"
    "  --only PART      one part of the benchmark (default: all; test needs --robotsim)\n"
    "  --robotsim PATH  the robotsim binary, for the test part\n"
    "  --workdir DIR    where the test part writes its copies of the examples (default: collision-bench)\n"
    "  --smoke          every part once at a tiny size (for the test suite: it runs and prints)\n";

bool positiveInt(const char* text, int& out) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 1 || v > 1000) return false;
  out = static_cast<int>(v);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  rs::bench::CollisionBenchOptions options;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::cerr << "collision_bench: error: " << arg << " needs a value\n" << kUsage;
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--reps") {
      const char* v = value();
      if (!positiveInt(v, options.reps)) {
        std::cerr << "collision_bench: error: --reps takes a whole number from 1 to 1000, not '" << v << "'\n";
        return 2;
      }
    } else if (arg == "--only") {
      only = value();
      if (only != "gjk" && only != "sweep" && only != "runs" && only != "test") {
        std::cerr << "collision_bench: error: --only takes gjk, sweep, runs or test, not '" << only << "'\n";
        return 2;
      }
    } else if (arg == "--robotsim") {
      options.robotsim = value();
    } else if (arg == "--workdir") {
      options.workDir = value();
    } else if (arg == "--smoke") {
      options.smoke = true;
    } else if (!arg.empty() && arg[0] != '-') {  // the old form: collision_bench REPS
      if (!positiveInt(arg.c_str(), options.reps)) {
        std::cerr << "collision_bench: error: REPS must be a whole number from 1 to 1000, not '" << arg << "'\n"
                  << kUsage;
        return 2;
      }
    } else {
      std::cerr << "collision_bench: error: unknown argument '" << arg << "'\n" << kUsage;
      return 2;
    }
  }
  if (options.smoke) options.reps = 1;
  if (only == "test" && options.robotsim.empty()) {
    std::cerr << "collision_bench: error: --only test needs --robotsim PATH\n";
    return 2;
  }
  try {
    if (only.empty() || only == "gjk") rs::bench::benchGjk(options);
    if (only.empty() || only == "sweep") rs::bench::benchSweep(options);
    if (only.empty() || only == "runs") rs::bench::benchWorkcellRuns(options);
    if ((only.empty() && !options.robotsim.empty()) || only == "test") rs::bench::benchTestExamples(options);
  } catch (const std::exception& e) {
    std::cerr << "collision_bench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
