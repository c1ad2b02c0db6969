// A client that talks to the live-view server byte by byte over a real
// socket, for what cpp-httplib's client would not send: half-open
// connections, requests cut short, hostile Host and Origin headers,
// streams nobody reads.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <string>
#include <string_view>

namespace rawhttp {

class Socket {
 public:
  /// Connected to 127.0.0.1:port; `receiveBuffer` > 0 shrinks the socket's buffer.
  explicit Socket(int port, int receiveBuffer = 0) {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    REQUIRE(fd_ >= 0);
    if (receiveBuffer > 0) ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receiveBuffer, sizeof receiveBuffer);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    REQUIRE(::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0);
  }
  ~Socket() {
    if (fd_ >= 0) ::close(fd_);
  }
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;
  Socket(Socket&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }

  int fd() const { return fd_; }
  void send(std::string_view bytes) const {
    REQUIRE(::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size()));
  }
  /// What arrives within `seconds`, until the server closes or `enough` says so.
  template <typename Enough>
  std::string receive(double seconds, Enough&& enough) const {
    std::string got;
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!enough(got)) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (left.count() <= 0) break;
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
      char buffer[65536];
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n <= 0) {
        closedByServer_ = true;
        break;
      }
      got.append(buffer, static_cast<std::size_t>(n));
    }
    return got;
  }
  /// Everything until the server closes (or `seconds` pass).
  std::string receiveAll(double seconds) const {
    return receive(seconds, [](const std::string&) { return false; });
  }
  /// One response whose head and Content-Length body have arrived.
  std::string receiveResponse(double seconds) const {
    return receive(seconds, [](const std::string& all) {
      std::string_view got = all;
      while (got.starts_with("HTTP/1.1 100")) {  // interim answers first
        const std::size_t end = got.find("\r\n\r\n");
        if (end == std::string_view::npos) return false;
        got.remove_prefix(end + 4);
      }
      const std::size_t head = got.find("\r\n\r\n");
      if (head == std::string_view::npos) return false;
      const std::size_t at = got.find("Content-Length: ");
      if (at == std::string_view::npos || at > head) return true;
      return got.size() >= head + 4 + std::stoul(std::string(got.substr(at + 16, 8)));
    });
  }
  bool closedByServer() const { return closedByServer_; }

 private:
  int fd_ = -1;
  mutable bool closedByServer_ = false;
};

/// The status of a response ("HTTP/1.1 403 ..." → 403), 0 when there is none.
inline int statusOf(std::string_view response) {
  if (!response.starts_with("HTTP/1.1 ") || response.size() < 12) return 0;
  return std::stoi(std::string(response.substr(9, 3)));
}

/// The body of a response (after its head).
inline std::string bodyOf(const std::string& response) {
  const std::size_t head = response.find("\r\n\r\n");
  return head == std::string::npos ? std::string() : response.substr(head + 4);
}

}  // namespace rawhttp
