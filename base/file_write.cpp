#include "base/file_write.h"

#include "base/removed_on_signal.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <streambuf>

namespace rs::base {

namespace {

// An ostream's buffer over a file descriptor: what the callers' writers
// write into, whatever the destination (a temporary file, a device, a
// FIFO, standard output).
class DescriptorBuffer final : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  int savedErrno() const { return errno_; }

 protected:
  int_type overflow(int_type c) override {
    if (!flush()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return flush() ? 0 : -1; }

 private:
  bool flush() {
    const char* p = pbase();
    while (p < pptr()) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        errno_ = n < 0 ? errno : EIO;
        return false;
      }
      p += n;
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return true;
  }

  int fd_;
  int errno_ = 0;
  char buffer_[1 << 16];
};

// Runs `write` into `fd`; "" when every byte went out, else why not.
std::string writeInto(int fd, const std::function<bool(std::ostream&)>& write) {
  DescriptorBuffer buffer(fd);
  std::ostream out(&buffer);
  const bool written = write(out);
  out.flush();
  if (written && out) return {};
  return buffer.savedErrno() ? std::strerror(buffer.savedErrno()) : "write error";
}

std::string folderOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string leafOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A device, a FIFO or a socket: written where it is, as `cat > PATH` would.
bool writeInPlace(const std::string& path, const std::function<bool(std::ostream&)>& write, std::string& error) {
  // O_NONBLOCK so that opening a FIFO nobody reads fails (ENXIO) instead
  // of waiting for a reader for ever; the writes then block as usual.
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    error = errno == ENXIO ? "nothing is reading it (a FIFO without a reader, or a socket)" : std::strerror(errno);
    return false;
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  error = writeInto(fd, write);
  ::close(fd);
  return error.empty();
}

bool writeStandardOutput(const std::function<bool(std::ostream&)>& write, std::string& error) {
  std::cout.flush();  // what the command printed before goes first
  error = writeInto(STDOUT_FILENO, write);
  return error.empty();
}

}  // namespace

std::string finalTarget(const std::string& path, std::string& error) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
    const ssize_t n = ::readlink(p.c_str(), link.data(), link.size());
    if (n < 0 || static_cast<std::size_t>(n) >= link.size()) return p;  // changed under us: let open say
    link.resize(static_cast<std::size_t>(n));
    p = link.starts_with('/') || p.find('/') == std::string::npos ? link : folderOf(p) + "/" + link;
  }
  error = "too many levels of symbolic links";
  return {};
}

int createTemporaryBeside(const std::string& target, unsigned mode, std::string& tmpPath, std::string& error) {
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  const std::string folder = folderOf(target);
  // A long name keeps its first 200 bytes: the temporary stays under NAME_MAX.
  const std::string leaf = leafOf(target).substr(0, 200);
  for (int attempt = 0; attempt < 100; ++attempt) {
    unsigned char random[6] = {};
    if (::getrandom(random, sizeof random, 0) != static_cast<ssize_t>(sizeof random))
      for (unsigned char& r : random) r = static_cast<unsigned char>(std::rand());
    std::string suffix;
    for (unsigned char r : random) suffix += kLetters[r % (sizeof kLetters - 1)];
    tmpPath = fmt::format("{}/.{}.{}.tmp", folder, leaf, suffix);
    const int fd = ::open(tmpPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
    if (fd >= 0) return fd;
    if (errno != EEXIST) {
      error = fmt::format("cannot create a temporary file in {}: {}", folder, std::strerror(errno));
      return -1;
    }
  }
  error = fmt::format("cannot create a temporary file in {}: every name tried was taken", folder);
  return -1;
}

std::string takeOwnerAndMode(int fd, const struct stat& like, std::optional<unsigned> mode) {
  unsigned bits = mode ? *mode : static_cast<unsigned>(like.st_mode & 07777);
  if ((like.st_uid != ::geteuid() || like.st_gid != ::getegid()) && ::fchown(fd, like.st_uid, like.st_gid) != 0)
    bits &= ~static_cast<unsigned>(S_ISUID | S_ISGID);  // not another owner's set-id bits on our file
  if (::fchmod(fd, static_cast<mode_t>(bits)) != 0) return fmt::format("cannot set the mode: {}", std::strerror(errno));
  return {};
}

void syncFolderOf(const std::string& path) {
  const int fd = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

bool writeFileAtomically(const std::string& path, const std::function<bool(std::ostream&)>& write, std::string& error,
                         const WriteOptions& options) {
  if (path == "-") return writeStandardOutput(write, error);
  const std::string target = options.followLinks ? finalTarget(path, error) : path;
  if (target.empty()) return false;
  struct stat st {};
  const bool exists = ::lstat(target.c_str(), &st) == 0 && !S_ISLNK(st.st_mode);  // a link here: not followed
  if (exists && S_ISDIR(st.st_mode)) {
    error = "is a directory";
    return false;
  }
  if (exists && !S_ISREG(st.st_mode)) return writeInPlace(target, write, error);

  // A file that exists keeps its mode: the temporary is made 0600 (never
  // more open than the file, even for a moment) and given the mode after.
  std::string tmp;
  const int fd = createTemporaryBeside(target, exists || options.mode ? 0600 : 0666, tmp, error);
  if (fd < 0) return false;
  RemovedOnSignal cleanup(tmp);  // a Ctrl-C or a kill mid-write leaves no temporary
  if (!exists) st.st_uid = ::geteuid(), st.st_gid = ::getegid();  // a new file: ours
  if (exists || options.mode) error = takeOwnerAndMode(fd, st, options.mode);
  bool ok = error.empty();
  if (ok) {
    error = writeInto(fd, write);
    ok = error.empty();
  }
  if (ok && ::fsync(fd) != 0) {
    error = std::strerror(errno);
    ok = false;
  }
  if (::close(fd) != 0 && ok) {
    error = std::strerror(errno);
    ok = false;
  }
  if (ok && ::rename(tmp.c_str(), target.c_str()) != 0) {
    error = std::strerror(errno);
    ok = false;
  }
  if (!ok) {
    ::unlink(tmp.c_str());
    return false;
  }
  syncFolderOf(target);
  return true;
}

bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string& error,
                         const WriteOptions& options) {
  return writeFileAtomically(
      path,
      [bytes](std::ostream& out) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return static_cast<bool>(out);
      },
      error, options);
}

bool writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string& error,
                         const WriteOptions& options) {
  return writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), error,
                             options);
}

}  // namespace rs::base
