#include "teach/live_server.h"

#include <fmt/format.h>
#include <httplib.h>

#include <chrono>
#include <random>

namespace rs::teach {

namespace {

using namespace std::chrono_literals;

constexpr auto kPoll = 30ms;        // how often an event stream looks at the revision
constexpr auto kKeepAlive = 15s;    // a comment line on a quiet stream (finds closed connections)

void json(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

void error(httplib::Response& res, int status, const std::string& message) {
  json(res, status, {{"ok", false}, {"message", message}});
}

}  // namespace

std::string randomToken() {
  std::random_device device;  // /dev/urandom on Linux
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", static_cast<std::uint32_t>(device()));
  return token;
}

bool sameToken(std::string_view a, std::string_view b) {
  // Every byte of the longer one is looked at, whatever matches.
  const std::size_t n = std::max(a.size(), b.size());
  unsigned diff = a.size() == b.size() ? 0u : 1u;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char x = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const unsigned char y = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    diff |= static_cast<unsigned>(x ^ y);
  }
  return diff == 0 && n > 0;
}

struct LiveServer::Impl {
  httplib::Server http;
};

LiveServer::LiveServer(LiveSource& source, std::string token)
    : source_(source), token_(std::move(token)), impl_(std::make_unique<Impl>()) {
  httplib::Server& http = impl_->http;
  http.set_payload_max_length(kMaxBody);
  http.set_tcp_nodelay(true);  // small answers go out at once (no 40 ms delayed-ACK stalls)
  http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("Referrer-Policy", "no-referrer");
    const std::string given =
        req.has_param("token") ? req.get_param_value("token") : req.get_header_value("X-Robotsim-Token");
    if (!sameToken(given, token_)) {
      error(res, 403, "this address needs the token robotsim teach printed");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;
    error(res, res.status, res.status == 404 ? "no such route"
                           : res.status == 413 ? fmt::format("the body is over {} bytes", kMaxBody)
                                               : fmt::format("HTTP {}", res.status));
  });
  http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    error(res, 500, "internal error");
  });
  http.Get("/", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(source_.page(), "text/html; charset=utf-8");
  });
  http.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(source_.state(), "application/json");
  });
  http.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
    std::uint64_t sent = 0;
    res.set_chunked_content_provider("text/event-stream", [this, sent](std::size_t, httplib::DataSink& sink) mutable {
      const auto quietSince = std::chrono::steady_clock::now();
      while (!stopping_.load()) {
        const std::uint64_t now = source_.revision();
        if (now != sent) {
          sent = now;
          const std::string event = "data: " + source_.state() + "\n\n";
          return sink.write(event.data(), event.size());
        }
        if (std::chrono::steady_clock::now() - quietSince > kKeepAlive) return sink.write(":\n\n", 3);
        std::this_thread::sleep_for(kPoll);
      }
      sink.done();
      return false;
    });
  });
  http.Post("/api/command", [this](const httplib::Request& req, httplib::Response& res) {
    const nlohmann::json request = nlohmann::json::parse(req.body, nullptr, false);
    if (request.is_discarded()) return error(res, 400, "the body is not JSON");
    const LiveReply reply = source_.command(request);
    json(res, reply.status, reply.body);
  });
}

LiveServer::~LiveServer() { stop(); }

bool LiveServer::start(const std::string& host, int port, std::string& error) {
  httplib::Server& http = impl_->http;
  host_ = host;
  if (port == 0)
    port_ = http.bind_to_any_port(host);
  else
    port_ = http.bind_to_port(host, port) ? port : -1;
  if (port_ <= 0) {
    error = port == 0 ? fmt::format("cannot listen on {}", host) : fmt::format("cannot listen on {}:{}", host, port);
    return false;
  }
  thread_ = std::thread([this, &http] {
    http.listen_after_bind();
    listenerEnded_.store(true);
  });
  // cpp-httplib's stop() does nothing until the listener runs: a server
  // stopped at once (a debug session that quits at once) would accept for
  // ever and stop() would never return. So start() returns once it runs.
  while (!http.is_running() && !listenerEnded_.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return true;
}

std::string LiveServer::url() const {
  const bool v6 = host_.find(':') != std::string::npos;
  return fmt::format("http://{}{}{}:{}/?token={}", v6 ? "[" : "", host_, v6 ? "]" : "", port_, token_);
}

void LiveServer::stop() {
  stopping_.store(true);
  impl_->http.stop();
  if (thread_.joinable()) thread_.join();
}

}  // namespace rs::teach
