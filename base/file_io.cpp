#include "base/file_io.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace rs::base {

namespace {

// Longer than the kernel's default lease-break-time, after which the open succeeds.
constexpr int kLeaseWaitMs = 50'000;

}  // namespace

std::string sizeText(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t{1} << 20) && bytes % (std::uint64_t{1} << 20) == 0)
    return fmt::format("{} MiB", bytes >> 20);
  if (bytes >= (std::uint64_t{1} << 20)) return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1 << 20));
  if (bytes >= 1024 && bytes % 1024 == 0) return fmt::format("{} KiB", bytes >> 10);
  return fmt::format("{} bytes", bytes);
}

std::string notRegularFileReason(mode_t mode) {
  if (S_ISREG(mode)) return {};
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO (a named pipe), not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

int openRegularFile(const std::string& path, std::string& error, std::uint64_t* size) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    error = std::strerror(errno);
    return -1;
  }
  if (!S_ISREG(st.st_mode)) {
    error = notRegularFileReason(st.st_mode);
    return -1;
  }
  // A write lease another program holds (teach, while it settles a write:
  // file_swap.h) fails a non-blocking open with EWOULDBLOCK, having asked
  // the holder to give it up; a blocking open would wait for that, so this
  // one waits too, by trying again (the kernel breaks a lease that is not
  // given up within its lease-break-time, 45 s by default).
  int fd = -1;
  for (int waited = 0;; waited += 5) {
    fd = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd >= 0 || errno != EWOULDBLOCK || waited >= kLeaseWaitMs) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (fd < 0) {
    error = std::strerror(errno);
    return -1;
  }
  // What was opened, which may not be what stat() saw a moment before.
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    error = S_ISREG(st.st_mode) ? std::strerror(errno) : notRegularFileReason(st.st_mode);
    ::close(fd);
    return -1;
  }
  if (size) *size = static_cast<std::uint64_t>(st.st_size);
  return fd;
}

FileRead readFile(const std::string& path, std::size_t limit) {
  FileRead result;
  std::uint64_t size = 0;
  const int fd = openRegularFile(path, result.error, &size);
  if (fd < 0) return result;
  // Judged by its size before a byte is read.
  if (size > limit) {
    ::close(fd);
    result.error = fmt::format("file is {}; the limit is {}", sizeText(size), sizeText(limit));
    return result;
  }
  std::string text;
  text.reserve(static_cast<std::size_t>(size));  // one allocation of the right size
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      result.error = fmt::format("read error: {}", std::strerror(errno));
      break;
    }
    if (n == 0) {
      result.bytes = std::move(text);
      break;
    }
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > limit) {  // a file that grew, or one of /proc's (its size says 0)
      result.error = fmt::format("file is larger than the limit of {}", sizeText(limit));
      break;
    }
  }
  ::close(fd);
  return result;
}

}  // namespace rs::base
