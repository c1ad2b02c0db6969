// teach_bench (run by `make bench`): what a teach pendant's actions cost.
// A POINTS edit on a program of 10,000 points (the edit re-lays one row
// but rescans the section), a whole guarded write (read back, hash,
// atomic write) of a 1,000-point program, and a jog's round trip through
// the live server on 127.0.0.1 (HTTP POST, the simulated move, the state
// republished), with the page's and the state's sizes, alone and beside
// 50 slow connections (25 silent, 25 with a request cut short) and 8 event
// streams that never read (issue 26: eight of them froze the pendant).
// Prints figures for docs/performance.md; not a test.
//
//   teach_bench [--smoke] [POINTS [REPS [JOGS]]]
#include <arpa/inet.h>
#include <fmt/format.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <stdlib.h>

#include <filesystem>
#include <thread>
#include <vector>

#include "base/file_io.h"
#include "bench/bench_args.h"
#include "compiler/description/library.h"
#include "launch/program.h"
#include "tools/live/live_server.h"
#include "tools/teach/page.h"
#include "tools/teach/pendant_source.h"

// Last: its <resolv.h> defines _res, a name Eigen's headers use.
#include <httplib.h>

namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

// A connection to 127.0.0.1:port that sends `bytes` and then nothing, never reading.
int slowClient(int port, const std::string& bytes, int receiveBuffer) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (receiveBuffer > 0) ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receiveBuffer, sizeof receiveBuffer);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) return -1;
  if (!bytes.empty() && ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) < 0) return -1;
  return fd;
}

struct Stats {
  double median = 0, p95 = 0, best = 0;
};
Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v[v.size() * 95 / 100], v.front()};
}

int fail(const std::string& why) {
  fmt::print(stderr, "teach_bench: error: {}\n", why);
  return 1;
}

std::string program(int points) {
  std::string text = "        MOVEP P0                ; a program\n        END\nPOINTS\n";
  for (int i = 0; i < points; ++i) text += fmt::format("P{:<6} {:5} {:5} {:5} {:5} {:5}\n", i, i % 900, -i % 500, 0, 0, 0);
  return text;
}

constexpr rs::bench::CountArgument kTeachCounts[] = {
    {"POINTS", "points of the program edited", 10'000, 100},
    {"REPS", "edits and guarded writes timed (median printed)", 21, 3},
    {"JOGS", "jogs over HTTP timed", 500, 10}};

}  // namespace

