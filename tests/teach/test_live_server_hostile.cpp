// The live-view server against hostile and careless clients (issue 26):
// slow and half-open connections and event streams nobody reads must not
// hold up a jog; connections are bounded per client; a request must be
// whole in time; Host and Origin must be this server's own (no DNS
// rebinding, no cross-origin command); bodies are limited to 16 KiB
// whatever their Content-Type; numbers that do not fit are malformed, not
// wrapped; point names the compiler would refuse are refused.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <thread>

#include "../render/render_test_util.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tests/teach/raw_http.h"
#include "tools/live/live_server.h"
#include "tools/teach/page.h"
#include "tools/teach/pendant_source.h"

// Last: its <resolv.h> defines _res, a name Eigen's headers use.
#include <httplib.h>

namespace {

using nlohmann::json;
using rawhttp::Socket;

const std::string kHostileProgram = "        END\nPOINTS\nHOME  0 0 0 0\n";

// A pendant on the gantry cell behind a server with `limits`.
struct HostileServed {
  rs::testing::TempDir dir;
  std::string path = dir.write("p.rsp", kHostileProgram);
  std::shared_ptr<const rs::workcell::Workcell> cell =
      std::make_shared<const rs::workcell::Workcell>(rendertest::cell("gantry-cell"));
  std::unique_ptr<rs::teach::Pendant> pendant;
  std::unique_ptr<rs::teach::PendantSource> source;
  std::unique_ptr<rs::live::LiveServer> server;
  explicit HostileServed(rs::live::LiveLimits limits = {}) {
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    pendant = std::make_unique<rs::teach::Pendant>(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
    source = std::make_unique<rs::teach::PendantSource>(*pendant, rs::teach::teachPageHtml(*cell, path));
    server = std::make_unique<rs::live::LiveServer>(*source, rs::live::randomToken(), limits);
    std::string error;
    REQUIRE(server->start("127.0.0.1", 0, error));
  }
  int port() const { return server->port(); }
  std::string host() const { return fmt::format("127.0.0.1:{}", port()); }
  std::string q(const std::string& route) const { return route + "?token=" + server->token(); }
  // A whole request as bytes, with the headers given (Host first unless given).
  std::string request(const std::string& method, const std::string& route, const std::string& headers,
                      const std::string& body = {}) const {
    std::string head = fmt::format("{} {} HTTP/1.1\r\n", method, q(route));
    if (headers.find("Host:") == std::string::npos) head += "Host: " + host() + "\r\n";
    head += headers;
    if (!body.empty()) head += fmt::format("Content-Length: {}\r\n", body.size());
    return head + "\r\n" + body;
  }
  // One request on a fresh connection; the response.
  std::string exchange(const std::string& bytes) const {
    Socket s(port());
    s.send(bytes);
    return s.receiveResponse(10);
  }
  json state() const { return json::parse(rawhttp::bodyOf(exchange(request("GET", "/api/state", "")))); }
  // A jog on a fresh connection (cpp-httplib's client); its time.
  std::chrono::duration<double> jog() const {
    httplib::Client c("127.0.0.1", port());
    c.set_read_timeout(30, 0);
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = c.Post(q("/api/command"), R"({"op":"jog","motor":0,"delta":1})", "application/json");
    const auto took = std::chrono::steady_clock::now() - t0;
    REQUIRE(r);
    CHECK(r->status == 200);
    return took;
  }
};

// What a request's connection gets, waiting for the server to act.
template <typename Done>
bool within(double seconds, Done&& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

}  // namespace

TEST_CASE("50 slow connections and 8 streams nobody reads do not hold up a jog", "[teach][live][hostile]") {
  // Before: 8 worker threads, each held by a connection until it sent a
  // whole request (or its 5 s keep-alive wait ran out), and by an event
  // stream for as long as it was open: the jog waited for ever.
  HostileServed s;
  std::vector<Socket> slow;
  for (int i = 0; i < 25; ++i) slow.emplace_back(s.port());  // half-open: connected, nothing sent
  for (int i = 0; i < 25; ++i) {                             // a request cut short: the head never ends
    slow.emplace_back(s.port());
    slow.back().send(
        fmt::format("POST {} HTTP/1.1\r\nHost: {}\r\nContent-Length: 40\r\nX-Slow: ", s.q("/api/command"), s.host()));
  }
  std::vector<Socket> streams;
  for (int i = 0; i < 8; ++i) {  // eight browser tabs that never read
    streams.emplace_back(s.port(), 4096);
    streams.back().send(s.request("GET", "/api/events", ""));
  }
  REQUIRE(within(5, [&] { return s.server->eventStreams() == 8; }));
  double slowest = 0;
  for (int i = 0; i < 20; ++i) slowest = std::max(slowest, s.jog().count());
  // 100 ms is the promise (docs/teach.md has the measured figure, far
  // under it); the bound is generous for sanitizer builds on a busy machine.
  INFO("slowest jog: " << slowest * 1000 << " ms");
  CHECK(slowest < 1.0);
  CHECK(s.state()["encoders"][0] == 20);
  // The slow ones are still connected, unanswered: nothing was cut to make room.
  CHECK(s.server->connections() >= 58);
}

TEST_CASE("event streams hold no worker: one worker serves jogs beside 30 open streams", "[teach][live][hostile]") {
  rs::live::LiveLimits limits;
  limits.workers = 1;
  HostileServed s(limits);
  std::vector<Socket> streams;
  for (int i = 0; i < 30; ++i) {
    streams.emplace_back(s.port());
    streams.back().send(s.request("GET", "/api/events", ""));
  }
  REQUIRE(within(5, [&] { return s.server->eventStreams() == 30; }));
  for (int i = 0; i < 5; ++i) CHECK(s.jog().count() < 1.0);
  // Every stream got the state at once and then the newest after the jogs.
  for (Socket& stream : streams) {
    const std::string got =
        stream.receive(5, [](const std::string& g) { return g.find("\"revision\":6") != std::string::npos; });
    CHECK(got.starts_with("HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\n"));
    CHECK(got.find("\"revision\":6") != std::string::npos);
  }
}

TEST_CASE("event streams beyond the limit are refused with 503 and a reason", "[teach][live][hostile]") {
  rs::live::LiveLimits limits;
  limits.maxEventStreams = 3;
  HostileServed s(limits);
  std::vector<Socket> streams;
  for (int i = 0; i < 3; ++i) {
    streams.emplace_back(s.port());
    streams.back().send(s.request("GET", "/api/events", ""));
  }
  REQUIRE(within(5, [&] { return s.server->eventStreams() == 3; }));
  const std::string refused = s.exchange(s.request("GET", "/api/events", ""));
  CHECK(rawhttp::statusOf(refused) == 503);
  CHECK(json::parse(rawhttp::bodyOf(refused))["message"] ==
        "3 event streams are open, the most this server keeps: close a page");
  streams.pop_back();  // a tab closed: its place is free again
  REQUIRE(within(5, [&] { return s.server->eventStreams() == 2; }));
  Socket again(s.port());
  again.send(s.request("GET", "/api/events", ""));
  CHECK(again.receive(5, [](const std::string& g) { return g.find("data: ") != std::string::npos; })
            .starts_with("HTTP/1.1 200 OK"));
}

TEST_CASE("a stream that does not read gets the newest state, not a pile of old ones", "[teach][live][hostile]") {
  HostileServed s;
  Socket stream(s.port(), 2048);
  stream.send(s.request("GET", "/api/events", ""));
  REQUIRE(within(5, [&] { return s.server->eventStreams() == 1; }));
  for (int i = 0; i < 60; ++i) s.jog();
  const std::string got =
      stream.receive(10, [](const std::string& g) { return g.find("\"revision\":61") != std::string::npos; });
  CHECK(got.find("\"revision\":61") != std::string::npos);
  // 61 states of about 3 KB each were made; far fewer went to this stream.
  std::size_t events = 0;
  for (std::size_t at = 0; (at = got.find("data: ", at)) != std::string::npos; ++at) ++events;
  INFO(events << " events sent");
  CHECK(events < 61);
}

TEST_CASE("connections beyond the bound per client take the place of the longest idle", "[teach][live][hostile]") {
  rs::live::LiveLimits limits;
  limits.maxConnectionsPerClient = 10;
  HostileServed s(limits);
  std::vector<Socket> idle;
  for (int i = 0; i < 30; ++i) idle.emplace_back(s.port());
  REQUIRE(within(5, [&] { return s.server->connections() == 10; }));
  // The first twenty were closed by the server to make room, the last ten are open.
  for (int i = 0; i < 30; ++i) {
    idle[static_cast<std::size_t>(i)].receive(i < 20 ? 5 : 0.05, [](const std::string&) { return false; });
    INFO("connection " << i);
    CHECK(idle[static_cast<std::size_t>(i)].closedByServer() == (i < 20));
  }
  CHECK(s.jog().count() < 1.0);  // a new client still gets in
  CHECK(s.server->connections() <= 10);
}

TEST_CASE("a request not whole in time gets 408, an idle connection just ends", "[teach][live][hostile]") {
  rs::live::LiveLimits limits;
  limits.requestTimeout = std::chrono::milliseconds(200);
  HostileServed s(limits);
  Socket partial(s.port());
  partial.send("GET /api/state HTTP/1.1\r\nHost: " + s.host() + "\r\n");
  const std::string answer = partial.receiveAll(5);
  CHECK(rawhttp::statusOf(answer) == 408);
  CHECK(partial.closedByServer());
  Socket idle(s.port());
  CHECK(idle.receiveAll(5).empty());
  CHECK(idle.closedByServer());
  // A keep-alive connection between requests is idle too.
  Socket kept(s.port());
  kept.send(s.request("GET", "/api/state", ""));
  CHECK(rawhttp::statusOf(kept.receiveResponse(5)) == 200);
  CHECK(kept.receiveAll(5).empty());
  CHECK(kept.closedByServer());
}

TEST_CASE("only this server's own Host and Origin: DNS rebinding and cross-origin posts refused",
          "[teach][live][hostile]") {
  HostileServed s;
  const std::string jog = R"({"op":"jog","motor":0,"delta":7})";
  const auto status = [&](const std::string& headers, const std::string& method = "GET",
                          const std::string& route = "/api/state", const std::string& body = {}) {
    return rawhttp::statusOf(s.exchange(s.request(method, route, headers, body)));
  };
  // The names no one else controls, on this port.
  CHECK(status("") == 200);
  CHECK(status(fmt::format("Host: localhost:{}\r\n", s.port())) == 200);
  CHECK(status(fmt::format("Host: LOCALHOST:{}\r\n", s.port())) == 200);
  CHECK(status(fmt::format("Host: [::1]:{}\r\n", s.port())) == 200);
  CHECK(status(fmt::format("Host: 127.0.0.2:{}\r\n", s.port())) == 200);
  // A DNS name (rebound to 127.0.0.1 by its owner), another port, none at all.
  const std::string rebound =
      s.exchange(s.request("GET", "/api/state", fmt::format("Host: evil.example:{}\r\n", s.port())));
  CHECK(rawhttp::statusOf(rebound) == 403);
  CHECK_THAT(json::parse(rawhttp::bodyOf(rebound))["message"].get<std::string>(),
             Catch::Contains(fmt::format("not to 'evil.example:{}'", s.port())));
  CHECK(status(fmt::format("Host: localhost.evil.example:{}\r\n", s.port())) == 403);
  CHECK(status(fmt::format("Host: 127.0.0.1:{}\r\n", s.port() + 1)) == 403);
  CHECK(status("Host: 127.0.0.1\r\n") == 403);
  CHECK(status("Host: \r\n") == 403);
  const std::string noHost = fmt::format("GET {} HTTP/1.1\r\n\r\n", s.q("/api/state"));
  CHECK(rawhttp::statusOf(s.exchange(noHost)) == 403);
  // Origin: the page's own, or none (a tool); never another site's or "null".
  const std::string self = fmt::format("Origin: http://{}\r\n", s.host());
  CHECK(status(self, "POST", "/api/command", jog) == 200);
  CHECK(status("", "POST", "/api/command", jog) == 200);
  const int before = s.state()["encoders"][0];
  CHECK(status("Origin: http://evil.example\r\nContent-Type: text/plain\r\n", "POST", "/api/command", jog) == 403);
  CHECK(status(fmt::format("Origin: http://localhost:{}\r\n", s.port()), "POST", "/api/command", jog) == 403);
  CHECK(status("Origin: null\r\n", "POST", "/api/command", jog) == 403);
  CHECK(status("Sec-Fetch-Site: cross-site\r\n", "POST", "/api/command", jog) == 403);
  CHECK(status("Sec-Fetch-Site: same-site\r\n", "POST", "/api/command", jog) == 403);
  CHECK(status("Sec-Fetch-Site: same-origin\r\n" + self, "POST", "/api/command", jog) == 200);
  // The page opened from another site's link (a navigation) is served; a
  // cross-site read of the state or a cross-site form's POST is not.
  CHECK(status("Sec-Fetch-Site: cross-site\r\nSec-Fetch-Mode: navigate\r\n", "GET", "/") == 200);
  CHECK(status("Sec-Fetch-Site: cross-site\r\nSec-Fetch-Mode: cors\r\n", "GET", "/api/state") == 403);
  CHECK(status("Sec-Fetch-Site: cross-site\r\nSec-Fetch-Mode: navigate\r\n", "POST", "/api/command", jog) == 403);
  CHECK(s.state()["encoders"][0] == before + 7);  // only that last one moved it
  // A cross-origin teach writes nothing.
  CHECK(status("Origin: http://evil.example\r\nContent-Type: text/plain\r\n", "POST", "/api/command",
               R"({"op":"teach","name":"EVIL"})") == 403);
  CHECK(rs::testing::readBytes(s.path) == kHostileProgram);
}

TEST_CASE("two Host or two Origin headers, an empty Origin, a space before a colon: 400, nothing done",
          "[teach][live][hostile]") {
  // Before, the routes checked the first Host and the first Origin of two
  // (a second one, another site's, passed), an empty Origin counted as
  // none, and `Transfer-Encoding : chunked` was no Transfer-Encoding.
  HostileServed s;
  const std::string jog = R"({"op":"jog","motor":0,"delta":5})";
  const int before = s.state()["encoders"][0];
  const std::string self = fmt::format("Origin: http://{}\r\n", s.host());
  for (const std::string& headers :
       {fmt::format("Host: {}\r\nHost: evil.example:{}\r\n", s.host(), s.port()),
        self + "Origin: http://evil.example\r\n", std::string("Origin:\r\n"),
        std::string("Transfer-Encoding : chunked\r\n"), fmt::format("Host : {}\r\n", s.host())}) {
    CAPTURE(headers);
    Socket c(s.port());
    c.send(s.request("POST", "/api/command", headers, jog));
    const std::string answer = c.receiveAll(10);
    CHECK(rawhttp::statusOf(answer) == 400);
    CHECK(c.closedByServer());
  }
  CHECK(s.state()["encoders"][0] == before);
  CHECK(rawhttp::statusOf(s.exchange(s.request("POST", "/api/command", self, jog))) == 200);
  CHECK(s.state()["encoders"][0] == before + 5);
}

TEST_CASE("a request whose head cannot be read gets 400 and the connection ends", "[teach][live][hostile]") {
  // Found by fuzz_live_http: cpp-httplib answered a request line it could
  // not read itself, with a body even to HEAD, and kept the connection, so
  // a client read that body as the next answer.
  HostileServed s;
  for (const std::string method : {"HEAD", "GET"}) {
    Socket c(s.port());
    // A NUL in the path (cpp-httplib cannot read the request line).
    c.send(fmt::format("{} /api/st{}ate?token={} HTTP/1.1\r\nHost: {}\r\n\r\n", method, std::string(1, '\0'),
                       s.server->token(), s.host()) +
           s.request("GET", "/api/state", ""));
    const std::string answer = c.receiveAll(5);
    INFO(method << ": " << answer);
    CHECK(rawhttp::statusOf(answer) == 400);
    CHECK_THAT(answer, Catch::Contains("Connection: close\r\n"));
    CHECK_THAT(answer, Catch::Contains("a line of its head cannot be read"));
    CHECK(answer.find("HTTP/1.1", 1) == std::string::npos);  // the request after it is not answered
    CHECK(c.closedByServer());
  }
  // A path over cpp-httplib's 8 KiB: 414, ours, and the connection ends too.
  Socket longPath(s.port());
  longPath.send(fmt::format("GET {}&x={} HTTP/1.1\r\nHost: {}\r\n\r\n", s.q("/api/state"), std::string(9000, 'a'),
                            s.host()));
  const std::string tooLong = longPath.receiveAll(5);
  CHECK(rawhttp::statusOf(tooLong) == 414);
  CHECK_THAT(tooLong, Catch::Contains("the request's path is too long"));
  CHECK(longPath.closedByServer());
  CHECK(rawhttp::statusOf(s.exchange(s.request("GET", "/api/state", ""))) == 200);  // and the server goes on
}

TEST_CASE("a head line ending in a bare LF is refused at once: no header hidden from the framing",
          "[teach][live][hostile]") {
  // Found by fuzz_live_http: cpp-httplib ends a header line at a bare LF,
  // the server's framing only at CR LF, so a Content-Length (or an Expect)
  // after a bare LF was read by one and not the other: the body was framed
  // as the next request.
  HostileServed s;
  const std::string jog = R"({"op":"jog","motor":0,"delta":5})";
  Socket c(s.port());
  c.send(fmt::format("POST {} HTTP/1.1\r\nHost: {}\nContent-Length: {}\r\n\r\n{}", s.q("/api/command"), s.host(),
                     jog.size(), jog));
  const std::string answer = c.receiveAll(5);
  CHECK(rawhttp::statusOf(answer) == 400);
  CHECK_THAT(answer, Catch::Contains("ends in a bare LF"));
  CHECK(answer.find("HTTP/1.1", 1) == std::string::npos);
  CHECK(c.closedByServer());
  CHECK(s.state()["encoders"][0] == 0);
}

TEST_CASE("bodies up to 16 KiB whatever their Content-Type, over it 413 saying so", "[teach][live][hostile]") {
  HostileServed s;
  // curl -d's default type: cpp-httplib refused it over 8 KiB as "over 16384 bytes".
  std::string body = R"({"op":"jog","motor":0,"delta":3})";
  body.append(9 * 1024 - body.size(), ' ');
  const std::string form = "Content-Type: application/x-www-form-urlencoded\r\n";
  std::string answer = s.exchange(s.request("POST", "/api/command", form, body));
  CHECK(rawhttp::statusOf(answer) == 200);
  CHECK(json::parse(rawhttp::bodyOf(answer))["ok"] == true);
  body.append(rs::live::kMaxBody - body.size(), ' ');  // exactly the limit
  CHECK(rawhttp::statusOf(s.exchange(s.request("POST", "/api/command", form, body))) == 200);
  body += ' ';
  answer = s.exchange(s.request("POST", "/api/command", form, body));
  CHECK(rawhttp::statusOf(answer) == 413);
  CHECK(json::parse(rawhttp::bodyOf(answer))["message"] ==
        "the body is 16385 bytes; the limit is 16 KiB (16384 bytes)");
  // Refused from its Content-Length, before a byte of it is sent.
  Socket early(s.port());
  early.send(
      fmt::format("POST {} HTTP/1.1\r\nHost: {}\r\nContent-Length: 1000000\r\n\r\n", s.q("/api/command"), s.host()));
  CHECK(rawhttp::statusOf(early.receiveResponse(5)) == 413);
  // Chunked bodies and forms are refused; "Expect: 100-continue" is answered once.
  CHECK(rawhttp::statusOf(s.exchange(s.request("POST", "/api/command", "Transfer-Encoding: chunked\r\n"))) == 411);
  CHECK(rawhttp::statusOf(s.exchange(s.request(
            "POST", "/api/command", "Content-Type: multipart/form-data; boundary=x\r\n", "--x--\r\n"))) == 400);
  Socket expect(s.port());
  const std::string jog = R"({"op":"jog","motor":1,"delta":2})";
  expect.send(fmt::format("POST {} HTTP/1.1\r\nHost: {}\r\nExpect: 100-continue\r\nContent-Length: {}\r\n\r\n",
                          s.q("/api/command"), s.host(), jog.size()));
  CHECK(expect.receive(5, [](const std::string& g) { return g.find("\r\n\r\n") != std::string::npos; }) ==
        "HTTP/1.1 100 Continue\r\n\r\n");
  expect.send(jog);
  answer = expect.receiveResponse(5);
  CHECK(rawhttp::statusOf(answer) == 200);
  CHECK(answer.find("100 Continue") == std::string::npos);
  CHECK(s.state()["encoders"][1] == 2);
}

TEST_CASE("numbers that do not fit 32 bits are malformed, never wrapped", "[teach][live][hostile]") {
  HostileServed s;
  for (const char* body :
       {R"({"op":"jog","motor":0,"delta":18446744073709551615})",
        R"({"op":"jog","motor":0,"delta":9223372036854775808})",
        R"({"op":"jog","motor":0,"delta":-9223372036854775809})", R"({"op":"jog","motor":0,"delta":2147483648})",
        R"({"op":"set","motor":0,"value":18446744073709551615})",
        R"({"op":"jog","motor":18446744073709551615,"delta":1})",
        R"({"op":"moveTo","values":[18446744073709551615,0,0,0]})", R"({"op":"input","line":18446744073709551617})"}) {
    INFO(body);
    const std::string answer = s.exchange(s.request("POST", "/api/command", "", body));
    CHECK(rawhttp::statusOf(answer) == 400);
    CHECK(json::parse(rawhttp::bodyOf(answer))["ok"] == false);
  }
  CHECK(s.state()["encoders"] == json({0, 0, 0, 0}));
  CHECK(rawhttp::statusOf(s.exchange(s.request("POST", "/api/command", "", R"({"op":"jog","motor":0,"delta":-2})"))) ==
        200);
  CHECK(s.state()["encoders"][0] == -2);
}

TEST_CASE("a point name longer than the language allows is refused, the longest allowed compiles",
          "[teach][live][hostile]") {
  HostileServed s;
  const std::string longest(64, 'P'), tooLong(65, 'P');
  std::string answer =
      s.exchange(s.request("POST", "/api/command", "", json({{"op", "teach"}, {"name", tooLong}}).dump()));
  CHECK(json::parse(rawhttp::bodyOf(answer))["message"] == "a point name has at most 64 characters (this one has 65)");
  answer = s.exchange(
      s.request("POST", "/api/command", "", json({{"op", "rename"}, {"from", "HOME"}, {"to", tooLong}}).dump()));
  CHECK(json::parse(rawhttp::bodyOf(answer))["ok"] == false);
  CHECK(rs::testing::readBytes(s.path) == kHostileProgram);
  answer = s.exchange(s.request("POST", "/api/command", "", json({{"op", "teach"}, {"name", longest}}).dump()));
  CHECK(json::parse(rawhttp::bodyOf(answer))["ok"] == true);
  const auto compiled = rs::testing::runCli({"compile", s.path, "-o", s.dir.file("p.rsb"), "--cell", "gantry-cell"});
  INFO(compiled.err);
  CHECK(compiled.code == 0);
}
