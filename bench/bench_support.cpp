#include "bench/bench_support.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace rs::bench {

void progress(std::string_view what) {
  fmt::print("  ... {}\n", what);
  std::fflush(stdout);
}

std::string millis(double seconds) { return fmt::format("{:9.2f} ms", seconds * 1e3); }

void row(std::string_view what, const Samples& s, std::string_view extra) {
  fmt::print("  {:<40} best {}  median {}  [cpu {}]{}{}\n", what, millis(s.best()), millis(s.median()),
             millis(s.cpuBest()), extra.empty() ? "" : "  ", extra);
}

std::string verdict(double ratio, double target) {
  const std::string outcome =
      ratio <= target ? std::string("met") : fmt::format("missed by {:.0f}%", (ratio / target - 1) * 100);
  return fmt::format("{:.2f} (target <= {}: {})", ratio, target, outcome);
}

nlohmann::json toJson(const Samples& s) {
  return {{"best_s", s.best()},
          {"median_s", s.median()},
          {"cpu_best_s", s.cpuBest()},
          {"samples_s", s.seconds},
          {"cpu_samples_s", s.cpuSeconds}};
}

std::string writeInput(const Options& options, const std::string& name, const std::string& text) {
  std::filesystem::create_directories(options.workDir);
  const std::string path = (std::filesystem::path(options.workDir) / name).string();
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!file.flush()) throw std::runtime_error("cannot write " + path);
  return path;
}

vm::Image compileOrThrow(const diag::SourceFile& source, const compiler::Target& target) {
  compiler::CompileResult result = compiler::compile(source, target);
  if (!result.ok()) {
    const std::string first = result.diagnostics.empty() ? "no diagnostic" : result.diagnostics.front().message;
    throw std::runtime_error(fmt::format("{} did not compile: {}", source.name(), first));
  }
  return std::move(*result.image);
}

std::size_t slotOf(const vm::Image& image, std::string_view name) {
  for (std::size_t i = 0; i < image.variables.size(); ++i)
    if (image.variables[i] == name) return i;
  throw std::runtime_error(fmt::format("no variable {} in the image", name));
}

bool canRun(const std::vector<std::string>& argv) {
  try {
    return runProcess(argv).exitCode == 0;
  } catch (const std::runtime_error&) {
    return false;
  }
}

ProcessRun runLspSession(const Options& options, const std::string& sessionPath, const std::string& replyPath) {
  const std::string report = options.workDir + "/lsp_peak.txt";
  ProcessRun run = runProcess({"sh", "-c",
                               fmt::format("exec {} -f %M -o '{}' '{}' lsp < '{}' > '{}'", kGnuTime, report,
                                           options.robotsim, sessionPath, replyPath)});
  if (run.exitCode != 0) throw std::runtime_error("robotsim lsp did not exit 0 on the session " + sessionPath);
  run.maxRssKiB = gnuTimePeakKiB(report);
  return run;
}

}  // namespace rs::bench
