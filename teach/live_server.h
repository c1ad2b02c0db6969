// The live-view server (cpp-httplib): one LiveSource behind a secret token,
// on 127.0.0.1 and a free port unless told otherwise. Routes (every one
// needs ?token=TOKEN, or the header X-Robotsim-Token, compared in constant
// time; else 403):
//
//   GET  /              the page
//   GET  /api/state     the state (JSON)
//   GET  /api/events    server-sent events: the state at once, then at each new revision
//   POST /api/command   a command (JSON body, at most kMaxBody bytes; else 413)
//
// Anything else is 404; a body that is not JSON 400; the server never
// names or serves a file. stop() ends every event stream and the listener.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <thread>

#include "teach/live_source.h"

namespace rs::teach {

inline constexpr std::size_t kMaxBody = 16 * 1024;

/// 32 hex digits from the system's random source.
std::string randomToken();
/// Equal, in time that depends on the lengths only.
bool sameToken(std::string_view a, std::string_view b);

class LiveServer {
 public:
  /// `source` must outlive the server.
  LiveServer(LiveSource& source, std::string token);
  ~LiveServer();
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  /// Binds `host` (port 0: a free one) and serves on a thread of its own;
  /// false, with `error` set, when it cannot bind.
  bool start(const std::string& host, int port, std::string& error);
  int port() const { return port_; }
  const std::string& token() const { return token_; }
  /// The page's address, token included.
  std::string url() const;
  /// Ends the event streams and the listener; waits for its thread.
  void stop();

 private:
  struct Impl;
  LiveSource& source_;
  std::string token_;
  std::string host_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> listenerEnded_{false};
  std::unique_ptr<Impl> impl_;
  std::thread thread_;
};

}  // namespace rs::teach
