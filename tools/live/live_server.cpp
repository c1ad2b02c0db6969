#include "tools/live/live_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <condition_variable>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <vector>

#include "tools/live/http_frame.h"

namespace rs::live {

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr std::size_t kReadPiece = 16 * 1024;
constexpr auto kLinger = 2s;          // reading what a client still sends after our last answer, so it gets it
constexpr auto kAcceptPause = 100ms;  // out of file descriptors: accept again after this

std::string peerAddress(const sockaddr_storage& addr) {
  char text[INET6_ADDRSTRLEN] = {};
  if (addr.ss_family == AF_INET)
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(addr).sin_addr, text, sizeof text);
  else if (addr.ss_family == AF_INET6)
    inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(addr).sin6_addr, text, sizeof text);
  return text;
}

// A listening socket on host:port (port 0: a free one), non-blocking; -1 with `error`.
int listenOn(const std::string& host, int port, int& boundPort, std::string& error) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string service = std::to_string(port);
  if (const int rc = getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0) {
    error = fmt::format("cannot listen on {}: {}", host, gai_strerror(rc));
    return -1;
  }
  int fd = -1;
  for (addrinfo* a = found; a && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    const int yes = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, 128) != 0) {
      ::close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(found);
  if (fd < 0) {
    error = port == 0 ? fmt::format("cannot listen on {}", host) : fmt::format("cannot listen on {}:{}", host, port);
    return -1;
  }
  sockaddr_storage bound{};
  socklen_t length = sizeof bound;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &length);
  boundPort = ntohs(bound.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6&>(bound).sin6_port
                                                : reinterpret_cast<sockaddr_in&>(bound).sin_port);
  return fd;
}

}  // namespace

// The connections and the work on them: nested here, not in the anonymous
// namespace, since Loop (a member of LiveServer) holds them (a unity build
// warns of a class with linkage holding types without).
struct LiveServer::Loop {
  enum class Phase {
    kReading,  // waiting for a whole request (or writing the answer to the last one)
    kWorking,  // a worker has its request
    kStream,   // an event stream
    kClosing,  // our side is done; reading what still comes for a moment
  };

  struct Connection {
    int fd = -1;
    std::string peer;
    Phase phase = Phase::kReading;
    std::string in;
    std::string out;
    std::size_t sent = 0;
    bool closeAfter = false;
    bool peerDone = false;  // the client sent its end: answered, then closed
    bool continueSent = false;
    Clock::time_point waitingSince;  // the request timeout's start: connected, or the last answer sent
    Clock::time_point lastWrite;     // the last progress writing `out`
    std::uint64_t revision = 0;      // a stream: the revision it was last sent
    Clock::time_point lastEvent;

    bool pending() const { return sent < out.size(); }
  };

  struct Job {
    std::uint64_t id;
    std::string request;
    std::string peer;
  };

  struct Done {
    std::uint64_t id;
    LiveAnswer answer;
  };

  Loop(LiveServer& server, int listener, int port)
      : owner(server),
        limits(server.limits_),
        listener(listener),
        routes(server.source_, server.token_, ServerAddress{server.host_, port}) {}

  LiveServer& owner;
  const LiveLimits limits;
  const int listener;
  const LiveRoutes routes;
  int wake = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  std::atomic<bool> stopping{false};
  std::thread io;
  std::vector<std::thread> workers;

  std::mutex jobsMutex;
  std::condition_variable jobsReady;
  std::deque<Job> jobs;
  std::mutex doneMutex;
  std::deque<Done> done;

  // Owned by the I/O thread.
  std::map<std::uint64_t, Connection> connections;
  std::map<std::string, std::size_t> perClient;
  std::uint64_t nextId = 1;
  std::size_t streams = 0;
  Clock::time_point acceptAgain{};
  Clock::time_point lastEventRound{};

  void signal() {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(wake, &one, sizeof one);
  }

