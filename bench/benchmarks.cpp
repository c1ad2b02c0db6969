#include "bench/benchmarks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "bench/generate.h"
#include "bench/timing.h"
#include "compiler/compiler.h"
#include "compiler/library.h"
#include "launch/program.h"
#include "runtime/run/run.h"
#include "vm/image_file.h"
#include "vm/verify.h"

namespace rs::bench {

namespace {

using nlohmann::json;

constexpr long kLoopIterations = 10'000'000;

// --- printing ----------------------------------------------------------------

void progress(std::string_view what) {
  fmt::print("  ... {}\n", what);
  std::fflush(stdout);
}

std::string millis(double seconds) { return fmt::format("{:9.2f} ms", seconds * 1e3); }

// Wall best and median, then CPU best (user + system) in brackets.
void row(std::string_view what, const Samples& s, std::string_view extra = {}) {
  fmt::print("  {:<40} best {}  median {}  [cpu {}]{}{}\n", what, millis(s.best()), millis(s.median()),
             millis(s.cpuBest()), extra.empty() ? "" : "  ", extra);
}

// "0.85 (target <= 1: met)" or "4.20 (target <= 3: missed by 40%)".
std::string verdict(double ratio, double target) {
  const std::string outcome =
      ratio <= target ? std::string("met") : fmt::format("missed by {:.0f}%", (ratio / target - 1) * 100);
  return fmt::format("{:.2f} (target <= {}: {})", ratio, target, outcome);
}

json toJson(const Samples& s) {
  return {{"best_s", s.best()},
          {"median_s", s.median()},
          {"cpu_best_s", s.cpuBest()},
          {"samples_s", s.seconds},
          {"cpu_samples_s", s.cpuSeconds}};
}

// --- helpers -------------------------------------------------------------------

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

// --- 1. VM dispatch ----------------------------------------------------------------

// Times Run::runToEnd alone (compiled and verified once, a fresh run per
// measurement) and checks that the loop really counted to the end. The
// loop takes no simulated time, so the clock-standing-still limit is off.
Measurement vmLoop(const std::shared_ptr<const vm::Image>& image, std::uint64_t& steps) {
  return [image, &steps, n = slotOf(*image, "N")] {
    runtime::RunSpec spec;
    spec.image = image;
    spec.limits.maxSteps = 3 * static_cast<std::uint64_t>(kLoopIterations);
    spec.limits.maxStepsPerInstant = 0;
    runtime::Run run(std::move(spec));
    const Stopwatch clock;
    const vm::RunOutcome outcome = run.runToEnd();
    const Sample sample = clock.stop();
    const std::int32_t counted = run.interpreter().variables()[n];
    if (!outcome.ok() || counted != kLoopIterations)
      throw std::runtime_error(fmt::format("the VM loop stopped early ({}): N = {}", outcome.message, counted));
    steps = outcome.steps;
    return sample;
  };
}

}  // namespace

json benchDispatch(const Options& options) {
  fmt::print("\n[1] VM dispatch: SET/ADD/JMPVAR loop, {} iterations\n", kLoopIterations);
  const diag::SourceFile source("dispatch.rsp",
                                    fmt::format("SET N 0\nloop: ADD N 1\nJMPVAR N < {} loop\nEND\n", kLoopIterations));
  const auto image = std::make_shared<const vm::Image>(compileOrThrow(source, launch::defaultTarget()));
  if (const vm::VerifyError e = vm::verify(*image); !e.message.empty())
    throw std::runtime_error("the dispatch image does not verify: " + e.message);

  std::uint64_t steps = 0;
  std::vector<Measurement> runs{vmLoop(image, steps)};
  const bool lua = canRun({options.lua, "-v"});
  if (lua) {
    runs.push_back(
        processMeasurement({options.lua, writeInput(options, "dispatch.lua", luaCountedLoop(kLoopIterations))}));
    runs.push_back(processMeasurement({options.lua, writeInput(options, "empty.lua", "")}));
  }
  progress(fmt::format("interleaved, 1 warm-up + {} rounds: Run::runToEnd in-process{}", options.reps,
                       lua ? fmt::format(", {0} loop, {0} empty script (processes)", options.lua) : ""));
  const std::vector<Samples> s = interleave(runs, options.reps);
  const Samples& ours = s[0];
  row("robotsim VM (in-process run)", ours,
      fmt::format("{} steps, {:.2f} ns/instruction", steps, ours.best() * 1e9 / static_cast<double>(steps)));
  json out = {{"iterations", kLoopIterations}, {"steps", steps}, {"ours", toJson(ours)}};
  if (!lua) {
    fmt::print("  Lua comparison skipped: cannot run {}\n", options.lua);
    out["lua_skipped"] = true;
    return out;
  }
  const Samples& luaRaw = s[1];
  const Samples& luaEmpty = s[2];
  const double netBest = luaRaw.best() - luaEmpty.best();
  const double netMedian = luaRaw.median() - luaEmpty.median();
  row("lua5.4 loop (whole process, raw)", luaRaw);
  row("lua5.4 empty script (startup)", luaEmpty);
  fmt::print("  {:<40} best {}  median {}\n", "lua5.4 loop minus startup", millis(netBest), millis(netMedian));
  const double ratio = ours.best() / netBest;
  const double ratioRaw = ours.best() / luaRaw.best();
  fmt::print("  ratio ours / Lua, startup subtracted (best) {}\n", verdict(ratio, 1));
  fmt::print("  ratio ours / Lua, raw process (best)        {:.2f}\n", ratioRaw);
  fmt::print("  ratio ours / Lua, startup subtracted (median) {:.2f}\n", ours.median() / netMedian);
  const double ratioCpu = ours.cpuBest() / (luaRaw.cpuBest() - luaEmpty.cpuBest());
  fmt::print("  ratio ours / Lua, startup subtracted (CPU)  {:.2f}\n", ratioCpu);
  out["lua_raw"] = toJson(luaRaw);
  out["lua_empty"] = toJson(luaEmpty);
  out["lua_corrected"] = {{"best_s", netBest}, {"median_s", netMedian}};
  out["ratio_corrected"] = ratio;
  out["ratio_corrected_median"] = ours.median() / netMedian;
  out["ratio_raw"] = ratioRaw;
  out["ratio_corrected_cpu"] = ratioCpu;
  out["target_ratio"] = 1.0;
  out["target_met"] = ratio <= 1.0;
  return out;
}

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
  sizes.push_back(prepareSize(options, "10k", 10'000));
  sizes.push_back(prepareSize(options, "100k", 100'000));
  sizes.push_back(prepareSize(options, "1M", 1'000'000));
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
  const double ratio = s[0].best() / s[1].best();
  fmt::print("  ratio robotsim compile / luac -p (best)   {}\n", verdict(ratio, 3));
  fmt::print("  ratio robotsim compile / luac -p (median) {:.2f}\n", s[0].median() / s[1].median());
  fmt::print("  ratio robotsim compile / luac -p (CPU)    {:.2f}\n", s[0].cpuBest() / s[1].cpuBest());
  out["luac_pair"] = {{"lines", mid.program.lines}, {"robotsim", toJson(s[0])}, {"luac", toJson(s[1])}};
  out["ratio_100k_over_luac"] = ratio;
  out["ratio_100k_over_luac_median"] = s[0].median() / s[1].median();
  out["ratio_100k_over_luac_cpu"] = s[0].cpuBest() / s[1].cpuBest();
  out["target_ratio"] = 3.0;
  out["target_met"] = ratio <= 3.0;
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
  cases.push_back(prepareErrors(options, "10k-lines", errorProgram(10'000)));
  cases.push_back(prepareErrors(options, "100k-lines", errorProgram(100'000)));
  cases.push_back(prepareErrors(options, "1-line-10MB-stray", oneLineOfStrayCharacters(100'000)));
  cases.push_back(prepareErrors(options, "1-line-10MB-words", oneLineOfWords(10'000'000)));
  cases.push_back(prepareErrors(options, "1M-lines", errorProgram(1'000'000)));
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
  fmt::print("  one 10 MB line with 100,000 errors: robotsim check {:.0f} ms (target: well under a second: {})\n",
             oneLine * 1e3, oneLine < 0.5 ? "met" : "missed");
  out["growth"] = {{"in_process_100k_over_10k", growth(1, 0, false)},
                   {"in_process_1m_over_100k", growth(2, 1, false)},
                   {"process_100k_over_10k", growth(1, 0, true)},
                   {"process_1m_over_100k", growth(2, 1, true)}};
  out["one_line_10mb_process_best_s"] = oneLine;
  return out;
}

json benchStartup(const Options& options) {
  fmt::print("\n[3] Startup: robotsim check, whole process\n");
  const GeneratedProgram program = robotProgramOfLines(1000);
  const std::string path = writeInput(options, "startup-1000.rsp", program.text);
  progress(
      fmt::format("1 warm-up + {} rounds: robotsim help (the process floor), robotsim check on {} lines "
                  "({} instructions)",
                  options.reps, program.lines, program.instructions));
  const std::vector<Samples> s = interleave(
      {processMeasurement({options.robotsim, "help"}), processMeasurement({options.robotsim, "check", path})},
      options.reps);
  const Samples& floor = s[0];
  const Samples& check = s[1];
  row("robotsim help", floor);
  row(fmt::format("robotsim check {} lines", program.lines), check);
  const double ms = check.best() * 1e3;
  fmt::print("  robotsim check, best {:.2f} ms (target <= 20 ms: {})\n", ms,
             ms <= 20 ? std::string("met") : fmt::format("missed by {:.0f}%", (ms / 20 - 1) * 100));
  return {{"lines", program.lines}, {"instructions", program.instructions},
          {"help", toJson(floor)},  {"check", toJson(check)},
          {"target_s", 0.020},      {"target_met", check.best() <= 0.020}};
}

// --- 4. Run snapshots ------------------------------------------------------------

namespace {

constexpr int kSnapshotLoops = 20'000;
constexpr std::uint64_t kSnapshotEvery = 300;

// A run of the snapshot program on scara-pick, keeping a log.
std::unique_ptr<runtime::Run> snapshotRun(const std::shared_ptr<const vm::Image>& image,
                                          const std::shared_ptr<const workcell::Workcell>& cell) {
  runtime::RunSpec spec;
  spec.image = image;
  spec.cell = cell;
  spec.log = true;
  spec.limits.maxTime = vm::Micros{1} << 50;  // simulated time is not what is measured
  return std::make_unique<runtime::Run>(std::move(spec));
}

}  // namespace

json benchSnapshot(const Options& options) {
  fmt::print("\n[6] Run snapshots: a {}-loop program on scara-pick, logged\n", kSnapshotLoops);
  compiler::Library library(compiler::librarySearchPath({}));
  const std::optional<workcell::Workcell> found = library.workcell("scara-pick");
  if (!found) throw std::runtime_error("the library has no scara-pick workcell");
  const auto cell = std::make_shared<const workcell::Workcell>(*found);
  const diag::SourceFile source(
      "snapshot.rsp", fmt::format("SET N 0\nloop: ADD N 1\nMOVE 10 0 0 0 0\nMOVE -10 0 0 0 60\nGOSUB sub\n"
                                  "MOVE 0 0 0 0 -60\nJMPVAR N < {} loop\nEND\nsub: OUTSIG 1 ON\nOUTSIG 1 OFF\nRETURN\n",
                                  kSnapshotLoops));
  const auto image = std::make_shared<const vm::Image>(compileOrThrow(source, launch::cellTarget(*cell)));
  std::uint64_t steps = 0, snapshots = 0;
  const Measurement plain = [&] {
    auto run = snapshotRun(image, cell);
    const Stopwatch clock;
    const vm::RunOutcome outcome = run->runToEnd();
    const Sample sample = clock.stop();
    if (!outcome.ok()) throw std::runtime_error("the snapshot program failed: " + outcome.message);
    steps = outcome.steps;
    return sample;
  };
  const Measurement withSnapshots = [&] {
    auto run = snapshotRun(image, cell);
    runtime::RunSnapshot last;
    std::uint64_t taken = 0;
    const Stopwatch clock;
    while (!run->finished()) {
      last = run->snapshot();
      ++taken;
      run->step(kSnapshotEvery);
    }
    const Sample sample = clock.stop();
    if (!run->outcome()->ok() || last.vm.steps == 0) throw std::runtime_error("the snapshot run failed");
    snapshots = taken;
    return sample;
  };
  // Restoring: back to the middle of the run, 10,000 times.
  const Measurement restores = [&] {
    auto run = snapshotRun(image, cell);
    run->step(steps / 2);
    const runtime::RunSnapshot middle = run->snapshot();
    run->runToEnd();
    const Stopwatch clock;
    for (int i = 0; i < 10'000; ++i) run->restore(middle);
    const Sample sample = clock.stop();
    if (!(run->snapshot() == middle)) throw std::runtime_error("a restored run is not where it was");
    return sample;
  };
  progress(fmt::format("interleaved, 1 warm-up + {} rounds: to the end, with a snapshot every {} steps, 10,000 "
                       "restores",
                       options.reps, kSnapshotEvery));
  const std::vector<Samples> s = interleave({plain, withSnapshots, restores}, options.reps);
  const double perStep = s[0].best() * 1e9 / static_cast<double>(steps);
  const double perSnapshot = (s[1].best() - s[0].best()) * 1e9 / static_cast<double>(snapshots);
  const double perRestore = s[2].best() * 1e9 / 10'000;
  row("run to the end", s[0], fmt::format("{} steps, {:.1f} ns/step", steps, perStep));
  row(fmt::format("snapshot every {} steps", kSnapshotEvery), s[1],
      fmt::format("{} snapshots, {:+.1f} % time", snapshots, (s[1].best() / s[0].best() - 1) * 100));
  row("10,000 restores", s[2]);
  fmt::print("  one snapshot {:.0f} ns (the time of {:.1f} steps), one restore {:.0f} ns\n", perSnapshot,
             perSnapshot / perStep, perRestore);
  return {{"steps", steps},
          {"snapshots", snapshots},
          {"plain", toJson(s[0])},
          {"with_snapshots", toJson(s[1])},
          {"restores", toJson(s[2])},
          {"ns_per_step", perStep},
          {"ns_per_snapshot", perSnapshot},
          {"ns_per_restore", perRestore}};
}

// --- 5. robotsim test ----------------------------------------------------------------

json benchTestSuite(const Options& options) {
  constexpr int kPrograms = 1000;
  fmt::print("\n[7] robotsim test: {} generated programs, 3 expectations each, -j 2, whole process\n", kPrograms);
  const std::filesystem::path dir = std::filesystem::path(options.workDir) / "testsuite";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (int i = 0; i < kPrograms; ++i) {
    // k loops of two 100-unit moves of E at 400 units/s: 0.5 s each.
    const int k = 1 + i % 20;
    writeInput(options, fmt::format("testsuite/t{:04}.rsp", i),
               fmt::format("; expect: finished\n; expect: variable N = {0}\n; expect: time = {1}\n"
                           "SET N 0\nloop: ADD N 1\nMOVE 100 0 0 0 0\nMOVE -100 0 0 0 0\nJMPVAR N < {0} loop\nEND\n",
                           k, vm::formatSeconds(vm::Micros{k} * 500'000)));
  }
  progress(fmt::format("1 warm-up + {} runs of robotsim test {} -j 2 (every test must pass)", options.reps,
                       dir.string()));
  const std::vector<Samples> s =
      interleave({processMeasurement({options.robotsim, "test", dir.string(), "-j", "2"})}, options.reps);
  row("robotsim test, 1000 programs", s[0],
      fmt::format("{:.2f} ms per test; target <= 2 s: {}", s[0].best() * 1e3 / kPrograms,
                  s[0].best() <= 2.0 ? "met" : "missed"));
  return {{"programs", kPrograms}, {"jobs", 2}, {"run", toJson(s[0])}, {"target_s", 2.0},
          {"target_met", s[0].best() <= 2.0}};
}

}  // namespace rs::bench
