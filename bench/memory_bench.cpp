// Compile memory (benchMemory): the peak RSS of `robotsim compile` on
// programs whose every line is the same short kind, the cases where
// per-line bookkeeping weighs most against the source, at two sizes. The
// growth between them, per source byte, is what a program costs beyond the
// process's fixed part; the whole peak over the size is what a user sees.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_support.h"

namespace rs::bench {

using nlohmann::json;

namespace {

struct MemoryCase {
  std::string label;
  std::string what;
  std::function<std::string(std::size_t)> line;  // line i (0-based), with its '\n'
  std::string last;                              // after the lines ("" or a closing line)
  int exitCode = 0;                              // 2: a program with errors
};

struct MemoryPoint {
  std::size_t lines = 0;
  std::uintmax_t bytes = 0;
  long maxRssKiB = 0;
};

// Written line by line, so that the driver stays small (its peak is no
// longer in the measure: GNU time forks the compile, timing.h).
std::string writeCase(const Options& options, const MemoryCase& c, std::size_t lines) {
  const auto path = std::filesystem::path(options.workDir) / fmt::format("memory-{}-{}.rsp", c.label, lines);
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  for (std::size_t i = 0; i < lines; ++i) out << c.line(i);
  out << c.last;
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return path.string();
}

MemoryPoint measureCase(const Options& options, const MemoryCase& c, std::size_t lines) {
  const std::string path = writeCase(options, c, lines);
  const std::string image = (std::filesystem::path(options.workDir) / "memory.rsb").string();
  const long peakKiB = peakRssKiBByGnuTime(options.workDir, {options.robotsim, "compile", path, "-o", image}, c.exitCode);
  MemoryPoint p{lines, std::filesystem::file_size(path), peakKiB};
  std::filesystem::remove(path);
  return p;
}

}  // namespace

json benchMemory(const Options& options) {
  fmt::print("\n[0] Compile memory: peak RSS of robotsim compile on programs of one short kind of line\n");
  const std::vector<MemoryCase> cases = {
      {"end", "END", [](std::size_t) { return std::string("END\n"); }, "", 0},
      {"moves", "MOVE 1 1 1 1 1", [](std::size_t) { return std::string("MOVE 1 1 1 1 1\n"); }, "", 0},
      {"labels", "lN: END", [](std::size_t i) { return fmt::format("l{}: END\n", i); }, "", 0},
      {"jumps", "lN: GOTO lN+1", [](std::size_t i) { return fmt::format("l{}: GOTO l{}\n", i, i + 1); }, "", 0},
      {"errors", "x (an unknown instruction)", [](std::size_t) { return std::string("x\n"); }, "", 2},
  };
  const std::size_t fewerLines = sized<std::size_t>(options, 1'000'000, 1'000), moreLines = 2 * fewerLines;
  progress("a one-line program: the process's fixed part");
  const MemoryCase one{"one", "END", [](std::size_t) { return std::string("END\n"); }, "", 0};
  const MemoryPoint floor = measureCase(options, one, 1);
  fmt::print("  one line: {:.1f} MiB (the fixed part: code, libraries, allocator)\n",
             static_cast<double>(floor.maxRssKiB) / 1024);
  json out = {{"fixed_kib", floor.maxRssKiB}, {"cases", json::array()}, {"target_growth_per_byte", 5.0}};
  bool allMet = true;
  for (const MemoryCase& c : cases) {
    progress(fmt::format("{} and {} lines of '{}'", fewerLines, moreLines, c.what));
    // The jumps' last target must exist: the program ends on that label.
    MemoryCase ofSize = c;
    const auto measure = [&](std::size_t n) {
      if (c.label == "jumps") ofSize.last = fmt::format("l{}: END\n", n);
      return measureCase(options, ofSize, n);
    };
    const MemoryPoint small = measure(fewerLines), large = measure(moreLines);
    const double growth = static_cast<double>(large.maxRssKiB - small.maxRssKiB) * 1024 /
                          static_cast<double>(large.bytes - small.bytes);
    const double whole = static_cast<double>(large.maxRssKiB) * 1024 / static_cast<double>(large.bytes);
    allMet = allMet && growth <= 5.0;
    fmt::print("  {:<28} {:>5.1f} MB: {:6.1f} MiB, {:5.2f}x the source; growth {}\n", c.what,
               static_cast<double>(large.bytes) / 1e6, static_cast<double>(large.maxRssKiB) / 1024, whole,
               verdict(growth, 5.0));
    out["cases"].push_back({{"label", c.label},
                            {"line", c.what},
                            {"small", {{"lines", small.lines}, {"bytes", small.bytes}, {"max_rss_kib", small.maxRssKiB}}},
                            {"large", {{"lines", large.lines}, {"bytes", large.bytes}, {"max_rss_kib", large.maxRssKiB}}},
                            {"growth_per_byte", growth},
                            {"whole_over_source", whole}});
  }
  fmt::print("  growth = (peak at {} lines - peak at {}) / (their size difference): bytes of memory a source byte\n",
             moreLines, fewerLines);
  out["target_met"] = allMet;
  return out;
}

}  // namespace rs::bench