  // ---- the workers: whole requests in, answers out, never a socket.
  void work() {
    for (;;) {
      Job job;
      {
        std::unique_lock lock(jobsMutex);
        jobsReady.wait(lock, [this] { return stopping.load() || !jobs.empty(); });
        if (stopping.load()) return;
        job = std::move(jobs.front());
        jobs.pop_front();
      }
      LiveAnswer answer;
      try {
        answer = routes.answer(job.request, job.peer);
      } catch (...) {  // out of memory, say: an answer all the same
        answer.response = plainResponse(500, "internal error", true);
        answer.close = true;
      }
      {
        std::lock_guard lock(doneMutex);
        done.push_back({job.id, std::move(answer)});
      }
      signal();
    }
  }

  // ---- connections
  void drop(std::uint64_t id) {
    const auto it = connections.find(id);
    if (it == connections.end()) return;
    ::close(it->second.fd);
    if (it->second.phase == Phase::kStream) --streams;
    if (--perClient[it->second.peer] == 0) perClient.erase(it->second.peer);
    connections.erase(it);
    owner.connections_.store(connections.size());
    owner.streams_.store(streams);
  }

  // The connection that has waited longest without a whole request, among
  // those of `peer` (or all, when empty), that no worker or stream holds.
  std::optional<std::uint64_t> oldestIdle(const std::string& peer) const {
    std::optional<std::uint64_t> oldest;
    Clock::time_point since = Clock::time_point::max();
    for (const auto& [id, c] : connections) {
      const bool idle = (c.phase == Phase::kReading && !c.pending()) || c.phase == Phase::kClosing;
      if (idle && (peer.empty() || c.peer == peer) && c.waitingSince < since) since = c.waitingSince, oldest = id;
    }
    return oldest;
  }

  bool admit(const std::string& peer) {
    const auto it = perClient.find(peer);
    if (it != perClient.end() && it->second >= limits.maxConnectionsPerClient) {
      const auto victim = oldestIdle(peer);
      if (!victim) return false;
      drop(*victim);
    }
    if (connections.size() >= limits.maxConnections) {
      const auto victim = oldestIdle({});
      if (!victim) return false;
      drop(*victim);
    }
    return true;
  }

