// base::writeFileAtomically, the writer behind compile -o, test --junit,
// render -o and teach: regular files replaced atomically and keeping their
// mode (and owner), links written through to their target, devices, FIFOs
// and terminals written in place and never renamed over, nothing followed
// at a temporary's name, nothing left behind.
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <thread>

#include "base/file_write.h"
#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using rs::base::writeFileAtomically;
using rs::testing::readBytes;

unsigned modeOf(const std::string& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return st.st_mode & 07777;
}

// The names in a folder, so that a test can see nothing was left there.
std::vector<std::string> namesIn(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool writeText(const std::string& path, std::string_view text, std::string& error) {
  return writeFileAtomically(path, text, error);
}

}  // namespace

TEST_CASE("writing a new file: all of it, the umask's mode, nothing else left", "[base][write]") {
  const rs::testing::TempDir dir;
  const mode_t mask = ::umask(022);
  ::umask(mask);
  std::string error;
  const std::string path = dir.file("out.rsb");
  REQUIRE(writeText(path, "image bytes", error));
  CHECK(readBytes(path) == "image bytes");
  CHECK(modeOf(path) == (0666u & ~static_cast<unsigned>(mask)));
  CHECK(namesIn(dir.path()) == std::vector<std::string>{"out.rsb"});
}

TEST_CASE("replacing a file keeps its mode: a 0600 file stays 0600, a 0640 one 0640", "[base][write]") {
  const rs::testing::TempDir dir;
  std::string error;
  for (const unsigned mode : {0600u, 0640u, 0755u}) {
    const std::string path = dir.write("p.rsp", "old text\n");
    REQUIRE(::chmod(path.c_str(), mode) == 0);
    REQUIRE(writeText(path, "new text\n", error));
    CHECK(readBytes(path) == "new text\n");
    CHECK(modeOf(path) == mode);
  }
  // Set on request, for a file that exists and for a new one (teach's .bak).
  rs::base::WriteOptions options;
  options.mode = 0600;
  REQUIRE(writeFileAtomically(dir.file("p.rsp"), "x", error, options));
  CHECK(modeOf(dir.file("p.rsp")) == 0600);
  REQUIRE(writeFileAtomically(dir.file("new.bak"), "x", error, options));
  CHECK(modeOf(dir.file("new.bak")) == 0600);
}

TEST_CASE("replacing a file keeps its owner where the system lets us", "[base][write]") {
  if (::geteuid() != 0) {
    WARN("not root: a file of another owner cannot be made here; skipped");
    return;
  }
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "old\n");
  REQUIRE(::chown(path.c_str(), 4321, 4322) == 0);
  REQUIRE(::chmod(path.c_str(), 0640) == 0);
  std::string error;
  REQUIRE(writeText(path, "new\n", error));
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  CHECK(st.st_uid == 4321);
  CHECK(st.st_gid == 4322);
  CHECK((st.st_mode & 07777) == 0640);
}

TEST_CASE("a link planted at the old temporary name is never followed", "[base][write]") {
  // The writer used PATH.tmp: a link there sent the bytes into its target.
  const rs::testing::TempDir dir;
  const std::string victim = dir.write("victim", "precious\n");
  const std::string path = dir.write("p.rsb", "old\n");
  fs::create_symlink(victim, dir.file("p.rsb.tmp"));
  std::string error;
  REQUIRE(writeText(path, "new\n", error));
  CHECK(readBytes(victim) == "precious\n");
  CHECK(readBytes(path) == "new\n");
  CHECK(fs::is_symlink(dir.file("p.rsb.tmp")));
  CHECK(namesIn(dir.path()) == std::vector<std::string>{"p.rsb", "p.rsb.tmp", "victim"});
}

TEST_CASE("the temporary is created exclusively: a name taken is never opened", "[base][write]") {
  const rs::testing::TempDir dir;
  std::string tmp, error;
  const int fd = rs::base::createTemporaryBeside(dir.file("out"), 0600, tmp, error);
  REQUIRE(fd >= 0);
  ::close(fd);
  CHECK(fs::path(tmp).parent_path() == dir.path());
  CHECK(fs::path(tmp).filename().string().starts_with(".out."));
  // Every later one gets another name; none follows a link or reuses a file.
  std::string second;
  const int fd2 = rs::base::createTemporaryBeside(dir.file("out"), 0600, second, error);
  REQUIRE(fd2 >= 0);
  ::close(fd2);
  CHECK(second != tmp);
}

TEST_CASE("a link is written through: the target replaced, its mode kept, the link a link", "[base][write]") {
  const rs::testing::TempDir dir;
  fs::create_directories(dir.path() / "real");
  const std::string target = dir.write("real/p.rsb", "old\n");
  REQUIRE(::chmod(target.c_str(), 0640) == 0);
  fs::create_symlink("real/p.rsb", dir.file("link1"));       // relative, read from the link's folder
  fs::create_symlink(dir.file("link1"), dir.file("link2"));  // a chain
  std::string error;
  REQUIRE(writeText(dir.file("link2"), "new\n", error));
  CHECK(fs::is_symlink(dir.file("link1")));
  CHECK(fs::is_symlink(dir.file("link2")));
  CHECK(readBytes(target) == "new\n");
  CHECK(modeOf(target) == 0640);
  CHECK(namesIn(dir.path() / "real") == std::vector<std::string>{"p.rsb"});  // replaced in the target's folder
  // A dangling link: its target is created.
  fs::create_symlink("real/new.rsb", dir.file("dangling"));
  REQUIRE(writeText(dir.file("dangling"), "made\n", error));
  CHECK(readBytes(dir.file("real/new.rsb")) == "made\n");
  CHECK(fs::is_symlink(dir.file("dangling")));
  // A loop of links is an error, and nothing is written.
  fs::create_symlink(dir.file("loop2"), dir.file("loop1"));
  fs::create_symlink(dir.file("loop1"), dir.file("loop2"));
  CHECK_FALSE(writeText(dir.file("loop1"), "x", error));
  CHECK(error == "too many levels of symbolic links");
}

