#include "base/file_swap.h"

#include "base/removed_on_signal.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <stdio.h>  // renameat2
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace rs::base {

namespace {

// An editor's save in place takes milliseconds: half a second is plenty.
constexpr int kLeaseTries = 50;
constexpr auto kLeaseWait = std::chrono::milliseconds(10);
constexpr int kMaxRestoreSteps = 100;

bool sameFile(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

// The same file with the same bytes as far as the system can tell (not
// its ctime: the exchange itself changes that).
bool untouched(const struct stat& a, const struct stat& b) {
  return sameFile(a, b) && a.st_size == b.st_size && a.st_mtim.tv_sec == b.st_mtim.tv_sec &&
         a.st_mtim.tv_nsec == b.st_mtim.tv_nsec;
}

class Descriptor {
 public:
  explicit Descriptor(int fd = -1) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// The file open for reading under a read lease when one can be had.
struct LeasedFile {
  int fd = -1;
  bool leased = false;
  bool busy = false;  // someone kept it open for writing the whole time
  std::string error;
};

LeasedFile openLeased(const std::string& path) {
  LeasedFile f;
  for (int attempt = 0;; ++attempt) {
    // O_NONBLOCK: a write lease someone else holds makes the open fail
    // instead of wait; on a regular file it changes nothing else.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0 && errno != EWOULDBLOCK) {
      f.error = std::strerror(errno);
      return f;
    }
    if (fd >= 0) {
      struct stat st {};
      if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        f.error = "not a regular file";
        ::close(fd);
        return f;
      }
      // A lease's break is signalled to its holder, SIGIO by default, which
      // would end the process: SIGURG instead (ignored unless handled),
      // and then no one (owner 0) once it is held; F_GETLEASE tells.
      ::fcntl(fd, F_SETSIG, SIGURG);
      if (::fcntl(fd, F_SETLEASE, F_RDLCK) == 0) {
        ::fcntl(fd, F_SETOWN, 0);
        f.fd = fd, f.leased = true;
        return f;
      }
      if (errno != EAGAIN && errno != EBUSY) {  // not the owner, or a file system without leases
        f.fd = fd;
        return f;
      }
      ::close(fd);
    }
    if (attempt + 1 == kLeaseTries) {
      f.busy = true;
      return f;
    }
    std::this_thread::sleep_for(kLeaseWait);
  }
}

// Up to `limit` bytes of `fd` from its start; nullopt on a read error.
std::optional<std::string> readUpTo(int fd, std::size_t limit) {
  std::string text;
  char buffer[1 << 16];
  while (text.size() < limit) {
    const ssize_t n =
        ::pread(fd, buffer, std::min(sizeof buffer, limit - text.size()), static_cast<off_t>(text.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return std::nullopt;
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

bool exchange(const std::string& a, const std::string& b) {
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
}

// After an exchange that must not stand: `tmp` holds what was at `target`
// (someone's file), `target` what we put there (`ours`). Exchanges again
// until what comes out of `target` is what we put there the step before,
// i.e. until no one renamed a file in between: `target` then holds the
// newest file anyone saved, and `tmp` ours or an older file its own
// writer replaced, which goes. "" when settled, else where a file was kept.
std::string restore(const std::string& tmp, const std::string& target, struct stat ours) {
  struct stat expected = ours;
  for (int step = 0; step < kMaxRestoreSteps; ++step) {
    struct stat goingIn {};
    if (::lstat(tmp.c_str(), &goingIn) != 0) return {};
    if (!exchange(tmp, target)) {
      // Deleted meanwhile (an editor that deletes, then creates): theirs goes
      // back only if they have not created it again.
      if (errno == ENOENT && ::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0)
        return {};
      ::unlink(tmp.c_str());
      return {};
    }
    struct stat cameOut {};
    if (::lstat(tmp.c_str(), &cameOut) == 0 && sameFile(cameOut, expected)) {
      ::unlink(tmp.c_str());
      return {};
    }
    expected = goingIn;
  }
  return tmp;  // never settled: what it holds is kept
}

SwapResult failed(std::string error) { return {SwapOutcome::kFailed, std::move(error)}; }

// A write lease on our temporary (open for writing by us alone): from the
// exchange until the write is settled, whoever opens our file at the name
// (an editor reading the file to build its next save on) waits; the break
// is signalled to no one, as in openLeased. false where leases are refused.
bool leaseForWriting(int fd) {
  ::fcntl(fd, F_SETSIG, SIGURG);
  if (::fcntl(fd, F_SETLEASE, F_WRLCK) != 0) return false;
  ::fcntl(fd, F_SETOWN, 0);
  return true;
}

// After an undone exchange, before the lease on our file ends: a program
// that opened our file while it was at the name gets, once the lease ends,
// the bytes of the file at the name now (the newest file anyone saved),
// not ours that never stood: an editor building its next save on what it
// read then keeps its own last save. Best effort: nothing else depends on it.
void takeBytesOfFileAt(int ours, const std::string& target) {
  const Descriptor now(::open(target.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK));
  struct stat st {};
  if (now.get() < 0 || ::fstat(now.get(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  const std::optional<std::string> bytes = readUpTo(now.get(), static_cast<std::size_t>(st.st_size));
  if (!bytes) return;
  for (std::size_t done = 0; done < bytes->size();) {
    const ssize_t n = ::pwrite(ours, bytes->data() + done, bytes->size() - done, static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
  (void)::ftruncate(ours, static_cast<off_t>(bytes->size()));
}

}  // namespace

FileRead readFileWhenQuiet(const std::string& path, std::size_t limit) {
  std::string error;
  const std::string target = finalTarget(path, error);
  if (target.empty()) return {std::nullopt, error};
  const LeasedFile f = openLeased(target);
  const Descriptor held(f.fd);  // the lease lasts while the read below opens and reads the file
  return readFile(target, limit);
}

SwapResult replaceFileIfUnchanged(const std::string& path, std::string_view expected, std::string_view bytes) {
  std::string error;
  const std::string target = finalTarget(path, error);
  if (target.empty()) return failed(error);
  const LeasedFile f = openLeased(target);
  if (f.busy) return {SwapOutcome::kBusy, {}};
  if (f.fd < 0) return failed(f.error);
  const Descriptor old(f.fd);
  struct stat checked {};
  ::fstat(old.get(), &checked);
  const std::optional<std::string> current = readUpTo(old.get(), expected.size() + 1);
  if (!current) return failed(fmt::format("cannot read it: {}", std::strerror(errno)));
  if (*current != expected) return {SwapOutcome::kChanged, {}};
  struct stat after {};
  if (::fstat(old.get(), &after) != 0 || !untouched(checked, after)) return {SwapOutcome::kBusy, {}};

  std::string tmp;
  const Descriptor ours(createTemporaryBeside(target, 0600, tmp, error));
  if (ours.get() < 0) return failed(error);
  // Until the exchange (after it the name `tmp` may hold the file someone
  // else saved, which a signal must not remove).
  RemovedOnSignal cleanup(tmp);
  error = takeOwnerAndMode(ours.get(), checked);
  for (std::size_t done = 0; error.empty() && done < bytes.size();) {
    const ssize_t n = ::write(ours.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      error = n < 0 ? std::strerror(errno) : "write error";
    else
      done += static_cast<std::size_t>(n);
  }
  if (error.empty() && ::fsync(ours.get()) != 0) error = std::strerror(errno);
  struct stat oursStat {};
  if (error.empty() && ::fstat(ours.get(), &oursStat) != 0) error = std::strerror(errno);
  if (!error.empty()) {
    ::unlink(tmp.c_str());
    return failed(error);
  }
  const bool oursLeased = leaseForWriting(ours.get());
  const auto endOursLease = [&] {
    if (oursLeased) ::fcntl(ours.get(), F_SETLEASE, F_UNLCK);
  };

  // A writer asking for the old file while it was leased, or a change of
  // it, makes the write give way (kBusy); another file at the name (an
  // atomic save) makes it a change (kChanged).
  const auto stillQuiet = [&] {
    struct stat now {};
    return ::fstat(old.get(), &now) == 0 && untouched(checked, now) &&
           (!f.leased || ::fcntl(old.get(), F_GETLEASE) == F_RDLCK);
  };
  // A last look right before the exchange: the exchange exposes our file
  // at the name until it is undone, and an editor reading then would build
  // on it, so it is not made when the name already holds another file.
  {
    struct stat now {};
    if (::stat(target.c_str(), &now) != 0 || !untouched(checked, now) || !stillQuiet()) {
      const bool same = sameFile(checked, now);
      ::unlink(tmp.c_str());
      return {same ? SwapOutcome::kBusy : SwapOutcome::kChanged, {}};
    }
  }
  cleanup.release();
  if (!exchange(tmp, target)) {
    if (errno != EINVAL && errno != ENOSYS && errno != EOPNOTSUPP) {
      const int saved = errno;
      ::unlink(tmp.c_str());
      return saved == ENOENT ? SwapResult{SwapOutcome::kChanged, {}} : failed(std::strerror(saved));
    }
    // No exchange on this file system: after the last look, a plain rename.
    if (::rename(tmp.c_str(), target.c_str()) != 0) {
      const int saved = errno;
      ::unlink(tmp.c_str());
      return failed(std::strerror(saved));
    }
    syncFolderOf(target);
    return {SwapOutcome::kWritten, {}};
  }
  struct stat cameOut {};
  const bool wasChecked = ::lstat(tmp.c_str(), &cameOut) == 0 && sameFile(cameOut, checked);
  if (wasChecked && stillQuiet()) {
    endOursLease();
    ::unlink(tmp.c_str());
    syncFolderOf(target);
    return {SwapOutcome::kWritten, {}};
  }
  const std::string kept = restore(tmp, target, oursStat);
  if (oursLeased) takeBytesOfFileAt(ours.get(), target);
  endOursLease();
  if (!kept.empty())
    return failed(fmt::format("another program kept replacing the file; a version of it is kept in {}", kept));
  return {wasChecked ? SwapOutcome::kBusy : SwapOutcome::kChanged, {}};
}

}  // namespace rs::base
