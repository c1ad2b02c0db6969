// The live-view server (tools/live/live_server.h) from a test client
// (cpp-httplib's own client, over 127.0.0.1): the token, the body limit,
// unknown routes, malformed commands, a read-only source, the event
// stream, and jogs sent at once from several clients.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <thread>

#include "../render/render_test_util.h"
#include "launch/program.h"
#include "tests/cli/cli_support.h"
#include "tools/live/live_server.h"
#include "tools/teach/page.h"
#include "tools/teach/pendant_source.h"

// Last: its <resolv.h> defines _res, a name Eigen's headers use.
#include <httplib.h>

namespace {

using nlohmann::json;

const std::string kProgram = "        END\nPOINTS\nHOME  0 0 0 0\n";

// A pendant on the gantry cell, its source and a server on a free port.
struct Served {
  rs::testing::TempDir dir;
  std::string path = dir.write("p.rsp", kProgram);
  std::shared_ptr<const rs::workcell::Workcell> cell =
      std::make_shared<const rs::workcell::Workcell>(rendertest::cell("gantry-cell"));
  std::unique_ptr<rs::teach::Pendant> pendant;
  std::unique_ptr<rs::teach::PendantSource> source;
  std::unique_ptr<rs::live::LiveServer> server;
  Served() {
    rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(path);
    REQUIRE(file);
    pendant = std::make_unique<rs::teach::Pendant>(cell, rs::launch::cellTarget(*cell).motors, std::move(*file));
    source = std::make_unique<rs::teach::PendantSource>(*pendant, rs::teach::teachPageHtml(*cell, path));
    server = std::make_unique<rs::live::LiveServer>(*source, rs::live::randomToken());
    std::string error;
    REQUIRE(server->start("127.0.0.1", 0, error));
  }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", server->port());
    c.set_read_timeout(5, 0);
    return c;
  }
  std::string q(const std::string& route) const { return route + "?token=" + server->token(); }
};

// A source that only shows: what the debugger serves for a stopped run.
class ReadOnly final : public rs::live::LiveSource {
 public:
  std::string page() override { return "<!DOCTYPE html><title>view</title>"; }
  std::uint64_t revision() override { return 7; }
  std::string state() override { return R"({"stopped":true})"; }
  rs::live::LiveReply command(const json&) override {
    return {403, {{"ok", false}, {"message", "this view is read-only"}}};
  }
};

}  // namespace