TEST_CASE("a name robotsim makes up replaces a link there instead of following it", "[base][write]") {
  const rs::testing::TempDir dir;
  const std::string victim = dir.write("victim", "precious\n");
  fs::create_symlink(victim, dir.file("p.rsp.bak"));
  rs::base::WriteOptions options;
  options.followLinks = false;
  std::string error;
  REQUIRE(writeFileAtomically(dir.file("p.rsp.bak"), "backup\n", error, options));
  CHECK(readBytes(victim) == "precious\n");
  CHECK_FALSE(fs::is_symlink(dir.file("p.rsp.bak")));
  CHECK(readBytes(dir.file("p.rsp.bak")) == "backup\n");
}

TEST_CASE("a FIFO is written in place for its reader, and stays a FIFO", "[base][write]") {
  const rs::testing::TempDir dir;
  const std::string fifo = dir.file("pipe");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string received;
  std::thread reader([&] {
    const int fd = ::open(fifo.c_str(), O_RDONLY);
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) received.append(buffer, static_cast<std::size_t>(n));
    ::close(fd);
  });
  // The writer opens without waiting for a reader: wait for the reader to be there.
  std::string error;
  bool written = false;
  for (int i = 0; i < 500 && !written; ++i) {
    written = writeText(fifo, std::string(200'000, 'x'), error);
    if (!written) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(written);
  reader.join();
  CHECK(received == std::string(200'000, 'x'));
  CHECK(fs::is_fifo(fifo));
  CHECK(namesIn(dir.path()) == std::vector<std::string>{"pipe"});
}

TEST_CASE("a FIFO nobody reads is an error at once, not a hang", "[base][write]") {
  const rs::testing::TempDir dir;
  const std::string fifo = dir.file("pipe");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string error;
  CHECK_FALSE(writeText(fifo, "bytes", error));
  CHECK_THAT(error, Catch::Contains("nothing is reading it"));
  CHECK(fs::is_fifo(fifo));
  CHECK(namesIn(dir.path()) == std::vector<std::string>{"pipe"});
}

TEST_CASE("a terminal is written in place (a real pseudo-terminal)", "[base][write]") {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  REQUIRE(master >= 0);
  REQUIRE(::grantpt(master) == 0);
  REQUIRE(::unlockpt(master) == 0);
  const std::string device = ::ptsname(master);
  // Raw, so that the bytes arrive as written.
  const int keep = ::open(device.c_str(), O_RDWR | O_NOCTTY);
  REQUIRE(keep >= 0);
  termios t{};
  ::tcgetattr(keep, &t);
  ::cfmakeraw(&t);
  ::tcsetattr(keep, TCSANOW, &t);
  std::string error;
  REQUIRE(writeText(device, "to the terminal", error));
  std::string got;
  char buffer[256];
  for (int i = 0; i < 100 && got.size() < 15; ++i) {
    const ssize_t n = ::read(master, buffer, sizeof buffer);
    if (n > 0) got.append(buffer, static_cast<std::size_t>(n));
  }
  CHECK(got == "to the terminal");
  struct stat st {};
  REQUIRE(::stat(device.c_str(), &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  ::close(keep);
  ::close(master);
}

TEST_CASE("a device is written in place, never renamed over (a /dev/null made in a temp folder)", "[base][write]") {
  // The machine's own /dev/null is never touched: as root, a node for the
  // same device (1, 3) is made in a temporary folder.
  if (::geteuid() != 0) {
    WARN("not root: a device node cannot be made here; skipped");
    return;
  }
  const rs::testing::TempDir dir;
  const std::string null = dir.file("null");
  if (::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) {
    WARN("mknod refused here (a container without CAP_MKNOD?); skipped");
    return;
  }
  std::string error;
  REQUIRE(writeText(null, "discarded", error));
  struct stat st {};
  REQUIRE(::lstat(null.c_str(), &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  CHECK(st.st_rdev == ::makedev(1, 3));
  CHECK(namesIn(dir.path()) == std::vector<std::string>{"null"});
}

TEST_CASE("a directory, a failed writer and a folder that does not exist leave everything as it was", "[base][write]") {
  const rs::testing::TempDir dir;
  std::string error;
  fs::create_directories(dir.path() / "sub");
  CHECK_FALSE(writeText(dir.file("sub"), "x", error));
  CHECK(error == "is a directory");
  const std::string path = dir.write("p.rsb", "old\n");
  CHECK_FALSE(writeFileAtomically(
      path,
      [](std::ostream& out) {
        out << "half";
        return false;
      },
      error));
  CHECK(readBytes(path) == "old\n");
  CHECK(namesIn(dir.path()) == std::vector<std::string>{"p.rsb", "sub"});
  CHECK_FALSE(writeText(dir.file("missing/p.rsb"), "x", error));
  CHECK_THAT(error, Catch::Contains("cannot create a temporary file in"));
  CHECK_THAT(error, Catch::Contains("No such file or directory"));
}
