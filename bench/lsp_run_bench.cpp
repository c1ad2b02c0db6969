// The language server's run-time diagnostics (issue 23): a 10,000-line
// program on the scara-pick cell is changed by one character, and the time
// is taken from the change to the publication of its compile diagnostics
// and to the publication of what its run (robotsim check's, on the run
// worker) found: a deadlock at its last instruction, so that every run is
// published. Target: 200 ms from the keystroke. Measured with collisions
// checked (check's default) and off (the robotsim.collisions setting):
// the difference is the cost of the collision checks of 5,000 moves.
// Then the two-robot example (issue 36): left.rsp of
// examples/two_robots/interlock.rsd, open with right.rsp, edited by one
// digit (a move of 300 and 301 in turn); the time from the change until
// the cell run (both programs, on the cell's one clock) is made and what
// it found published for both documents. Target: 50 ms median.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "base/file_io.h"
#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "tools/lsp/jsonrpc.h"
#include "tools/lsp/server.h"

namespace rs::bench {

namespace {

using lsp::Json;

const std::string kRunUri = "file:///bench/run.rsp";

// About `size` lines: blocks of ten (a label, a counted loop of two
// small moves out and back, a move to a taught point, two outputs, a
// subroutine call, a jump to the next block), one RETURN a block, 100
// points near home, all clear of the cell's table, pallet and blocks; the
// last instruction waits for an input nothing turns on.
std::string runProgram(int size) {
  std::string s = "; cell: scara-pick\n; generated for the language server's run benchmark\n";
  int lines = 2, blocks = 0;
  while (lines + 11 + 2 + 101 < size) {
    const int n = blocks % 50, out = blocks % 8 + 1;
    s += fmt::format("b{}:     SET N{} 0                 ; block {}\n", blocks, n, blocks);
    s += fmt::format("l{}:     MOVE 40 -40 0 0 0           ; out\n", blocks);
    s += "        MOVE -40 40 0 0 0           ; and back\n";
    s += fmt::format("        ADD N{} 1\n", n);
    s += fmt::format("        JMPVAR N{} < 2 l{}\n", n, blocks);
    s += fmt::format("        MOVEP P{}\n", blocks % 100);
    s += fmt::format("        OUTSIG {} ON\n        OUTSIG {} OFF\n", out, out);
    s += fmt::format("        GOSUB s{}\n        GOTO b{}\n", blocks, blocks + 1);
    lines += 11, ++blocks;  // with the block's RETURN below
  }
  s += fmt::format("b{}:     WAITFOR 1 ON                ; nothing turns it on: a deadlock\n        END\n", blocks);
  for (int b = 0; b < blocks; ++b) s += fmt::format("s{}:     RETURN\n", b);
  s += "POINTS\n";
  for (int p = 0; p < 100; ++p) s += fmt::format("P{} {} {} 0 {} 0\n", p, (p % 20) * 10 - 100, (p % 10) * 20 - 100, p);
  return s;
}

Json message(const std::string& method, Json params, int id = 0) {
  Json m = {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
  if (id) m["id"] = id;
  return m;
}

// A server whose publications are watched: the run's (the second of a
// version, with its deadlock) are waited for.
class WatchedServer {
 public:
  explicit WatchedServer(const Json& options)
      : self_(std::this_thread::get_id()), server_([this](const Json& m) { return sent(m); }, log_) {
    send(message("initialize", {{"capabilities", Json::object()}, {"initializationOptions", options}}, 1));
    send(message("initialized", Json::object()));
  }
  void send(const Json& m) { server_.receive({lsp::Frame{lsp::Frame::Kind::Message, lsp::dumpJson(m), {}}}); }
  /// The next compile publication (made on this thread) is timed by `clock`.
  void timeCompile(const Stopwatch* clock) { compileClock_ = clock; }
  Sample compilePublished() const { return compileAt_; }
  lsp::Server& server() { return server_; }
  /// Waits until the run of `version` is published (60 s at most).
  void waitForRun(std::int64_t version) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!published_.wait_for(lock, std::chrono::seconds(60), [&] { return runVersion_ == version; }))
      throw std::runtime_error(fmt::format("no run-time diagnostics published for version {}", version));
  }

