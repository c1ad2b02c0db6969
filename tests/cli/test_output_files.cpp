// What `robotsim compile -o` and `test --junit` do to the file they are
// named (docs/cli.md, "Output files"): `-` is standard output, a device or
// a FIFO is written in place (before, a temporary was renamed over it: as
// root, `-o /dev/null` replaced the machine's /dev/null with the image), a
// link's target is replaced and keeps its mode, a 0600 file stays 0600.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <thread>

#include "tests/cli/cli_support.h"
#include "tests/support/piped_process.h"

namespace {

namespace fs = std::filesystem;
using rs::testing::readBytes;
using rs::testing::runCli;

const std::string kTinyProgram = "; expect: finished\n        MOVE 100 0 0 0 0\n        END\n";

}  // namespace

TEST_CASE("compile -o - writes the image to standard output, the note to standard error", "[cli][output]") {
  const rs::testing::TempDir dir;
  const std::string prog = dir.write("p.rsp", kTinyProgram);
  rstest::PipedProcess p = rstest::spawnRobotsim({"compile", prog, "-o", "-"});
  ::close(p.in);
  std::string out;
  char buffer[4096];
  for (ssize_t n; (n = ::read(p.out, buffer, sizeof buffer)) > 0;) out.append(buffer, static_cast<std::size_t>(n));
  ::close(p.out);
  const int status = rstest::waitForExit(p.pid, 30);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(out.starts_with("\x89RSB\r\n\x1A\n"));
  // The same bytes as an image written to a file.
  REQUIRE(runCli({"compile", prog, "-o", dir.file("p.rsb")}).code == 0);
  CHECK(out == readBytes(dir.file("p.rsb")));
  CHECK_FALSE(fs::exists("-"));
}

TEST_CASE("compile -o and test --junit on a device write in place (a /dev/null made in a temp folder)",
          "[cli][output]") {
  if (::geteuid() != 0) {
    WARN("not root: a device node cannot be made here; skipped");
    return;
  }
  const rs::testing::TempDir dir;
  const std::string null = dir.file("null");
  if (::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) {
    WARN("mknod refused here; skipped");
    return;
  }
  const std::string prog = dir.write("p.rsp", kTinyProgram);
  const auto compiled = runCli({"compile", prog, "-o", null});
  INFO(compiled.err);
  CHECK(compiled.code == 0);
  const auto tested = runCli({"test", prog, "--junit", null});
  INFO(tested.err);
  CHECK(tested.code == 0);
  struct stat st {};
  REQUIRE(::lstat(null.c_str(), &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  CHECK(st.st_rdev == ::makedev(1, 3));
  for (const auto& e : fs::directory_iterator(dir.path()))
    CHECK((e.path().filename() == "null" || e.path().filename() == "p.rsp"));
}

TEST_CASE("test --junit into a FIFO feeds its reader", "[cli][output]") {
  const rs::testing::TempDir dir;
  const std::string fifo = dir.file("junit.fifo");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string prog = dir.write("p.rsp", kTinyProgram);
  std::string xml;
  std::thread reader([&] {
    const int fd = ::open(fifo.c_str(), O_RDONLY);
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) xml.append(buffer, static_cast<std::size_t>(n));
    ::close(fd);
  });
  // The reader must be there first: the writer never waits for one.
  int code = -1;
  std::string err;
  for (int i = 0; i < 500; ++i) {
    const auto r = runCli({"test", prog, "--junit", fifo});
    code = r.code, err = r.err;
    if (code == 0) break;
    CHECK_THAT(r.err, Catch::Contains("nothing is reading it"));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  INFO(err);
  REQUIRE(code == 0);
  reader.join();
  CHECK(xml.starts_with("<?xml"));
  CHECK(fs::is_fifo(fifo));
}

TEST_CASE("compile -o through a link keeps the link and its target's mode, a 0600 image stays 0600", "[cli][output]") {
  const rs::testing::TempDir dir;
  const std::string prog = dir.write("p.rsp", kTinyProgram);
  fs::create_directories(dir.path() / "images");
  const std::string target = dir.write("images/p.rsb", "old");
  REQUIRE(::chmod(target.c_str(), 0600) == 0);
  fs::create_symlink("images/p.rsb", dir.file("latest.rsb"));
  REQUIRE(runCli({"compile", prog, "-o", dir.file("latest.rsb")}).code == 0);
  CHECK(fs::is_symlink(dir.file("latest.rsb")));
  CHECK(readBytes(target).starts_with("\x89RSB"));
  struct stat st {};
  REQUIRE(::stat(target.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0600);
}
