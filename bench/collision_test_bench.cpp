// collision_bench's test part: what grading costs with collisions on.
// The example programs of the top of examples/ (with their stimuli files)
// copied into folders until there are 1,000 programs, then one `robotsim
// test DIR -j 2` process with collisions (the default) and one with
// --collisions=off, interleaved; every test must pass. Target: 1 s with
// collisions on.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "bench/collision_runs.h"
#include "bench/timing.h"

namespace rs::bench {

namespace fs = std::filesystem;

namespace {

// Copies the examples into `dir` until it holds `wanted` programs; returns
// how many it holds.
int copyExamples(const fs::path& dir, int wanted) {
  std::vector<fs::path> programs, others;
  for (const fs::directory_entry& e : fs::directory_iterator(fs::path(ROBOTSIM_SOURCE_DIR) / "examples")) {
    if (!e.is_regular_file()) continue;
    if (e.path().extension() == ".rsp") programs.push_back(e.path());
    if (e.path().extension() == ".stim") others.push_back(e.path());
  }
  if (programs.empty()) throw std::runtime_error("no example programs in " ROBOTSIM_SOURCE_DIR "/examples");
  std::sort(programs.begin(), programs.end());
  fs::remove_all(dir);
  int count = 0;
  for (int copy = 0; count < wanted; ++copy) {
    const fs::path to = dir / fmt::format("copy{:03}", copy);
    fs::create_directories(to);
    for (const fs::path& p : others) fs::copy_file(p, to / p.filename());
    for (const fs::path& p : programs) {
      if (count == wanted) break;
      fs::copy_file(p, to / p.filename());
      ++count;
    }
  }
  return count;
}

}  // namespace

void benchTestExamples(const CollisionBenchOptions& options) {
  const int wanted = options.smoke ? 12 : 1000;
  const fs::path dir = fs::path(options.workDir) / "examples";
  const int programs = copyExamples(dir, wanted);
  fmt::print("\nrobotsim test -j 2 on {} copies of the example programs (examples/*.rsp), whole process, best of {}\n",
             programs, options.reps);
  const std::vector<Samples> s = interleave(
      {processMeasurement({options.robotsim, "test", dir.string(), "-j", "2"}),
       processMeasurement({options.robotsim, "test", dir.string(), "-j", "2", "--collisions=off"})},
      options.reps);
  fmt::print("  --collisions=error  {:8.1f} ms wall (median {:.1f}), {:8.1f} ms CPU\n", s[0].best() * 1e3,
             s[0].median() * 1e3, s[0].cpuBest() * 1e3);
  fmt::print("  --collisions=off    {:8.1f} ms wall (median {:.1f}), {:8.1f} ms CPU\n", s[1].best() * 1e3,
             s[1].median() * 1e3, s[1].cpuBest() * 1e3);
  fmt::print("  ratio {:.2f} (wall), {:.2f} (CPU); target: 1 s wall with collisions\n", s[0].best() / s[1].best(),
             s[0].cpuBest() / s[1].cpuBest());
}

}  // namespace rs::bench
