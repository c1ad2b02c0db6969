// The live-view server: one LiveSource behind a secret token, on
// 127.0.0.1 and a free port unless told otherwise. The routes and the
// checks of each request are live_routes.h's; this is the part that talks
// to sockets, built so that no client can hold the page up:
//
//   - one thread waits on every connection at once (poll) and reads what
//     each sends; a request goes to a worker only when it is whole
//     (http_frame.h), so a client that sends slowly, or nothing, holds no
//     worker; the workers answer into memory and the same thread writes
//     the answers out as each client takes them;
//   - event streams (GET /api/events) are written by that thread too, the
//     newest state only (a stream that reads slowly skips states, it never
//     piles them up); at most LiveLimits::maxEventStreams, beyond that 503;
//   - a request must be whole within requestTimeout of its connection's
//     last answer (or its start), else 408 and the connection ends; an
//     answer that the client does not take for writeTimeout ends it too;
//   - at most maxConnectionsPerClient connections from one address and
//     maxConnections in all: a new one beyond them takes the place of the
//     one that has waited longest without a whole request (or, when every
//     connection is busy, is refused).
//
// stop() ends every connection and the threads.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <thread>

#include "tools/live/live_routes.h"
#include "tools/live/live_source.h"

namespace rs::live {

struct LiveLimits {
  std::size_t maxConnections = 512;
  std::size_t maxConnectionsPerClient = 64;
  std::size_t maxEventStreams = 32;
  std::chrono::milliseconds requestTimeout{10'000};
  std::chrono::milliseconds writeTimeout{10'000};
  std::chrono::milliseconds eventPoll{30};           ///< how often the streams look at the revision
  std::chrono::milliseconds eventKeepAlive{15'000};  ///< a comment line on a quiet stream
  std::size_t workers = 4;
};

class LiveServer {
 public:
  /// `source` must outlive the server.
  LiveServer(LiveSource& source, std::string token, LiveLimits limits = {});
  ~LiveServer();
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  /// Binds `host` (port 0: a free one) and serves on threads of its own;
  /// false, with `error` set, when it cannot bind.
  bool start(const std::string& host, int port, std::string& error);
  int port() const { return port_; }
  const std::string& token() const { return token_; }
  /// The page's address, token included.
  std::string url() const;
  /// Ends every connection and the threads; waits for them.
  void stop();

  /// Connections open now, event streams among them (for tests and the bench).
  std::size_t connections() const { return connections_.load(); }
  std::size_t eventStreams() const { return streams_.load(); }

 private:
  struct Loop;
  LiveSource& source_;
  std::string token_;
  LiveLimits limits_;
  std::string host_;
  int port_ = 0;
  std::atomic<std::size_t> connections_{0};
  std::atomic<std::size_t> streams_{0};
  std::unique_ptr<Loop> loop_;
};

}  // namespace rs::live
