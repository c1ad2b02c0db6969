// The live-view server's answers (tools/live/live_server.h): one whole request
// in, the whole response out, with no socket in sight, so that a worker
// never waits for a client and the fuzz target drives exactly what the
// server runs. cpp-httplib parses the request, routes it and writes the
// response (its Server::process_request over a stream in memory); the
// server's own checks come first, in this order: the Host and Origin
// (request_origin.h), then the token. Routes:
//
//   GET  /              the page
//   GET  /api/state     the state (JSON)
//   GET  /api/events    server-sent events: answered by the server itself
//                       (it holds the open streams without a thread)
//   POST /api/command   a command (a JSON body, whatever its Content-Type)
//
// Anything else 404; a body that is not JSON 400; an exception in a
// handler 500, never a crash.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "tools/live/live_source.h"
#include "tools/live/request_origin.h"

namespace rs::live {

inline constexpr std::size_t kMaxBody = 16 * 1024;
inline constexpr std::size_t kMaxHead = 16 * 1024;

/// 32 hex digits from the system's random source.
std::string randomToken();
/// Equal, in time that depends on the lengths only.
bool sameToken(std::string_view a, std::string_view b);

struct LiveAnswer {
  std::string response;     ///< the bytes to send (for a stream: nothing yet)
  bool close = false;       ///< the connection ends after them
  bool openStream = false;  ///< GET /api/events, allowed: the server takes the connection over
};

class LiveRoutes {
 public:
  /// `source` must outlive the routes.
  LiveRoutes(LiveSource& source, std::string token, ServerAddress address);
  ~LiveRoutes();
  LiveRoutes(const LiveRoutes&) = delete;
  LiveRoutes& operator=(const LiveRoutes&) = delete;

  /// The answer to one whole request (as http_frame.h frames it) from `peer`.
  /// Thread-safe: the server's workers call it at once.
  LiveAnswer answer(std::string_view request, const std::string& peer) const;

  const std::string& token() const { return token_; }
  const ServerAddress& address() const { return address_; }

 private:
  struct Http;
  LiveSource& source_;
  const std::string token_;
  const ServerAddress address_;
  std::unique_ptr<Http> http_;
};

/// A complete response the server writes itself (a request it could not
/// frame, a timeout, a refused stream): JSON {"ok": false, "message"}.
std::string plainResponse(int status, std::string_view message, bool close);
/// The head of an event stream (its body runs until the connection closes).
std::string eventStreamHead();
/// One server-sent event carrying `state`.
std::string stateEvent(std::string_view state);
/// A comment line that keeps a quiet stream open (and finds closed ones).
std::string_view keepAliveEvent();

}  // namespace rs::live
