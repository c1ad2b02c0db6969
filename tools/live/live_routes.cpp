#include "tools/live/live_routes.h"

#include <fmt/format.h>
#include <httplib.h>

#include <cstdlib>
#include <cstring>
#include <random>

#include "base/file_io.h"
#include "tools/live/http_frame.h"

namespace rs::live {

namespace {

// The answer the handlers of the request being answered on this thread
// fill in (cpp-httplib's handlers see only the request and the response).
thread_local LiveAnswer* tAnswer = nullptr;
// Whether cpp-httplib read the request far enough to route it (its
// pre-routing handler ran); when not, it answers on its own, without our
// headers, and keeps the connection.
thread_local bool tRouted = false;

void replyJson(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

void replyError(httplib::Response& res, int status, const std::string& message) {
  replyJson(res, status, {{"ok", false}, {"message", message}});
}

// One request in memory for cpp-httplib's reader, its response into a string.
class MemoryStream final : public httplib::Stream {
 public:
  MemoryStream(std::string_view in, std::string& out, const std::string& peer) : in_(in), out_(out), peer_(peer) {}
  bool is_readable() const override { return true; }
  bool is_writable() const override { return true; }
  ssize_t read(char* ptr, size_t size) override {
    const std::size_t n = std::min(size, in_.size() - at_);
    std::memcpy(ptr, in_.data() + at_, n);
    at_ += n;
    return static_cast<ssize_t>(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    out_.append(ptr, size);
    return static_cast<ssize_t>(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override { ip = peer_, port = 0; }
  void get_local_ip_and_port(std::string& ip, int& port) const override { ip.clear(), port = 0; }
  socket_t socket() const override { return INVALID_SOCKET; }

 private:
  std::string_view in_;
  std::size_t at_ = 0;
  std::string& out_;
  const std::string& peer_;
};

const char* reasonOf(int status) {
  switch (status) {
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 408: return "Request Timeout";
    case 411: return "Length Required";
    case 413: return "Payload Too Large";
    case 414: return "URI Too Long";
    case 431: return "Request Header Fields Too Large";
    case 503: return "Service Unavailable";
    default: return "Error";
  }
}

constexpr std::string_view kSafetyHeaders =
    "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nReferrer-Policy: no-referrer\r\n";

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

std::string plainResponse(int status, std::string_view message, bool close) {
  const nlohmann::json body = {{"ok", false}, {"message", message}};
  const std::string text = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return fmt::format("HTTP/1.1 {} {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\n{}{}\r\n{}", status,
                     reasonOf(status), text.size(), kSafetyHeaders, close ? "Connection: close\r\n" : "", text);
}

std::string eventStreamHead() {
  return fmt::format("HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\n{}Connection: close\r\n\r\n",
                     kSafetyHeaders);
}

std::string stateEvent(std::string_view state) { return fmt::format("data: {}\n\n", state); }

std::string_view keepAliveEvent() { return ":\n\n"; }

// cpp-httplib's server, used for what it does well (parsing, routing,
// writing responses) and not for its sockets: process_request is what it
// runs for each request of a connection.
struct LiveRoutes::Http : httplib::Server {
  using httplib::Server::process_request;
};

LiveRoutes::LiveRoutes(LiveSource& source, std::string token, ServerAddress address)
    : source_(source), token_(std::move(token)), address_(std::move(address)), http_(std::make_unique<Http>()) {
  Http& http = *http_;
  http.set_payload_max_length(kMaxBody);
  http.set_keep_alive_max_count(1000);  // as announced in Keep-Alive: the server's own timeouts decide
  http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    tRouted = true;
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("Referrer-Policy", "no-referrer");
    const std::string host = req.get_header_value("Host"), origin = req.get_header_value("Origin"),
                      site = req.get_header_value("Sec-Fetch-Site");
    const bool navigation = req.method == "GET" && req.get_header_value("Sec-Fetch-Mode") == "navigate";
    if (const std::string why = whyNotSameOrigin({host, origin, site, navigation}, address_); !why.empty()) {
      replyError(res, 403, why);
      return httplib::Server::HandlerResponse::Handled;
    }
    const std::string given =
        req.has_param("token") ? req.get_param_value("token") : req.get_header_value("X-Robotsim-Token");
    if (!sameToken(given, token_)) {
      replyError(res, 403, "this address needs the token robotsim teach printed");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;
    replyError(res, res.status,
               res.status == 404   ? "no such route"
               : res.status == 413 ? fmt::format("the body is over {} ({} bytes)", base::sizeText(kMaxBody), kMaxBody)
                                   : fmt::format("HTTP {}", res.status));
  });
  http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    replyError(res, 500, "internal error");
  });
  http.Get("/", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(source_.page(), "text/html; charset=utf-8");
  });
  http.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(source_.state(), "application/json");
  });
  http.Get("/api/events", [](const httplib::Request& req, httplib::Response& res) {
    if (req.method == "GET" && tAnswer) tAnswer->openStream = true;
    res.status = 200;
  });
  // With a content reader the body is read as it is, whatever its
  // Content-Type: cpp-httplib would otherwise parse a form-encoded one
  // (curl -d's default) and refuse it over 8 KiB.
  http.Post("/api/command",
            [this](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader) {
              if (req.is_multipart_form_data()) return replyError(res, 400, "the body is JSON, not a form");
              std::string body;
              reader([&body](const char* data, std::size_t n) {
                if (body.size() + n > kMaxBody) return false;
                body.append(data, n);
                return true;
              });
              const nlohmann::json request = nlohmann::json::parse(body, nullptr, false);
              if (request.is_discarded()) return replyError(res, 400, "the body is not JSON");
              const LiveReply reply = source_.command(request);
              replyJson(res, reply.status, reply.body);
            });
}

LiveRoutes::~LiveRoutes() = default;

LiveAnswer LiveRoutes::answer(std::string_view request, const std::string& peer) const {
  // The body is here: "Expect: 100-continue" is answered by the server
  // when the head arrives (or not at all), never again in the answer.
  std::string whole(request);
  const std::size_t head = whole.find("\r\n\r\n");
  disarmExpect(whole, head == std::string::npos ? whole.size() : head + 4);
  LiveAnswer a;
  MemoryStream stream(whole, a.response, peer);
  tAnswer = &a;
  tRouted = false;
  bool closed = false;
  http_->process_request(stream, false, closed, [](httplib::Request&) {});
  tAnswer = nullptr;
  a.close = closed;
  if (a.openStream) {
    // Allowed (every check passed): the server writes the stream's head and events.
    a.response.clear();
    a.close = false;
  } else if (a.response.empty() || !tRouted) {
    // A request cpp-httplib could not read (a request line or header line
    // it cannot parse, a path over its limit): what it would answer does
    // not follow the request's method (a HEAD got a body, which a client
    // reads as the next answer), so the answer is ours and ends the connection.
    const int status = a.response.size() > 12 ? std::atoi(a.response.c_str() + 9) : 0;
    a.response = status == 414 ? plainResponse(414, "the request's path is too long", true)
                               : plainResponse(400, "not an HTTP request (a line of its head cannot be read)", true);
    a.close = true;
  }
  return a;
}

}  // namespace rs::live