int main(int argc, char** argv) {
  const rs::bench::BenchArguments args = rs::bench::parseBenchArguments(
      argc, argv, "teach_bench", "The teach pendant: POINTS edits, guarded writes, a jog over HTTP (docs/performance.md).",
      kTeachCounts);
  if (args.exitCode) return *args.exitCode;
  const int points = static_cast<int>(args[0]), reps = static_cast<int>(args[1]), jogCount = static_cast<int>(args[2]);
  using rs::teach::PointsText;
  const std::vector<std::int32_t> values{1, 2, 3, 4, 5};
  {
    const std::string text = program(points);
    std::vector<double> add, replace;
    for (int r = 0; r < reps; ++r) {
      PointsText p(text);
      auto t0 = Clock::now();
      if (!p.add("NEWPOINT", values).empty()) return fail("a POINTS add was refused");
      auto t1 = Clock::now();
      if (!p.replace(fmt::format("P{}", points / 2), values).empty()) return fail("a POINTS replace was refused");
      auto t2 = Clock::now();
      add.push_back(micros(t1 - t0)), replace.push_back(micros(t2 - t1));
    }
    const Stats a = stats(add), b = stats(replace);
    fmt::print("POINTS edit, {} points ({} KiB): add median {:.0f} us (best {:.0f}), replace median {:.0f} us\n", points,
               text.size() / 1024, a.median, a.best, b.median);
  }
  // A folder of its own: two runs at once (two build trees' tests) must
  // not remove each other's files.
  std::string pattern = (std::filesystem::temp_directory_path() / "robotsim-teach-bench-XXXXXX").string();
  if (!mkdtemp(pattern.data())) return fail("cannot make a temporary folder");
  const std::filesystem::path dir = pattern;
  {
    const std::string path = (dir / "big.rsp").string();
    std::string error;
    if (!rs::base::writeFileAtomically(path, program(1'000), error)) return fail(error);
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    if (!file) return fail(file.failure().message);
    std::vector<double> writes;
    for (int r = 0; r < reps; ++r) {
      const auto t0 = Clock::now();
      if (!file->change([&](PointsText& p) { const std::vector<std::int32_t> v{r, 0, 0, 0, 0};
        return p.replace("P10", v); }).empty()) return fail("a guarded write was refused");
      writes.push_back(micros(Clock::now() - t0));
    }
    const Stats w = stats(writes);
    fmt::print("guarded write of a 1,000-point program: median {:.0f} us, p95 {:.0f} us\n", w.median, w.p95);
  }
  {
    rs::compiler::Library library(rs::compiler::librarySearchPath({}));
    auto cell = std::make_shared<const rs::workcell::Workcell>(*library.workcell("scara-pick"));
    const std::string path = (dir / "jog.rsp").string();
    std::string error;
    if (!rs::base::writeFileAtomically(path, "        END\nPOINTS\n", error)) return fail(error);
    rs::diag::Result<rs::teach::ProgramFile> jogFile = rs::teach::ProgramFile::load(path);
    if (!jogFile) return fail(jogFile.failure().message);
    rs::teach::Pendant pendant(cell, rs::launch::cellTarget(*cell).motors, *jogFile);
    rs::teach::PendantSource source(pendant, rs::teach::teachPageHtml(*cell, path));
    rs::live::LiveServer server(source, rs::live::randomToken());
    if (!server.start("127.0.0.1", 0, error)) return fail(error);
    httplib::Client client("127.0.0.1", server.port());
    client.set_keep_alive(true);
    client.set_tcp_nodelay(true);
    const std::string route = "/api/command?token=" + server.token();
    std::vector<double> jogs;
    for (int i = 0; i < jogCount; ++i) {
      const std::string body = fmt::format(R"({{"op":"jog","motor":0,"delta":{}}})", i % 2 ? -10 : 10);
      const auto t0 = Clock::now();
      const auto r = client.Post(route, body, "application/json");
      if (!r || r->status != 200) return fail("a jog was not answered 200");
      jogs.push_back(micros(Clock::now() - t0));
    }
    const Stats j = stats(jogs);
    fmt::print("jog round trip over HTTP (scara-pick, keep-alive): median {:.0f} us, p95 {:.0f} us\n", j.median, j.p95);
    // The same beside clients that hold connections and streams open.
    std::vector<int> slow;
    const std::string host = fmt::format("Host: 127.0.0.1:{}\r\n", server.port());
    for (int i = 0; i < 25; ++i) slow.push_back(slowClient(server.port(), "", 0));
    for (int i = 0; i < 25; ++i)
      slow.push_back(
          slowClient(server.port(), "POST " + route + " HTTP/1.1\r\n" + host + "Content-Length: 40\r\nX-Slow: ", 0));
    for (int i = 0; i < 8; ++i)
      slow.push_back(
          slowClient(server.port(), "GET /api/events?token=" + server.token() + " HTTP/1.1\r\n" + host + "\r\n", 4096));
    if (std::find(slow.begin(), slow.end(), -1) != slow.end()) return 1;
    for (int i = 0; i < 200 && server.eventStreams() < 8; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::vector<double> crowded, fresh;
    for (int i = 0; i < 500; ++i) {
      const std::string body = fmt::format(R"({{"op":"jog","motor":0,"delta":{}}})", i % 2 ? -10 : 10);
      auto t0 = Clock::now();
      const auto r = client.Post(route, body, "application/json");
      if (!r || r->status != 200) return 1;
      crowded.push_back(micros(Clock::now() - t0));
      if (i % 5 == 0) {  // a new connection each time: accepted beside the crowd
        httplib::Client once("127.0.0.1", server.port());
        t0 = Clock::now();
        const auto f = once.Post(route, body, "application/json");
        if (!f || f->status != 200) return 1;
        fresh.push_back(micros(Clock::now() - t0));
      }
    }
    const Stats c = stats(crowded), f = stats(fresh);
    fmt::print(
        "jog beside 50 slow connections and 8 unread event streams: median {:.0f} us ({:.2f}x alone), p95 {:.0f} us, "
        "slowest {:.0f} us; on a new connection each: median {:.0f} us, slowest {:.0f} us\n",
        c.median, c.median / j.median, c.p95, *std::max_element(crowded.begin(), crowded.end()), f.median,
        *std::max_element(fresh.begin(), fresh.end()));
    for (int fd : slow) ::close(fd);
    fmt::print("page {} KiB, state {} bytes after a jog (with its motion frames)\n", source.page().size() / 1024,
               source.state().size());
  }
  std::filesystem::remove_all(dir);
  return 0;
}
