// urdf_bench: what a too-large URDF file costs (issue 37: "a 100 MB URDF"
// is an error, never a hang). The reader refuses a file over 64 MiB by its
// size, before a byte is read (model/urdf/urdf_read.h): here a sparse file
// of 100,000,000 bytes refused in this process (readUrdfFile) and through
// the helper program robotsim-urdf (readUrdfInHelper, the command's path),
// beside the reading of a small arm (tests/urdf/data_read/ur5_dh.urdf) for
// scale; best and median of N runs. Target: the refusal within 50 ms
// through the helper. Figures in docs/performance.md. Not a test: it prints
// numbers (the refusal itself is tested in tests/urdf/).
//
//   urdf_bench [--smoke] [REPS]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_args.h"
#include "model/urdf/urdf_read.h"
#include "model/urdf/urdf_read_remote.h"

namespace {

using Clock = std::chrono::steady_clock;

// Best and median of `reps` runs of f, in milliseconds; f says whether it
// gave what it should (else the figure is not printed as a measurement).
template <typename F>
double measure(const std::string& what, int reps, F&& f) {
  std::vector<double> times;
  for (int r = 0; r < reps; ++r) {
    const auto start = Clock::now();
    if (!f()) {
      fmt::print("  {}: did not give what it should\n", what);
      std::exit(1);
    }
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  fmt::print("  {:<52} best {:>9.3f} ms   median {:>9.3f} ms\n", what, times.front(), times[times.size() / 2]);
  return times[times.size() / 2];
}

bool refused(const rs::urdf::UrdfRead& read) {
  return !read.robot && read.diagnostics.size() == 1 && read.diagnostics[0].code == "urdf-size";
}

}  // namespace

constexpr rs::bench::CountArgument kUrdfCounts[] = {{"REPS", "runs (best and median printed)", 9, 1}};

int main(int argc, char** argv) {
  const rs::bench::BenchArguments args = rs::bench::parseBenchArguments(
      argc, argv, "urdf_bench", "the refusal of a 100 MB URDF file beside reading a small arm (docs/performance.md).",
      kUrdfCounts);
  if (args.exitCode) return *args.exitCode;
  const int reps = static_cast<int>(args[0]);
  namespace fs = std::filesystem;
  const fs::path big = fs::temp_directory_path() / fmt::format("robotsim-urdf-bench-{}.urdf", ::getpid());
  {
    std::ofstream out(big, std::ios::binary);
    out << "<robot name=\"big\">\n";
  }
  fs::resize_file(big, 100'000'000);  // sparse: the size without the bytes
  const fs::path ur5 = fs::path(ROBOTSIM_SOURCE_DIR) / "tests/urdf/data_read/ur5_dh.urdf";
  fmt::print("URDF reading, best and median of {}\n", reps);
  measure("100 MB URDF refused, in this process", reps, [&] { return refused(rs::urdf::readUrdfFile(big, {})); });
  const double helped = measure("100 MB URDF refused, through robotsim-urdf", reps,
                                [&] { return refused(rs::urdf::readUrdfInHelper(big, {})); });
  measure("ur5_dh.urdf read, through robotsim-urdf", reps,
          [&] { return rs::urdf::readUrdfInHelper(ur5, {}).robot.has_value(); });
  fs::remove(big);
  fmt::print("  target <= 50 ms for the refusal through the helper (median): {}\n", helped <= 50 ? "met" : "missed");
  return 0;
}