 private:
  bool sent(const Json& m) {
    if (m.value("method", "") != "textDocument/publishDiagnostics") return true;
    if (std::this_thread::get_id() == self_ && compileClock_) compileAt_ = compileClock_->stop();
    const Json& d = m["params"]["diagnostics"];
    if (!d.empty() && d.back().value("code", "") == "run-not-finished")
      std::fprintf(stderr, "robotsim_bench: the editor's run did not finish within its budget\n"), std::abort();
    if (d.empty() || d.back().value("message", "").rfind("deadlock:", 0) != 0) return true;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      runVersion_ = m["params"]["version"].get<std::int64_t>();
    }
    published_.notify_all();
    return true;
  }

  std::ostringstream log_;
  std::mutex mutex_;
  std::condition_variable published_;
  std::int64_t runVersion_ = -1;
  std::thread::id self_;
  const Stopwatch* compileClock_ = nullptr;
  Sample compileAt_;
  lsp::Server server_;  // last: its run worker stops first
};

std::string readText(const std::string& path) {
  base::FileRead read = base::readFile(path, std::size_t{1} << 20);
  if (!read.bytes) throw std::runtime_error(fmt::format("cannot read {}: {}", path, read.error));
  return *read.bytes;
}

// The two-robot example's left program edited, both programs open: the
// change to the settled worker (the cell run made and published).
nlohmann::json benchCellRun(const Options& options) {
  const std::string folder = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/two_robots/";
  const std::string left = readText(folder + "left.rsp"), right = readText(folder + "right.rsp");
  const std::string leftUri = "file://" + folder + "left.rsp", rightUri = "file://" + folder + "right.rsp";
  std::ostringstream log;
  std::atomic<int> published = 0;
  Json hoverReply;
  lsp::Server server(
      [&](const Json& m) {
        if (m.value("method", "") == "textDocument/publishDiagnostics") ++published;
        if (m.contains("id") && m["id"] == 2) hoverReply = m;
        return true;
      },
      log);
  const auto send = [&](const Json& m) { server.receive({lsp::Frame{lsp::Frame::Kind::Message, lsp::dumpJson(m), {}}}); };
  send(message("initialize", {{"capabilities", Json::object()},
                              {"initializationOptions", {{"robotsim", {{"cell", folder + "interlock.rsd"}}}}}}, 1));
  send(message("initialized", Json::object()));
  for (const auto& [uri, text] : {std::pair{leftUri, left}, std::pair{rightUri, right}})
    send(message("textDocument/didOpen",
                 {{"textDocument", {{"uri", uri}, {"languageId", "robotsim-program"}, {"version", 1}, {"text", text}}}}));
  server.publishPending();
  server.settle();
  // The last digit of the first "MOVE 300": 300 and 301 in turn.
  const std::size_t digit = left.find("MOVE 300") + 7;
  const int line = static_cast<int>(std::count(left.begin(), left.begin() + static_cast<long>(digit), '\n'));
  const int character = static_cast<int>(digit - left.rfind('\n', digit) - 1);
  progress(fmt::format("two robots (interlock): {} changes of left.rsp", options.reps + 1));
  Samples ran;
  for (int rep = 0, version = 1; rep <= options.reps; ++rep) {  // the first is a warm-up
    ++version;
    const Json at = {{"line", line}, {"character", character}};
    const Json after = {{"line", line}, {"character", character + 1}};
    const Stopwatch clock;
    send(message("textDocument/didChange",
                 {{"textDocument", {{"uri", leftUri}, {"version", version}}},
                  {"contentChanges", {{{"range", {{"start", at}, {"end", after}}}, {"text", version % 2 ? "0" : "1"}}}}}));
    server.publishPending();
    server.settle();
    const Sample sample = clock.stop();
    if (rep == 0) continue;
    ran.seconds.push_back(sample.wall), ran.cpuSeconds.push_back(sample.cpu);
  }
  if (published == 0) throw std::runtime_error("the two-robot example: nothing was published");
  // The last run was the cell's: left's first move ran twice (alone, left
  // would wait for ever after one turn; tests/lsp/test_lsp_cell_runs.cpp).
  hoverReply = nullptr;
  send(message("textDocument/hover", {{"textDocument", {{"uri", leftUri}}}, {"position", {{"line", line}, {"character", 9}}}}, 2));
  if (lsp::dumpJson(hoverReply).find("the first of 2 times") == std::string::npos)
    throw std::runtime_error("the two-robot example was not run as a cell: " + lsp::dumpJson(hoverReply));
  row("two robots (interlock): edit to the cell run published", ran,
      fmt::format("target 50 ms (median): {}", ran.median() * 1e3 <= 50 ? "met" : "MISSED"));
  return {{"published", toJson(ran)}, {"target_ms", 50}};
}

}  // namespace

