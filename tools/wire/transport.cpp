#include "tools/wire/transport.h"

#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>

namespace rs::wire {

std::size_t FdInput::read(char* into, std::size_t n) {
  for (;;) {
    const ssize_t got = ::read(fd_, into, n);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR) return 0;  // an unreadable input ends like EOF
  }
}

bool FdInput::ready() {
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & (POLLIN | POLLHUP)) != 0;
}

FdOutput::FdOutput(int fd) : fd_(fd) { ::signal(SIGPIPE, SIG_IGN); }

bool FdOutput::write(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t put = ::write(fd_, bytes.data(), bytes.size());
    if (put < 0) {
      if (errno == EINTR) continue;
      return false;  // EPIPE: the client is gone
    }
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return true;
}

std::size_t StreamInput::read(char* into, std::size_t n) {
  // A stream has everything already: take what is there.
  const std::streamsize got = in_.rdbuf()->sgetn(into, static_cast<std::streamsize>(n));
  return got > 0 ? static_cast<std::size_t>(got) : 0;
}

// A stream has everything already: read() never waits (at the end it
// returns 0 at once, which is how a server sees that its client left).
bool StreamInput::ready() { return true; }

bool StreamOutput::write(std::string_view bytes) {
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out_.flush();
  return static_cast<bool>(out_);
}

}  // namespace rs::wire
