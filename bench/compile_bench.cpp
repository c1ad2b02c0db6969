// The compiler's benchmarks: throughput on large programs (benchCompile)
// and programs full of errors (benchErrors), in-process and as processes.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "bench/bench_support.h"
#include "bench/generate.h"
#include "compiler/program/compiler.h"
#include "launch/program.h"
#include "vm/image_file.h"

namespace rs::bench {

using nlohmann::json;

namespace {

// --- 2. compile throughput ----------------------------------------------------------

struct SizeResult {
  std::string label;
  GeneratedProgram program;
  std::string path;
  Samples inProcess;
  Samples process;
  long maxRssKiB = 0;       // of one `robotsim compile` run
  bool rssIsChild = false;  // false: no larger than the driver's own peak
  std::size_t imageBytes = 0;
};

std::vector<std::string> compileCommand(const Options& options, const SizeResult& r) {
  const auto out = std::filesystem::path(options.workDir) / fmt::format("compile-{}.rsb", r.label);
  return {options.robotsim, "compile", r.path, "-o", out.string()};
}

// Generates and writes the program, then runs `robotsim compile` on it once
// for its peak RSS, before the driver itself has compiled anything that big:
// wait4 reports the larger of the child's peak and the driver's (see
// ProcessRun), so the driver must still be small here.
SizeResult prepareSize(const Options& options, std::string label, std::size_t instructions) {
  SizeResult r{std::move(label), robotProgram(instructions), {}, {}, {}, 0, false, 0};
  r.path = writeInput(options, fmt::format("compile-{}.rsp", r.label), r.program.text);
  progress(fmt::format("{} instructions: one robotsim compile for its peak RSS", instructions));
  const ProcessRun run = runProcess(compileCommand(options, r));
  if (run.exitCode != 0)
    throw std::runtime_error(fmt::format("robotsim compile {} failed (exit {})", r.path, run.exitCode));
  r.maxRssKiB = run.maxRssKiB;
  r.rssIsChild = run.maxRssKiB > selfPeakRssKiB();
  return r;
}

// compile() in-process (source already in memory) and `robotsim compile`
// as a process, interleaved.
void measureSize(const Options& options, SizeResult& r) {
  const diag::SourceFile source(r.path, r.program.text);
  const compiler::Target target = launch::defaultTarget();
  const vm::Image image = compileOrThrow(source, target);
  if (image.code.size() != r.program.instructions)
    throw std::runtime_error(
        fmt::format("{}: {} instructions compiled, expected {}", r.path, image.code.size(), r.program.instructions));
  r.imageBytes = vm::writeImage(image).size();

  const Measurement inProcess = [&] {
    const Stopwatch clock;
    const compiler::CompileResult result = compiler::compile(source, target);
    const Sample sample = clock.stop();
    if (!result.ok()) throw std::runtime_error(r.path + " stopped compiling");
    return sample;  // the image is freed after the clock stopped
  };
  progress(fmt::format(
      "{} instructions ({} lines, {:.1f} MB), 1 warm-up + {} rounds: compile() in-process, "
      "robotsim compile (process)",
      r.program.instructions, r.program.lines, static_cast<double>(r.program.text.size()) / 1e6, options.reps));
  const std::vector<Samples> s = interleave({inProcess, processMeasurement(compileCommand(options, r))}, options.reps);
  r.inProcess = s[0];
  r.process = s[1];
}

std::string perSecond(std::size_t lines, const Samples& s) {
  return fmt::format("{:.2f} M lines/s", static_cast<double>(lines) / s.best() / 1e6);
}

json sizeJson(const SizeResult& r) {
  const double lines = static_cast<double>(r.program.lines);
  return {
      {"label", r.label},
      {"instructions", r.program.instructions},
      {"lines", r.program.lines},
      {"bytes", r.program.text.size()},
      {"in_process", toJson(r.inProcess)},
      {"in_process_lines_per_s", lines / r.inProcess.best()},
      {"process", toJson(r.process)},
      {"process_lines_per_s", lines / r.process.best()},
      {"process_max_rss_kib", r.maxRssKiB},
      {"process_max_rss_is_child", r.rssIsChild},
      {"image_bytes", r.imageBytes},
      {"image_bytes_per_instruction", static_cast<double>(r.imageBytes) / static_cast<double>(r.program.instructions)}};
}

}  // namespace

json benchCompile(const Options& options) {
  fmt::print("\n[2] Compile throughput: generated programs, every instruction kind\n");
  std::vector<SizeResult> sizes;
  // Three sizes ten times apart; --smoke: a thousandth of each.
  const std::size_t scale = sized<std::size_t>(options, 1, 1000);
  sizes.push_back(prepareSize(options, "10k", 10'000 / scale));
  sizes.push_back(prepareSize(options, "100k", 100'000 / scale));
  sizes.push_back(prepareSize(options, "1M", 1'000'000 / scale));
  for (SizeResult& r : sizes) measureSize(options, r);

  json out = {{"sizes", json::array()}};
  for (const SizeResult& r : sizes) {
    row(fmt::format("compile() {:>7} instr, {:>7} lines", r.program.instructions, r.program.lines), r.inProcess,
        perSecond(r.program.lines, r.inProcess));
    row(fmt::format("robotsim compile {:>7} instr (process)", r.program.instructions), r.process,
        perSecond(r.program.lines, r.process));
    out["sizes"].push_back(sizeJson(r));
  }
  const auto growth = [&](const SizeResult& big, const SizeResult& small, bool process) {
    return process ? big.process.best() / small.process.best() : big.inProcess.best() / small.inProcess.best();
  };
  fmt::print(
      "  growth (best, linear = 10): in-process 100k/10k {:.1f}, 1M/100k {:.1f}; "
      "process 100k/10k {:.1f}, 1M/100k {:.1f}\n",
      growth(sizes[1], sizes[0], false), growth(sizes[2], sizes[1], false), growth(sizes[1], sizes[0], true),
      growth(sizes[2], sizes[1], true));
  out["growth"] = {{"in_process_100k_over_10k", growth(sizes[1], sizes[0], false)},
                   {"in_process_1m_over_100k", growth(sizes[2], sizes[1], false)},
                   {"process_100k_over_10k", growth(sizes[1], sizes[0], true)},
                   {"process_1m_over_100k", growth(sizes[2], sizes[1], true)}};

  const SizeResult& big = sizes[2];
  const double perInstr = static_cast<double>(big.imageBytes) / static_cast<double>(big.program.instructions);
  fmt::print("  image: {:.1f} bytes per instruction ({} bytes for {} instructions)\n", perInstr, big.imageBytes,
             big.program.instructions);
  for (const SizeResult& r : sizes)
    fmt::print("  peak RSS of robotsim compile on {:>7} instructions: {:7.1f} MiB{}\n", r.program.instructions,
               static_cast<double>(r.maxRssKiB) / 1024,
               r.rssIsChild ? "" : " (not measurable: no larger than the driver's own peak)");
  out["image_bytes_per_instruction_1m"] = perInstr;
  out["compile_1m_max_rss_kib"] = big.maxRssKiB;

  const SizeResult& mid = sizes[1];
  if (!canRun({options.luac, "-v"})) {
    fmt::print("  luac comparison skipped: cannot run {}\n", options.luac);
    out["luac_skipped"] = true;
    return out;
  }
  const std::string chunk = writeInput(options, "compile-100k.lua", luaChunk(mid.program.lines));
  progress(fmt::format("1 warm-up + {} rounds: robotsim compile 100k and {} -p on {} lines of Lua (processes)",
                       options.reps, options.luac, mid.program.lines));
  const std::vector<Samples> s =
      interleave({processMeasurement(compileCommand(options, mid)), processMeasurement({options.luac, "-p", chunk})},
                 options.reps);
  row(fmt::format("robotsim compile {:>7} lines (process)", mid.program.lines), s[0],
      perSecond(mid.program.lines, s[0]));
  row(fmt::format("luac5.4 -p       {:>7} lines (process)", mid.program.lines), s[1],
      perSecond(mid.program.lines, s[1]));
  // The target (issue 23) is by CPU time: on the shared machine wall
  // time includes waiting for a core, which neither program controls.
  constexpr double kTarget = 1.3;
  const double ratio = s[0].best() / s[1].best(), ratioCpu = s[0].cpuBest() / s[1].cpuBest();
  fmt::print("  ratio robotsim compile / luac -p (CPU)    {}\n", verdict(ratioCpu, kTarget));
  fmt::print("  ratio robotsim compile / luac -p (best)   {:.2f}\n", ratio);
  fmt::print("  ratio robotsim compile / luac -p (median) {:.2f}\n", s[0].median() / s[1].median());
  out["luac_pair"] = {{"lines", mid.program.lines}, {"robotsim", toJson(s[0])}, {"luac", toJson(s[1])}};
  out["ratio_100k_over_luac"] = ratio;
  out["ratio_100k_over_luac_median"] = s[0].median() / s[1].median();
  out["ratio_100k_over_luac_cpu"] = ratioCpu;
  out["target_ratio_cpu"] = kTarget;
  out["target_met"] = ratioCpu <= kTarget;
  return out;
}

// --- 5. Programs full of errors ------------------------------------------------------

namespace {

struct ErrorCase {
  std::string label;
  ErrorProgram program;  // its text freed once written (read back to measure)
  std::size_t bytes = 0;
  std::string path;
  Samples inProcess;
  Samples process;
  std::size_t stderrBytes = 0;  // what robotsim check printed
  long maxRssKiB = 0;           // of one `robotsim check` run
  bool rssIsChild = false;
};

// robotsim check FILE: must exit 2 (the program does not compile).
Measurement checkFails(const Options& options, const std::string& path) {
  return [argv = std::vector<std::string>{options.robotsim, "check", path}] {
    const ProcessRun run = runProcess(argv);
    if (run.exitCode != 2)
      throw std::runtime_error(fmt::format("robotsim check {} exited {}, not 2", argv[2], run.exitCode));
    return Sample{run.seconds, run.cpuSeconds};
  };
}

// What `robotsim check` does with the diagnostics in-process: compile,
// keeping the first 50 (its default --max-errors), and render those.
std::size_t compileAndRender(const diag::SourceFile& source, const compiler::Target& target, std::size_t& errors) {
  const compiler::CompileResult r = compiler::compile(source, target, 50);
  std::string out;
  for (const diag::Diagnostic& d : r.diagnostics) out += diag::render(d, &source);
  out += launch::omittedNote(r.omitted);
  errors = r.diagnostics.size() + r.omitted.errors + r.omitted.warnings;
  return out.size();
}

// Writes the program and runs robotsim check once for its peak RSS (before
// the driver compiled anything large itself: see prepareSize) and the size
// of what it prints (counted in-process: the process's stderr goes to
// /dev/null).
ErrorCase prepareErrors(const Options& options, std::string label, ErrorProgram program) {
  ErrorCase c{std::move(label), std::move(program), 0, {}, {}, {}, 0, 0, false};
  c.bytes = c.program.text.size();
  c.path = writeInput(options, fmt::format("errors-{}.rsp", c.label), c.program.text);
  std::string().swap(c.program.text);  // keeps the driver's peak below the child's
  progress(fmt::format("{}: one robotsim check for its peak RSS", c.label));
  const ProcessRun run = runProcess({options.robotsim, "check", c.path});
  if (run.exitCode != 2)
    throw std::runtime_error(fmt::format("robotsim check {} exited {}, not 2", c.path, run.exitCode));
  c.maxRssKiB = run.maxRssKiB;
  c.rssIsChild = run.maxRssKiB > selfPeakRssKiB();
  return c;
}

void measureErrors(const Options& options, ErrorCase& c) {
  std::ifstream file(c.path, std::ios::binary);
  std::string text(c.bytes, '\0');
  if (!file.read(text.data(), static_cast<std::streamsize>(c.bytes))) throw std::runtime_error("cannot read " + c.path);
  const diag::SourceFile source(c.path, std::move(text));
  const compiler::Target target = launch::defaultTarget();
  std::size_t errors = 0;
  c.stderrBytes = compileAndRender(source, target, errors);
  if (errors != c.program.errors)
    throw std::runtime_error(fmt::format("{}: {} errors reported, expected {}", c.path, errors, c.program.errors));
  const Measurement inProcess = [&] {
    std::size_t n = 0;
    const Stopwatch clock;
    compileAndRender(source, target, n);
    return clock.stop();
  };
  progress(fmt::format(
      "{} ({} lines, {:.1f} MB, {} errors), 1 warm-up + {} rounds: compile() and render in-process, "
      "robotsim check (process)",
      c.label, c.program.lines, static_cast<double>(c.bytes) / 1e6, c.program.errors, options.reps));
  const std::vector<Samples> s = interleave({inProcess, checkFails(options, c.path)}, options.reps);
  c.inProcess = s[0];
  c.process = s[1];
}

json errorJson(const ErrorCase& c) {
  return {{"label", c.label},
          {"lines", c.program.lines},
          {"bytes", c.bytes},
          {"errors", c.program.errors},
          {"in_process", toJson(c.inProcess)},
          {"process", toJson(c.process)},
          {"printed_bytes", c.stderrBytes},
          {"process_max_rss_kib", c.maxRssKiB},
          {"process_max_rss_is_child", c.rssIsChild}};
}

}  // namespace

json benchErrors(const Options& options) {
  fmt::print("\n[5] Programs full of errors: robotsim check (default --max-errors 50)\n");
  std::vector<ErrorCase> cases;
  // Each text is freed once written, and every peak RSS is taken before
  // anything is measured: wait4's peak is the driver's when that is larger.
  // The one-line cases (10 MB texts) go before the 16 MB one.
  // --smoke: a thousandth of each size.
  const std::size_t scale = sized<std::size_t>(options, 1, 1000);
  cases.push_back(prepareErrors(options, "10k-lines", errorProgram(10'000 / scale)));
  cases.push_back(prepareErrors(options, "100k-lines", errorProgram(100'000 / scale)));
  cases.push_back(prepareErrors(options, "1-line-10MB-stray", oneLineOfStrayCharacters(100'000 / scale)));
  cases.push_back(prepareErrors(options, "1-line-10MB-words", oneLineOfWords(10'000'000 / scale)));
  cases.push_back(prepareErrors(options, "1M-lines", errorProgram(1'000'000 / scale)));
  std::rotate(cases.begin() + 2, cases.begin() + 4, cases.end());  // 10k, 100k, 1M lines, then one line
  for (ErrorCase& c : cases) measureErrors(options, c);

  json out = {{"cases", json::array()}};
  for (const ErrorCase& c : cases) {
    const std::string perError =
        fmt::format("{:.0f} ns/error", c.inProcess.best() * 1e9 / static_cast<double>(c.program.errors));
    row(fmt::format("compile()+render {:<18} {:>7} err", c.label, c.program.errors), c.inProcess, perError);
    row(fmt::format("robotsim check {:<20} (process)", c.label), c.process,
        fmt::format("peak RSS {:.1f} MiB{}, {} bytes printed", static_cast<double>(c.maxRssKiB) / 1024,
                    c.rssIsChild ? "" : " (not measurable)", c.stderrBytes));
    out["cases"].push_back(errorJson(c));
  }
  const auto growth = [&](std::size_t big, std::size_t small, bool process) {
    return process ? cases[big].process.best() / cases[small].process.best()
                   : cases[big].inProcess.best() / cases[small].inProcess.best();
  };
  fmt::print(
      "  growth (best, linear = 10): in-process 100k/10k {:.1f}, 1M/100k {:.1f}; "
      "process 100k/10k {:.1f}, 1M/100k {:.1f}\n",
      growth(1, 0, false), growth(2, 1, false), growth(1, 0, true), growth(2, 1, true));
  const double oneLine = cases[3].process.best();
  fmt::print("  one {:.1f} MB line with {} errors: robotsim check {:.0f} ms (target for 10 MB: well under a second: {})\n",
             static_cast<double>(cases[3].bytes) / 1e6, cases[3].program.errors, oneLine * 1e3,
             oneLine < 0.5 ? "met" : "missed");
  out["growth"] = {{"in_process_100k_over_10k", growth(1, 0, false)},
                   {"in_process_1m_over_100k", growth(2, 1, false)},
                   {"process_100k_over_10k", growth(1, 0, true)},
                   {"process_1m_over_100k", growth(2, 1, true)}};
  out["one_line_10mb_process_best_s"] = oneLine;
  return out;
}

}  // namespace rs::bench
