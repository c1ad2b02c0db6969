// The language server's latencies on a 10,000-line program: diagnostics
// published after a one-character change, hover and completion, in
// process (the time from the message to the answer); and the peak memory
// of a `robotsim lsp` process that opens the file, is edited and answers.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "bench/benchmarks.h"
#include "bench/timing.h"
#include "tools/lsp/jsonrpc.h"
#include "tools/lsp/server.h"
#include "vm/io_lines.h"

namespace rs::bench {

namespace {

using lsp::Json;

const std::string kUri = "file:///bench/big.rsp";

// A program of about `lines` lines as people write them: blocks of ten
// lines with a label, a loop on a variable, moves, a subroutine call, I/O
// and comments; 100 taught points at the end.
std::string program(int lines) {
  std::string s = "; generated for the language server benchmark\n";
  int line = 1, block = 0;
  while (line + 10 < lines - 102) {
    s += fmt::format("b{}:     SET N{} 0                 ; block {}\n", block, block % 50, block);
    s += fmt::format("        MOVE 10 -10 5 0 0           ; a small step\n");
    s += fmt::format("        ADD N{} 1\n", block % 50);
    s += fmt::format("        JMPVAR N{} < 3 b{}\n", block % 50, block);
    s += fmt::format("        MOVEP P{}\n", block % 100);
    s += fmt::format("        OUTSIG {} ON\n", block % vm::kIoCount + 1);
    s += fmt::format("        OUTSIG {} OFF\n", block % vm::kIoCount + 1);
    s += "; between blocks\n";
    s += fmt::format("        GOSUB s{}\n", block);
    s += fmt::format("        GOTO b{}\n", block + 1);
    line += 10, ++block;
  }
  s += fmt::format("b{}:     END\n", block);
  for (int b = 0; b < block; ++b) s += fmt::format("s{}:     RETURN\n", b);
  s += "POINTS\n";
  for (int p = 0; p < 100; ++p) s += fmt::format("P{} {} {} 0 {} 0\n", p, p * 5, -p * 3, p);
  return s;
}

// Line and character of the first occurrence of `what` at or after line `from`.
std::pair<int, int> find(const std::string& text, const std::string& what, int from) {
  int line = 0;
  std::size_t at = 0;
  for (; line < from; ++line) at = text.find('\n', at) + 1;
  const std::size_t hit = text.find(what, at);
  if (hit == std::string::npos) throw std::runtime_error("benchmark program lacks " + what);
  for (; at <= hit; ++line) {
    const std::size_t next = text.find('\n', at);
    if (next >= hit) return {line, static_cast<int>(hit - at)};
    at = next + 1;
  }
  return {line, 0};
}

Json request(int id, const std::string& method, Json params) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}};
}

Json at(std::pair<int, int> pos) {
  return {{"textDocument", {{"uri", kUri}}}, {"position", {{"line", pos.first}, {"character", pos.second}}}};
}

Json change(int version, std::pair<int, int> pos, const std::string& text) {
  const Json p = {{"line", pos.first}, {"character", pos.second}};
  const Json q = {{"line", pos.first}, {"character", pos.second + 1}};
  return {{"jsonrpc", "2.0"},
          {"method", "textDocument/didChange"},
          {"params", {{"textDocument", {{"uri", kUri}, {"version", version}}},
                      {"contentChanges", {{{"range", {{"start", p}, {"end", q}}}, {"text", text}}}}}}};
}

Json initialize() { return request(1, "initialize", {{"capabilities", Json::object()}}); }

Json didOpen(const std::string& text) {
  return {{"jsonrpc", "2.0"},
          {"method", "textDocument/didOpen"},
          {"params", {{"textDocument", {{"uri", kUri}, {"languageId", "robotsim-program"}, {"version", 1}, {"text", text}}}}}};
}

void send(lsp::Server& server, const Json& message) {
  server.receive({lsp::Frame{lsp::Frame::Kind::Message, lsp::dumpJson(message), {}}});
}

// Wall time, and the process's CPU time beside it (on a loaded machine the
// wall time includes waiting for a core; the CPU time includes the run
// worker's thread when it runs meanwhile).
void report(nlohmann::json& out, const std::string& key, const std::string& what, const Samples& s, double targetMs) {
  out[key] = {{"best_ms", s.best() * 1e3}, {"median_ms", s.median() * 1e3}, {"cpu_best_ms", s.cpuBest() * 1e3},
              {"target_ms", targetMs}};
  fmt::print("  {:<52} best {:7.2f} ms  median {:7.2f} ms  [cpu {:7.2f} ms]  (target {} ms{})\n", what, s.best() * 1e3,
             s.median() * 1e3, s.cpuBest() * 1e3, targetMs, s.median() * 1e3 <= targetMs ? "" : ", MISSED");
}

}  // namespace