  void acceptAll(Clock::time_point now) {
    for (int n = 0; n < 64; ++n) {
      sockaddr_storage addr{};
      socklen_t length = sizeof addr;
      const int fd = ::accept4(listener, reinterpret_cast<sockaddr*>(&addr), &length, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) {
        if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) acceptAgain = now + kAcceptPause;
        return;
      }
      std::string peer = peerAddress(addr);
      if (!admit(peer)) {
        ::close(fd);
        continue;
      }
      const int yes = 1;  // small answers go out at once (no 40 ms delayed-ACK stalls)
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
      Connection c;
      c.fd = fd;
      c.peer = peer;
      c.waitingSince = c.lastWrite = now;
      ++perClient[peer];
      connections.emplace(nextId++, std::move(c));
      owner.connections_.store(connections.size());
    }
  }

  void queue(Connection& c, std::string_view bytes, Clock::time_point now) {
    if (!c.pending()) c.out.clear(), c.sent = 0, c.lastWrite = now;
    c.out += bytes;
  }

  // Writes what the client takes now; false when the connection is to go.
  bool flush(std::uint64_t id, Connection& c, Clock::time_point now) {
    while (c.pending()) {
      const ssize_t n = ::send(c.fd, c.out.data() + c.sent, c.out.size() - c.sent, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n > 0) {
        c.sent += static_cast<std::size_t>(n);
        c.lastWrite = now;
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return true;
      return false;
    }
    c.out.clear();
    c.sent = 0;
    if (c.closeAfter && c.phase != Phase::kClosing) {
      if (c.phase == Phase::kStream) owner.streams_.store(--streams);  // a stream whose client already left
      ::shutdown(c.fd, SHUT_WR);  // the client reads the answer, then its end
      c.phase = Phase::kClosing;
      c.waitingSince = now;
      return true;
    }
    if (c.phase == Phase::kReading) return dispatch(id, c, now);
    return true;
  }

  // Hands the next whole request to a worker, answers one that cannot be
  // framed; false when the connection is to go.
  bool dispatch(std::uint64_t id, Connection& c, Clock::time_point now) {
    if (c.phase != Phase::kReading || c.pending() || c.closeAfter) return true;
    const RequestFrame frame = frameRequest(c.in, kMaxHead, kMaxBody);
    switch (frame.state) {
      case RequestFrame::State::kIncomplete:
        if (frame.expectsContinue && frame.headLength > 0 && !c.continueSent) {
          c.continueSent = true;
          queue(c, "HTTP/1.1 100 Continue\r\n\r\n", now);
          return flush(id, c, now);
        }
        return true;
      case RequestFrame::State::kRefused:
        c.in.clear();
        c.closeAfter = true;
        queue(c, plainResponse(frame.status, frame.message, true), now);
        return flush(id, c, now);
      case RequestFrame::State::kComplete: break;
    }
    Job job{id, c.in.substr(0, frame.length), c.peer};
    c.in.erase(0, frame.length);
    c.continueSent = false;
    c.phase = Phase::kWorking;
    {
      std::lock_guard lock(jobsMutex);
      jobs.push_back(std::move(job));
    }
    jobsReady.notify_one();
    return true;
  }

  void answered(Done& d, Clock::time_point now) {
    const auto it = connections.find(d.id);
    if (it == connections.end()) return;
    Connection& c = it->second;
    c.phase = Phase::kReading;
    c.waitingSince = now;
    if (d.answer.openStream && streams >= limits.maxEventStreams) {
      c.closeAfter = true;
      queue(c,
            plainResponse(
                503, fmt::format("{} event streams are open, the most this server keeps: close a page", streams), true),
            now);
    } else if (d.answer.openStream) {
      c.phase = Phase::kStream;
      c.in.clear();
      ++streams;
      owner.streams_.store(streams);
      c.revision = owner.source_.revision();  // before the state: a change between them is sent next round
      c.lastEvent = now;
      queue(c, eventStreamHead() + stateEvent(owner.source_.state()), now);
    } else {
      c.closeAfter = c.closeAfter || d.answer.close;
      queue(c, d.answer.response, now);
    }
    if (!flush(d.id, c, now)) drop(d.id);
  }

  static constexpr std::size_t kMaxBuffered = kMaxHead + kMaxBody + 8;  // more is refused by the framing first

  static bool wantsInput(const Connection& c) {
    if (c.peerDone || c.phase == Phase::kWorking) return false;
    return c.phase != Phase::kReading || c.in.size() < kMaxBuffered;
  }

  // What the client sent; false when the connection is to go.
  bool readable(std::uint64_t id, Connection& c, Clock::time_point now) {
    char buffer[kReadPiece];
    const bool keep = c.phase == Phase::kReading;  // else read and let go (a stream's client, a closing one)
    const std::size_t room = kMaxBuffered - std::min(c.in.size(), kMaxBuffered);
    const ssize_t n = ::recv(c.fd, buffer, keep ? std::min(room, sizeof buffer) : sizeof buffer, MSG_DONTWAIT);
    if (n == 0) {
      // The client's end. A request of it being answered still gets its
      // answer (a tool that shuts its side after sending); else it is over.
      c.peerDone = true;
      c.closeAfter = true;
      return c.phase == Phase::kWorking || (c.phase == Phase::kReading && c.pending());
    }
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    if (keep) {
      c.in.append(buffer, static_cast<std::size_t>(n));
      return dispatch(id, c, now);
    }
    return true;
  }

  // Timeouts: a request not whole in time, an answer not taken, a linger over.
  bool inTime(Connection& c, Clock::time_point now) {
    if (c.pending() && now - c.lastWrite > limits.writeTimeout) return false;
    if (c.phase == Phase::kClosing) return now - c.waitingSince < kLinger;
    if (c.phase != Phase::kReading || c.pending() || now - c.waitingSince <= limits.requestTimeout) return true;
    if (c.in.empty()) return false;  // an idle connection just ends
    c.in.clear();
    c.closeAfter = true;
    queue(
        c,
        plainResponse(408, fmt::format("the request was not whole within {} ms", limits.requestTimeout.count()), true),
        now);
    return true;
  }

  void eventRound(Clock::time_point now) {
    if (streams == 0 || now - lastEventRound < limits.eventPoll) return;
    lastEventRound = now;
    const std::uint64_t revision = owner.source_.revision();
    std::optional<std::string> event;  // made once a round, if any stream needs it
    for (auto& [id, c] : connections) {
      if (c.phase != Phase::kStream || c.pending()) continue;  // one that reads slowly gets the newest later
      if (c.revision != revision) {
        if (!event) event = stateEvent(owner.source_.state());
        c.revision = revision;
        c.lastEvent = now;
        queue(c, *event, now);
      } else if (now - c.lastEvent > limits.eventKeepAlive) {
        c.lastEvent = now;
        queue(c, keepAliveEvent(), now);
      }
    }
  }

  int pollTimeout(Clock::time_point now) const {
    auto wait = std::chrono::milliseconds(500);
    if (streams > 0) wait = std::min(wait, limits.eventPoll);
    if (acceptAgain > now)
      wait = std::min(wait, std::chrono::duration_cast<std::chrono::milliseconds>(acceptAgain - now));
    wait = std::min(wait, std::max(1ms, std::min(limits.requestTimeout, limits.writeTimeout) / 4));
    return static_cast<int>(std::max(wait, 1ms).count());
  }

  void run() {
    std::vector<pollfd> polled;
    std::vector<std::uint64_t> ids;
    while (!stopping.load()) {
      Clock::time_point now = Clock::now();
      polled.clear();
      ids.clear();
      const bool accepting = now >= acceptAgain;
      polled.push_back({wake, POLLIN, 0});
      polled.push_back({accepting ? listener : -1, POLLIN, 0});
      for (const auto& [id, c] : connections) {
        short events = 0;
        if (wantsInput(c)) events |= POLLIN;
        if (c.pending()) events |= POLLOUT;
        polled.push_back({c.fd, events, 0});
        ids.push_back(id);
      }
      ::poll(polled.data(), polled.size(), pollTimeout(now));
      now = Clock::now();
      if (polled[0].revents) {
        std::uint64_t count = 0;
        [[maybe_unused]] const ssize_t n = ::read(wake, &count, sizeof count);
      }
      std::deque<Done> answers;
      {
        std::lock_guard lock(doneMutex);
        answers.swap(done);
      }
      for (Done& d : answers) answered(d, now);
      for (std::size_t i = 0; i < ids.size(); ++i) {
        const auto it = connections.find(ids[i]);
        if (it == connections.end()) continue;
        Connection& c = it->second;
        const short revents = polled[i + 2].revents;
        bool keep = !(revents & (POLLHUP | POLLERR | POLLNVAL));  // reset, or gone both ways: nobody to answer
        if (keep && (revents & POLLOUT)) keep = flush(ids[i], c, now);
        if (keep && (revents & POLLIN)) keep = readable(ids[i], c, now);
        if (keep) keep = inTime(c, now) && flush(ids[i], c, now);
        if (!keep) drop(ids[i]);
      }
      if (polled[1].revents & POLLIN) acceptAll(now);
      eventRound(now);
    }
    while (!connections.empty()) drop(connections.begin()->first);
  }
};