nlohmann::json benchLspRuns(const Options& options) {
  const int size = sized(options, 10'000, 400);
  fmt::print("\nlanguage server: run-time diagnostics of a {}-line program on scara-pick\n", size);
  const std::string text = runProgram(size);
  // The "0" of "40" in the middle block's first move: 40 and 41 in turn.
  const std::size_t middle = text.find(fmt::format("l{}:", (size / 11) / 2));
  const std::size_t digit = text.find("40", middle) + 1;
  const int line = static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(digit), '\n'));
  const int character = static_cast<int>(digit - text.rfind('\n', digit) - 1);
  nlohmann::json out = {{"lines", std::count(text.begin(), text.end(), '\n')}, {"target_ms", 200}};
  for (const char* collisions : {"error", "off"}) {
    progress(fmt::format("collisions {}: {} changes", collisions, options.reps + 1));
    WatchedServer s(Json{{"robotsim", {{"collisions", collisions}}}});
    s.send(message("textDocument/didOpen",
                   {{"textDocument", {{"uri", kRunUri}, {"languageId", "robotsim-program"}, {"version", 1}, {"text", text}}}}));
    s.server().publishPending();
    s.waitForRun(1);
    std::int64_t version = 1;
    Samples compiled, ran;
    for (int rep = 0; rep <= options.reps; ++rep) {  // the first is a warm-up
      ++version;
      const Json at = {{"line", line}, {"character", character}};
      const Json after = {{"line", line}, {"character", character + 1}};
      const Stopwatch clock;
      s.timeCompile(&clock);
      s.send(message("textDocument/didChange",
                     {{"textDocument", {{"uri", kRunUri}, {"version", version}}},
                      {"contentChanges", {{{"range", {{"start", at}, {"end", after}}}, {"text", version % 2 ? "0" : "1"}}}}}));
      s.server().publishPending();
      s.waitForRun(version);
      const Sample run = clock.stop();
      s.timeCompile(nullptr);
      const Sample compile = s.compilePublished();
      if (rep == 0) continue;
      compiled.seconds.push_back(compile.wall), compiled.cpuSeconds.push_back(compile.cpu);
      ran.seconds.push_back(run.wall), ran.cpuSeconds.push_back(run.cpu);
    }
    const std::string key = fmt::format("collisions_{}", collisions);
    out[key] = {{"compile_published", toJson(compiled)}, {"run_published", toJson(ran)}};
    row(fmt::format("collisions {:<5}: compile diagnostics published", collisions), compiled);
    row(fmt::format("collisions {:<5}: run-time diagnostics published", collisions), ran,
        fmt::format("target 200 ms: {}", ran.median() * 1e3 <= 200 ? "met" : "MISSED"));
  }
  out["two_robots"] = benchCellRun(options);
  return out;
}

}  // namespace rs::bench