nlohmann::json benchLsp(const Options& options) {
  const int lines = sized(options, 10'000, 1'000);
  fmt::print("\nlanguage server on a {}-line program\n", lines);
  const std::string text = program(lines);
  const auto digit = find(text, "MOVE 10 -10 5", lines / 2);  // the "1" of "10" in the middle of the file
  const std::pair<int, int> digitPos{digit.first, digit.second + 5};
  const auto point = find(text, "MOVEP P", lines / 2);
  const std::pair<int, int> pointPos{point.first, point.second + 7};
  const auto gotoLine = find(text, "GOTO b", lines / 2);
  const std::pair<int, int> labelPos{gotoLine.first, gotoLine.second + 5};
  const auto mnemonic = find(text, "MOVE 10", lines / 2);
  nlohmann::json out = {{"lines", lines}};

  // Peak memory: a robotsim lsp process given the whole session on stdin.
  {
    std::filesystem::create_directories(options.workDir);
    const std::string session = options.workDir + "/lsp_session.bin";
    std::ofstream f(session, std::ios::binary | std::ios::trunc);
    for (const Json& m : {initialize(), didOpen(text), change(2, digitPos, "2"), request(2, "textDocument/hover", at(pointPos)),
                          request(3, "textDocument/completion", at(labelPos)), request(4, "shutdown", nullptr),
                          Json{{"jsonrpc", "2.0"}, {"method", "exit"}}})
      f << lsp::frameMessage(lsp::dumpJson(m));
    f.close();
    const ProcessRun run = runLspSession(options, session, "/dev/null");
    const double mib = static_cast<double>(run.maxRssKiB) / 1024.0;
    out["peak_rss_mib"] = mib;
    fmt::print("  {:<52} {:7.1f} MiB        (target 50 MiB{})\n", "peak RSS of robotsim lsp with the file open", mib,
               mib <= 50 ? "" : ", MISSED");
  }

  std::ostringstream log;
  // The compile's publications: those made on this thread (the run
  // worker's thread publishes what the runs find, later). The time of the
  // last one is read as it is sent: what follows it in publishPending
  // (handing the run to the worker) is not the client's wait.
  std::atomic<std::size_t> published = 0;
  const std::thread::id self = std::this_thread::get_id();
  const Stopwatch* publishing = nullptr;
  Sample publishedAt;
  lsp::Server server(
      [&](const Json& m) {
        if (m.value("method", "") == "textDocument/publishDiagnostics" && std::this_thread::get_id() == self) {
          ++published;
          if (publishing) publishedAt = publishing->stop();
        }
        return true;
      },
      log);
  send(server, initialize());
  send(server, didOpen(text));
  server.publishPending();
  int version = 1, id = 10;
  bool flip = false;
  const auto timed = [&](const std::function<void()>& work) {
    return [work, &server] {
      server.settle();  // the last change's run is not on the clock of what follows
      const Stopwatch clock;
      work();
      return clock.stop();
    };
  };
  const std::vector<Samples> samples = interleave(
      {[&] {
         // One character typed, then the diagnostics published.
         server.settle();
         const Stopwatch clock;
         publishing = &clock;
         flip = !flip;
         send(server, change(++version, digitPos, flip ? "2" : "1"));
         const std::size_t before = published;
         server.publishPending();
         publishing = nullptr;
         if (published != before + 1) throw std::runtime_error("no diagnostics published after a change");
         return publishedAt;
       },
       timed([&] { send(server, request(++id, "textDocument/hover", at(pointPos))); }),
       timed([&] { send(server, request(++id, "textDocument/hover", at(labelPos))); }),
       timed([&] { send(server, request(++id, "textDocument/completion", at(labelPos))); }),
       timed([&] { send(server, request(++id, "textDocument/completion", at({mnemonic.first, mnemonic.second + 2}))); }),
       timed([&] {
         // The first hover on a move after a change waits for the program's
         // run (robotsim check's, on the run worker) for its times.
         flip = !flip;
         send(server, change(++version, digitPos, flip ? "2" : "1"));
         server.publishPending();
         send(server, request(++id, "textDocument/hover", at({mnemonic.first, mnemonic.second + 1})));
       })},
      options.reps);
  report(out, "diagnostics_after_change", "diagnostics published after a one-character change", samples[0], 30);
  report(out, "hover_point", "hover on a point (values, tool centre point)", samples[1], 5);
  report(out, "hover_label", "hover on a label", samples[2], 5);
  report(out, "completion_labels", "completion of a jump target (1,000 labels)", samples[3], 5);
  report(out, "completion_instructions", "completion of an instruction", samples[4], 5);
  report(out, "change_then_hover_move", "a change, its diagnostics, then hover on a move (waits for the run)", samples[5], 60);
  return out;
}

}  // namespace rs::bench