TEST_CASE("live server: tokens, compared whole", "[teach]") {
  const std::string t = rs::live::randomToken();
  CHECK(t.size() == 32);
  CHECK(t.find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(t != rs::live::randomToken());
  CHECK(rs::live::sameToken(t, t));
  CHECK_FALSE(rs::live::sameToken(t, t.substr(0, 31)));
  CHECK_FALSE(rs::live::sameToken(t, t + "0"));
  CHECK_FALSE(rs::live::sameToken("", ""));
  std::string other = t;
  other[31] = other[31] == 'a' ? 'b' : 'a';
  CHECK_FALSE(rs::live::sameToken(t, other));
}

TEST_CASE("live server: every route needs the token, bad requests get 4xx", "[teach]") {
  Served s;
  httplib::Client c = s.client();
  CHECK(c.Get("/")->status == 403);
  CHECK(c.Get("/api/state?token=")->status == 403);
  CHECK(c.Get("/api/state?token=" + s.server->token().substr(1))->status == 403);
  CHECK(c.Get("/?token=" + rs::live::randomToken())->status == 403);
  const auto page = c.Get(s.q("/"));
  REQUIRE(page);
  CHECK(page->status == 200);
  CHECK(page->body.find("<script type=\"application/json\" id=\"robotsim-model\">") != std::string::npos);
  CHECK(page->body.find("function robotsimDrawing(model, canvas)") != std::string::npos);  // the shared code
  CHECK(page->get_header_value("Referrer-Policy") == "no-referrer");
  httplib::Headers byHeader{{"X-Robotsim-Token", s.server->token()}};
  CHECK(c.Get("/api/state", byHeader)->status == 200);
  CHECK(c.Get(s.q("/api/nothing"))->status == 404);
  CHECK(c.Get(s.q("/../p.rsp"))->status == 404);  // the client never names a file
  CHECK(c.Post(s.q("/api/state"), "{}", "application/json")->status == 404);
  CHECK(c.Post(s.q("/api/command"), "not json", "application/json")->status == 400);
  const auto malformed = c.Post(s.q("/api/command"), R"({"op":"jog","motor":"E"})", "application/json");
  CHECK(malformed->status == 400);
  CHECK(json::parse(malformed->body)["ok"] == false);
  const std::string big(rs::live::kMaxBody + 1, ' ');
  CHECK(c.Post(s.q("/api/command"), big, "application/json")->status == 413);
  CHECK(c.Post("/api/command", R"({"op":"reset"})", "application/json")->status == 403);  // no token: nothing done
  // A refusal as things stand is an answer, not a bad request.
  const auto refused = c.Post(s.q("/api/command"), R"({"op":"goTo","name":"NOWHERE"})", "application/json");
  CHECK(refused->status == 200);
  CHECK(json::parse(refused->body)["message"] == "there is no point NOWHERE");
  // Still serving after all that.
  const auto jog = c.Post(s.q("/api/command"), R"({"op":"jog","motor":0,"delta":5})", "application/json");
  REQUIRE(jog);
  CHECK(json::parse(jog->body)["ok"] == true);
  CHECK(json::parse(c.Get(s.q("/api/state"))->body)["encoders"] == json({5, 0, 0, 0}));
  CHECK(*rs::base::readFile(s.path, 1 << 20).bytes == kProgram);
}

TEST_CASE("live server: jogs from several clients at once all happen, one at a time", "[teach]") {
  Served s;
  constexpr int kClients = 4, kJogs = 10;
  std::vector<std::thread> threads;
  std::atomic<int> ok = 0;
  for (int t = 0; t < kClients; ++t)
    threads.emplace_back([&s, &ok, t] {
      httplib::Client c = s.client();
      for (int k = 0; k < kJogs; ++k) {
        const json body = {{"op", "jog"}, {"motor", t % 2}, {"delta", 1}};
        if (auto r = c.Post(s.q("/api/command"), body.dump(), "application/json"); r && r->status == 200) ++ok;
      }
    });
  for (std::thread& t : threads) t.join();
  CHECK(ok == kClients * kJogs);
  httplib::Client c = s.client();
  const json state = json::parse(c.Get(s.q("/api/state"))->body);
  CHECK(state["encoders"] == json({kClients / 2 * kJogs, kClients / 2 * kJogs, 0, 0}));
  CHECK(state["revision"] == 1 + kClients * kJogs);
  // X moved 20 counts and Z 20, one count at a time at 1000 counts/s.
  CHECK(state["clock"] == 40 * 1000);
}

TEST_CASE("live server: the event stream sends the state, then each new revision", "[teach]") {
  Served s;
  std::vector<json> events;
  std::atomic<std::size_t> received = 0;
  std::string buffer;
  std::thread reader([&] {
    httplib::Client c = s.client();
    c.Get(s.q("/api/events"), [&](const char* data, std::size_t n) {
      buffer.append(data, n);
      for (std::size_t end; (end = buffer.find("\n\n")) != std::string::npos; buffer.erase(0, end + 2))
        if (buffer.starts_with("data: ")) events.push_back(json::parse(buffer.substr(6, end - 6))), ++received;
      return received < 2;
    });
  });
  // The first event is the state as it is; the input switched makes the second.
  for (int i = 0; i < 250 && received == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  REQUIRE(received == 1);
  httplib::Client c = s.client();
  REQUIRE(c.Post(s.q("/api/command"), R"({"op":"input","line":2})", "application/json"));
  reader.join();
  REQUIRE(events.size() == 2);
  CHECK(events[0]["revision"] == 1);
  CHECK(events[1]["revision"] == 2);
  CHECK(events[1]["inputs"][1] == true);
}

TEST_CASE("live server: stop ends an open event stream at once", "[teach]") {
  Served s;
  std::atomic<int> received = 0;
  std::thread reader([&] {
    httplib::Client c = s.client();
    c.Get(s.q("/api/events"), [&](const char*, std::size_t) { return ++received, true; });
  });
  for (int i = 0; i < 250 && received == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  REQUIRE(received > 0);
  const auto t0 = std::chrono::steady_clock::now();
  s.server->stop();
  reader.join();
  // The stream looks at the stop flag every 30 ms; a second is a generous bound.
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(1));
}

TEST_CASE("live server: a read-only source refuses every command", "[teach]") {
  ReadOnly source;
  rs::live::LiveServer server(source, "0123456789abcdef0123456789abcdef");
  std::string error;
  REQUIRE(server.start("127.0.0.1", 0, error));
  CHECK(server.url() == fmt::format("http://127.0.0.1:{}/?token=0123456789abcdef0123456789abcdef", server.port()));
  httplib::Client c("127.0.0.1", server.port());
  const auto r = c.Post("/api/command?token=0123456789abcdef0123456789abcdef", R"({"op":"jog"})", "application/json");
  REQUIRE(r);
  CHECK(r->status == 403);
  CHECK(json::parse(r->body)["message"] == "this view is read-only");
  CHECK(c.Get("/api/state?token=0123456789abcdef0123456789abcdef")->body == R"({"stopped":true})");
  server.stop();
  CHECK_FALSE(c.Get("/api/state?token=0123456789abcdef0123456789abcdef"));  // nobody listens any more
}

TEST_CASE("live server: any body gets 200 or 400, never a crash or a 500", "[teach]") {
  Served s;
  httplib::Client c = s.client();
  // A deterministic soup: raw bytes, JSON of every type, and commands with
  // every op and arguments of the wrong type, missing, huge or negative.
  std::uint64_t seed = 12345;
  const auto next = [&seed] { return seed = seed * 6364136223846793005ULL + 1442695040888963407ULL, seed >> 33; };
  const std::vector<std::string> ops = {"jog", "set", "moveTo", "gripper", "teach", "reteach", "delete", "rename",
                                        "goTo", "input", "output", "reset", "readPosition", "reload", "", "JOG"};
  const std::vector<json> values = {json(), json(true), json(-1), json(0), json(3), json(1e300), json(-2147483649LL),
                                    json("P1"), json("HOME"), json(""), json::array({1, 2, 3, 4}), json::object()};
  for (int i = 0; i < 300; ++i) {
    std::string body;
    if (i % 3 == 0) {
      for (std::uint64_t n = next() % 40; n > 0; --n) body += static_cast<char>(next() % 256);
    } else {
      json j = {{"op", ops[next() % ops.size()]}};
      for (const char* key : {"motor", "delta", "value", "values", "close", "name", "from", "to", "line", "on"})
        if (next() % 3 == 0) j[key] = values[next() % values.size()];
      body = j.dump();
    }
    const auto r = c.Post(s.q("/api/command"), body, "application/json");
    REQUIRE(r);
    INFO(body);
    CHECK((r->status == 200 || r->status == 400));
  }
  const auto state = c.Get(s.q("/api/state"));
  REQUIRE(state);
  CHECK(state->status == 200);
}

TEST_CASE("a live server stopped the moment it started stops (a debug session that quits at once)",
          "[teach][live]") {
  // Before start() waited for the listener, stop() could come before
  // cpp-httplib's listener ran; it then did nothing and the join hung.
  ReadOnly source;
  for (int i = 0; i < 50; ++i) {
    rs::live::LiveServer server(source, rs::live::randomToken());
    std::string error;
    REQUIRE(server.start("127.0.0.1", 0, error));
    server.stop();
  }
}