LiveServer::LiveServer(LiveSource& source, std::string token, LiveLimits limits)
    : source_(source), token_(std::move(token)), limits_(limits) {}

LiveServer::~LiveServer() { stop(); }

bool LiveServer::start(const std::string& host, int port, std::string& error) {
  host_ = host;
  const int listener = listenOn(host, port, port_, error);
  if (listener < 0) {
    port_ = -1;
    return false;
  }
  loop_ = std::make_unique<Loop>(*this, listener, port_);
  loop_->io = std::thread([this] { loop_->run(); });
  for (std::size_t i = 0; i < std::max<std::size_t>(1, limits_.workers); ++i)
    loop_->workers.emplace_back([this] { loop_->work(); });
  return true;
}

std::string LiveServer::url() const {
  const bool v6 = host_.find(':') != std::string::npos;
  return fmt::format("http://{}{}{}:{}/?token={}", v6 ? "[" : "", host_, v6 ? "]" : "", port_, token_);
}

void LiveServer::stop() {
  if (!loop_) return;
  {
    std::lock_guard lock(loop_->jobsMutex);
    loop_->stopping.store(true);
  }
  loop_->jobsReady.notify_all();
  loop_->signal();
  if (loop_->io.joinable()) loop_->io.join();
  for (std::thread& w : loop_->workers) w.join();
  ::close(loop_->listener);
  ::close(loop_->wake);
  loop_.reset();
}

}  // namespace rs::live
