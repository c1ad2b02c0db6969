// What the live-view server serves: one page and the state of something
// that changes (a teach pendant, a stopped run in the debugger), and, when
// it allows them, commands. The server (live_server.h) knows nothing of
// robots: it checks the token, limits bodies, answers 4xx to bad requests
// and pushes the state to the page whenever its revision changes; a
// source knows nothing of HTTP. See tools/live/README.md.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace rs::live {

/// A source's answer to a command: an HTTP status (200 carried out or
/// refused as things stand, "ok" saying which: a point that does not
/// exist, a file changed on disk; 400 the request was malformed; 403 the
/// source is read-only) and a JSON body ({"ok", "message", "revision"}).
struct LiveReply {
  int status = 200;
  nlohmann::json body;
};

class LiveSource {
 public:
  virtual ~LiveSource() = default;
  /// The whole page (self-contained HTML). It reads its token from its own
  /// URL and talks to the API under the same origin.
  virtual std::string page() = 0;
  /// Grows whenever the state changes; the server pushes the state when it does.
  virtual std::uint64_t revision() = 0;
  /// The state now, as JSON text. Must not block for long: a source whose
  /// commands take time (a real robot moving) keeps the last state ready.
  virtual std::string state() = 0;
  /// A command from the page (any JSON value, already parsed). A read-only
  /// source answers 403 to every command.
  virtual LiveReply command(const nlohmann::json& request) = 0;
};

}  // namespace rs::live
