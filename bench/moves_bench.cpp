// Straight lines cost what a line costs (issue 32), measured: compiling
// 1,000 and 4,000 MOVES lines of the IRB 120 (300 units, hundreds of knots
// each; the path check plans each line, the cache of plans once per start
// and end) and 1,000 lines that are all different; the language server's
// diagnostics and hover right after an edit on 4,000 such lines (the check
// is on the run worker's thread, not the request's); the debugger's
// reverse step on a MOVES loop, and `pause` and `disconnect` sent to a
// `robotsim dap` process running a MOVES loop and a gantry of 65,536-knot
// lines; grading a MOVES submission that never ends, on the library's
// IRB 120 cell and on a cell of the student's own whose motors make a line
// take no time.
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "bench/bench_support.h"
#include "bench/benchmarks.h"
#include "bench/big_gantry.h"
#include "bench/timing.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "model/workcell/line_path.h"
#include "tools/debug/debug_session.h"
#include "tools/lsp/jsonrpc.h"
#include "tools/lsp/server.h"

extern char** environ;

namespace rs::bench {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double threadCpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

const char* kPoints = "POINTS\nA       AT 300 1000 -150 APPROACH 0 -1 0\nB       AT 300 1000 150 APPROACH 0 -1 0\n";

// `lines` MOVES between A and B, 300 units apart, on the IRB 120.
std::string movesProgram(int lines) {
  std::string s = "; cell: irb120-cell\n        MOVEP   A\n";
  for (int i = 0; i < lines; ++i) s += i % 2 ? "        MOVES   A\n" : "        MOVES   B\n";
  return s + "        END\n" + kPoints;
}

// `lines` MOVES of about 300 units, each from and to points of its own.
std::string distinctProgram(int lines) {
  std::string s = "; cell: irb120-cell\n        MOVEP   P0\n";
  for (int i = 1; i <= lines; ++i) s += fmt::format("        MOVES   P{}\n", i);
  s += "        END\nPOINTS\n";
  for (int i = 0; i <= lines; ++i)
    s += fmt::format("P{:<6} AT {:.2f} 1000 {} APPROACH 0 -1 0\n", i, 280 + i * 0.04, i % 2 ? 150 : -150);
  return s;
}

const std::string kLoop = "; cell: irb120-cell\n        MOVEP   A\nLOOP:   MOVES   B\n        MOVES   A\n"
                          "        GOTO    LOOP\n" + std::string(kPoints);

workcell::Workcell libraryCell(const std::string& name) {
  compiler::Library library(compiler::librarySearchPath({}));
  std::optional<workcell::Workcell> cell = library.workcell(name);
  if (!cell || cell->robots.empty()) throw std::runtime_error("the library has no workcell " + name);
  return std::move(*cell);
}

// The knots of the line from point `from` to point `to`, as the planner makes them.
std::size_t lineKnots(const workcell::Workcell& cell, const vm::Image& image, std::size_t from, std::size_t to) {
  const workcell::LinePlanner planner(*cell.drivenRobot());
  workcell::LinePath path(planner);
  if (planner.planTo(image.points[from].values, image.points[to].values, path))
    throw std::runtime_error("the IRB 120 cannot follow the benchmark's line");
  return path.size();
}

json compileLines(const Options& options, const workcell::Workcell& cell) {
  const vm::Image image = compileOrThrow(diag::SourceFile("knots.rsp", movesProgram(2)), launch::cellTarget(cell));
  const std::size_t there = lineKnots(cell, image, 0, 1), back = lineKnots(cell, image, 1, 0);
  fmt::print("  a MOVES from A to B on the IRB 120: {} knots, from B to A {}\n", there, back);
  json out = {{"knots_a_to_b", there}, {"knots_b_to_a", back}, {"programs", json::array()}};
  const int small = sized(options, 1000, 50), large = sized(options, 4000, 200);
  std::vector<Measurement> ms;
  std::vector<std::string> names;
  for (const auto& [name, text] : {std::pair{fmt::format("{} MOVES lines", small), movesProgram(small)},
                                   std::pair{fmt::format("{} MOVES lines", large), movesProgram(large)},
                                   std::pair{fmt::format("{} MOVES lines, all different", small), distinctProgram(small)}}) {
    const std::string path = writeInput(options, fmt::format("moves/compile-{}.rsp", names.size()), text);
    ms.push_back(processMeasurement({options.robotsim, "compile", path, "-o", path + ".rsb"}));
    names.push_back(name);
  }
  progress("robotsim compile (the path check of every line included), whole process");
  const std::vector<Samples> s = interleave(ms, options.reps);
  for (std::size_t i = 0; i < s.size(); ++i) {
    row("robotsim compile, " + names[i], s[i]);
    out["programs"].push_back({{"program", names[i]}, {"run", toJson(s[i])}});
  }
  fmt::print("  {} MOVES lines: CPU {:.3f} s (target <= 0.5 s: {})\n", small, s[0].cpuBest(),
             s[0].cpuBest() <= 0.5 ? "met" : "missed");
  out["target_met"] = s[0].cpuBest() <= 0.5;
  return out;
}

// ---- the language server ----------------------------------------------------

const std::string kLspUri = "file:///bench/moves.rsp";

lsp::Json lspAt(int line, int character) {
  return {{"textDocument", {{"uri", kLspUri}}}, {"position", {{"line", line}, {"character", character}}}};
}

void lspSend(lsp::Server& server, const lsp::Json& m) {
  server.receive({lsp::Frame{lsp::Frame::Kind::Message, lsp::dumpJson(m), {}}});
}

json lspAfterEdit(const Options& options) {
  const int lines = sized(options, 4000, 200);
  const std::string text = movesProgram(lines);
  // The edit: B's x, 300 and 301 in turn (the line of B, the "0" of "300").
  const int pointLine = lines + 5;
  const std::size_t bAt = text.rfind("B       AT 300");
  if (bAt == std::string::npos) throw std::runtime_error("the program has no point B");
  const int digit = static_cast<int>(std::string("B       AT 30").size());
  std::ostringstream log;
  std::size_t published = 0;
  const std::thread::id self = std::this_thread::get_id();
  lsp::Server server(
      [&](const lsp::Json& m) {
        if (m.value("method", "") == "textDocument/publishDiagnostics" && std::this_thread::get_id() == self) ++published;
        return true;
      },
      log);
  lspSend(server, {{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", {{"capabilities", lsp::Json::object()}}}});
  lspSend(server, {{"jsonrpc", "2.0"},
                   {"method", "textDocument/didOpen"},
                   {"params", {{"textDocument", {{"uri", kLspUri}, {"languageId", "robotsim-program"}, {"version", 1}, {"text", text}}}}}});
  server.publishPending();
  server.settle();
  int version = 1, id = 10;
  bool flip = false;
  std::vector<double> change, hover, settle;
  for (int r = 0; r < std::max(3, options.reps); ++r) {
    flip = !flip;
    const lsp::Json p = {{"line", pointLine}, {"character", digit}};
    const lsp::Json q = {{"line", pointLine}, {"character", digit + 1}};
    const auto start = Clock::now();
    const std::size_t before = published;
    lspSend(server, {{"jsonrpc", "2.0"},
                     {"method", "textDocument/didChange"},
                     {"params", {{"textDocument", {{"uri", kLspUri}, {"version", ++version}}},
                                 {"contentChanges", {{{"range", {{"start", p}, {"end", q}}}, {"text", flip ? "1" : "0"}}}}}}});
    server.publishPending();
    if (published != before + 1) throw std::runtime_error("no diagnostics published after a change");
    change.push_back(since(start));
    // Hover on the point B of the first MOVES, right after: its values and tool centre.
    const auto h = Clock::now();
    lspSend(server, {{"jsonrpc", "2.0"}, {"id", ++id}, {"method", "textDocument/hover"}, {"params", lspAt(2, 16)}});
    hover.push_back(since(h) + change.back());
    // What the worker does meanwhile, off the request path: the check of
    // the lines (two new plans) and the program's run.
    server.settle();
    settle.push_back(since(start));
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const double c = median(change), h = median(hover), w = median(settle);
  fmt::print("  {} MOVES lines: a one-character edit of a point, diagnostics published median {:.2f} ms, hover right "
             "after it answered at {:.2f} ms (target 30 ms: {}); the worker's check and run done at {:.0f} ms\n",
             lines, c * 1e3, h * 1e3, h <= 0.030 ? "met" : "missed", w * 1e3);
  return {{"lines", lines}, {"change_median_ms", c * 1e3}, {"hover_after_edit_median_ms", h * 1e3},
          {"worker_done_median_ms", w * 1e3}, {"target_met", h <= 0.030}};
}

// ---- the debugger -------------------------------------------------------------

json reverseSteps(const Options& options, const workcell::Workcell& cell) {
  runtime::RunSpec spec;
  spec.image = std::make_shared<const vm::Image>(
      compileOrThrow(diag::SourceFile("loop.rsp", kLoop), launch::cellTarget(cell)));
  spec.cell = std::make_shared<const workcell::Workcell>(cell);
  spec.limits.maxTime = vm::Micros{1'000'000} * 1'000'000;
  debug::DebugSession session(spec);
  const std::uint64_t steps = sized<std::uint64_t>(options, 3000, 100);
  const auto start = Clock::now();
  session.step(steps);
  const double forward = since(start);
  std::vector<double> wall, cpu;
  for (int i = 0; i < sized(options, 60, 5); ++i) {
    // Spread over the run: a few steps back from a moment, then one timed.
    session.step(static_cast<std::uint64_t>(i % 7) + 1);
    const auto t = Clock::now();
    const double c = threadCpu();
    session.reverseStep();
    cpu.push_back(threadCpu() - c);
    wall.push_back(since(t));
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  const std::uint64_t knots = session.run().knots();
  fmt::print("  a MOVES loop on the IRB 120, {} instructions ({} knots, {} snapshots) forwards in {:.0f} ms: a reverse "
             "step median {:.2f} ms, worst {:.2f} ms [cpu median {:.2f} ms, worst {:.2f} ms]\n",
             steps, knots, session.timeline().snapshotCount(), forward * 1e3, wall[wall.size() / 2] * 1e3,
             wall.back() * 1e3, cpu[cpu.size() / 2] * 1e3, cpu.back() * 1e3);
  return {{"steps", steps}, {"knots", knots}, {"reverse_median_ms", wall[wall.size() / 2] * 1e3},
          {"reverse_worst_ms", wall.back() * 1e3}, {"reverse_cpu_median_ms", cpu[cpu.size() / 2] * 1e3},
          {"reverse_cpu_worst_ms", cpu.back() * 1e3}};
}

// A `robotsim dap` process on pipes.
class DapProcess {
 public:
  explicit DapProcess(const std::string& robotsim) {
    int in[2], out[2];
    if (pipe(in) != 0 || pipe(out) != 0) throw std::runtime_error("no pipe for robotsim dap");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    for (const int fd : {in[0], in[1], out[0], out[1]}) posix_spawn_file_actions_addclose(&actions, fd);
    std::vector<std::string> args{robotsim, "dap"};
    std::vector<char*> argv{args[0].data(), args[1].data(), nullptr};
    const int spawned = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(in[0]), close(out[1]);
    to_ = in[1], from_ = out[0];
    if (spawned != 0) throw std::runtime_error("cannot run " + robotsim + " dap");
  }
  ~DapProcess() {
    close(to_), close(from_);
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  DapProcess(const DapProcess&) = delete;
  DapProcess& operator=(const DapProcess&) = delete;

  void request(const std::string& command, json arguments) {
    const std::string body =
        json{{"seq", ++seq_}, {"type", "request"}, {"command", command}, {"arguments", std::move(arguments)}}.dump();
    const std::string frame = fmt::format("Content-Length: {}\r\n\r\n{}", body.size(), body);
    if (write(to_, frame.data(), frame.size()) != static_cast<ssize_t>(frame.size()))
      throw std::runtime_error("robotsim dap did not take a request");
  }
  int seq() const { return seq_; }

  // Waits (at most `limit` seconds) for a message that `wanted` accepts.
  json waitFor(const std::function<bool(const json&)>& wanted, double limit) {
    const auto start = Clock::now();
    for (;;) {
      while (std::optional<json> m = nextFrame())
        if (wanted(*m)) return *m;
      const double left = limit - since(start);
      if (left <= 0) throw std::runtime_error("robotsim dap did not answer within " + fmt::format("{:.0f} s", limit));
      pollfd p{from_, POLLIN, 0};
      poll(&p, 1, static_cast<int>(left * 1000) + 1);
      char chunk[65536];
      const ssize_t n = read(from_, chunk, sizeof chunk);
      if (n <= 0) throw std::runtime_error("robotsim dap ended without the answer");
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }
  json response(int seq, double limit) {
    return waitFor([seq](const json& m) { return m.value("type", "") == "response" && m.value("request_seq", -1) == seq; },
                   limit);
  }
  int wait() {
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

 private:
  std::optional<json> nextFrame() {
    const std::size_t end = buffer_.find("\r\n\r\n");
    if (end == std::string::npos) return std::nullopt;
    const std::size_t length = std::stoul(buffer_.substr(buffer_.find(':') + 1, end));
    if (buffer_.size() < end + 4 + length) return std::nullopt;
    json m = json::parse(buffer_.substr(end + 4, length));
    buffer_.erase(0, end + 4 + length);
    return m;
  }

  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
  int seq_ = 0;
  bool reaped_ = false;
  std::string buffer_;
};

// The run started and going for `running` seconds.
void startRun(DapProcess& dap, const std::string& program, double running) {
  dap.request("initialize", {{"adapterID", "robotsim"}});
  dap.request("launch", {{"program", program}, {"maxTime", 1000000}});
  dap.request("configurationDone", json::object());
  dap.response(dap.seq(), 60);
  std::this_thread::sleep_for(std::chrono::duration<double>(running));
}

json pauseAndDisconnect(const Options& options, const std::string& name, const std::string& program) {
  std::vector<double> pause, disconnect;
  const double running = sized(options, 0.3, 0.05);
  for (int r = 0; r < std::max(3, options.reps); ++r) {
    {
      DapProcess dap(options.robotsim);
      startRun(dap, program, running);
      const auto t = Clock::now();
      dap.request("pause", {{"threadId", 1}});
      dap.waitFor([](const json& m) { return m.value("event", "") == "stopped"; }, 120);
      pause.push_back(since(t));
      dap.request("disconnect", json::object());
      dap.response(dap.seq(), 60);
      dap.wait();
    }
    DapProcess dap(options.robotsim);
    startRun(dap, program, running);
    const auto t = Clock::now();
    dap.request("disconnect", json::object());
    dap.response(dap.seq(), 120);
    if (dap.wait() != 0) throw std::runtime_error("robotsim dap did not exit 0 after disconnect");
    disconnect.push_back(since(t));
  }
  std::sort(pause.begin(), pause.end());
  std::sort(disconnect.begin(), disconnect.end());
  fmt::print("  {}: pause answered (the stopped event) median {:.2f} ms, worst {:.2f} ms; disconnect answered and "
             "the process gone median {:.2f} ms, worst {:.2f} ms\n",
             name, pause[pause.size() / 2] * 1e3, pause.back() * 1e3, disconnect[disconnect.size() / 2] * 1e3,
             disconnect.back() * 1e3);
  return {{"pause_median_ms", pause[pause.size() / 2] * 1e3}, {"pause_worst_ms", pause.back() * 1e3},
          {"disconnect_median_ms", disconnect[disconnect.size() / 2] * 1e3},
          {"disconnect_worst_ms", disconnect.back() * 1e3}};
}

// ---- grading ------------------------------------------------------------------

// The library's gantry with motors of SPEED 1,000,000,000 (allowed): a
// line takes no simulated time, so no time limit stops a loop of them.
std::string fastGantry() {
  std::ifstream in;
  for (const std::filesystem::path& dir : compiler::librarySearchPath({}))
    if (!in.is_open()) in.open(dir / "robots" / "gantry.rsd");
  std::stringstream text;
  text << in.rdbuf();
  std::string rsd = std::regex_replace(text.str(), std::regex("(JOINT [^\\n]*SPEED )[0-9]+"), "$011000000000");
  rsd = std::regex_replace(rsd, std::regex("ROBOT gantry\\n"), "ROBOT fast-gantry\n");
  if (rsd.find("SPEED 1000000000") == std::string::npos) throw std::runtime_error("the library's gantry was not found");
  return rsd + "WORKCELL fast-cell\n  ROBOT fast-gantry AT 0 1000 0\nEND\n";
}

json grading(const Options& options) {
  const std::string root = options.workDir + "/moves/grading";
  std::filesystem::create_directories(root + "/irb");
  std::filesystem::create_directories(root + "/own");
  writeInput(options, "moves/grading/irb/forever.rsp", kLoop);
  writeInput(options, "moves/grading/own/fast.rsd", fastGantry());
  writeInput(options, "moves/grading/own/forever.rsp",
             "; cell: fast.rsd\nloop:   MOVES A\n        MOVES B\n        GOTO loop\nPOINTS\nA 0 0 0 0\nB 3000 3000 0 0\n");
  const std::string onIrb =
      writeInput(options, "moves/grading/irb.rstest", "scenario on the cell\ntest: cell irb120-cell\nexpect: finished\n");
  const std::string own = writeInput(options, "moves/grading/own.rstest", "scenario it ends\nexpect: finished\n");
  json out;
  for (const auto& [key, spec, folder, what] :
       {std::tuple{"irb120", onIrb, root + "/irb", "on irb120-cell (the scenario's cell)"},
        std::tuple{"own_cell", own, root + "/own", "on the student's own cell (a gantry at SPEED 1e9)"}}) {
    std::vector<double> cpu;
    for (int r = 0; r < options.reps; ++r) {
      const ProcessRun run = runProcess({options.robotsim, "test", "--spec", spec, folder, "-j", "1"});
      if (run.exitCode != 1) throw std::runtime_error(fmt::format("robotsim test --spec {} exited {}", spec, run.exitCode));
      cpu.push_back(run.cpuSeconds);
    }
    const double best = *std::min_element(cpu.begin(), cpu.end());
    fmt::print("  a MOVES submission that never ends, {}: {:.3f} s CPU (target < 1 s: {})\n", what, best,
               best < 1.0 ? "met" : "missed");
    out[key] = {{"cpu_best_s", best}, {"target_met", best < 1.0}};
  }
  return out;
}

}  // namespace

json benchMoves(const Options& options) {
  fmt::print("\n[12] Straight lines: compile, the language server, the debugger and grading on MOVES\n");
  const workcell::Workcell irb = libraryCell("irb120-cell");
  std::filesystem::create_directories(std::filesystem::path(options.workDir) / "moves");
  json out;
  out["compile"] = compileLines(options, irb);
  progress("the language server: an edit, its diagnostics, a hover");
  out["lsp"] = lspAfterEdit(options);
  progress("the debugger: reverse steps in process; pause and disconnect sent to robotsim dap while it runs");
  out["reverse"] = reverseSteps(options, irb);
  const std::string loop = writeInput(options, "moves/loop.rsp", kLoop);
  writeInput(options, "moves/big.rsd", std::string(kBigGantry));
  const std::string big = writeInput(
      options, "moves/big.rsp", "; cell: big.rsd\nloop:   MOVETO -7000000\n        MOVES FAR\n        GOTO loop\nPOINTS\nFAR 7000000\n");
  out["dap_loop"] = pauseAndDisconnect(options, "a MOVES loop on the IRB 120", loop);
  out["dap_gantry"] = pauseAndDisconnect(options, "a gantry of 65,536-knot lines", big);
  progress("grading a MOVES submission that never ends (robotsim test --spec, -j 1, whole process)");
  out["grading"] = grading(options);
  return out;
}

}  // namespace rs::bench
