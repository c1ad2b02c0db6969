// Ctrl-C, SIGTERM or SIGHUP in the middle of a write (issue 32: a killed
// `compile -o` left its 78 MB `.NAME.XXXXXX.tmp` beside the output): the
// temporary is removed and the process still ends by the signal. A child
// process writes a 4 MiB output through base::writeFileAtomically, whose
// writer stops half-way (after 2 MiB, flushed to the temporary) and tells
// the test, which then sees the temporary there, sends the signal, and
// looks again. SIGKILL, which no handler sees, leaves the temporary: the
// same check fails there, so it can fail.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "base/file_write.h"
#include "base/removed_on_signal.h"
#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> signalFolderNames(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

struct Killed {
  std::vector<std::string> midWrite;  // the folder's names while the write waited
  int status = 0;
};

// A child that writes `path`, stopping half-way; the folder's names
// mid-write, then `sig` sent, and how the child ended.
Killed killMidWrite(const std::string& path, int sig) {
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::close(ready[0]);
    // As a command started from a shell: the default dispositions (a
    // background job of a script has SIGINT ignored).
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) ::signal(s, SIG_DFL);
    const std::string half(std::size_t{2} << 20, 'x');
    std::string error;
    rs::base::writeFileAtomically(
        path,
        [&](std::ostream& out) {
          out << half;
          out.flush();
          if (::write(ready[1], "w", 1) != 1) ::_exit(3);
          ::pause();  // until the signal
          out << half;
          return static_cast<bool>(out);
        },
        error);
    ::_exit(0);
  }
  ::close(ready[1]);
  Killed k;
  pollfd p{ready[0], POLLIN, 0};
  char byte = 0;
  const bool wrote = ::poll(&p, 1, 20000) == 1 && ::read(ready[0], &byte, 1) == 1;
  ::close(ready[0]);
  if (wrote) k.midWrite = signalFolderNames(fs::path(path).parent_path());
  ::kill(child, wrote ? sig : SIGKILL);
  // Bounded: a child that did not end is killed, and the test fails.
  for (int i = 0; i < 2000 && ::waitpid(child, &k.status, WNOHANG) == 0; ++i) ::usleep(10000);
  if (::waitpid(child, &k.status, WNOHANG) == 0) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &k.status, 0);
    FAIL("the child did not end within 20 s of the signal");
  }
  REQUIRE(wrote);
  return k;
}

bool isTemporaryOf(const std::string& name, const std::string& leaf) {
  return name.rfind("." + leaf + ".", 0) == 0 && name.size() > leaf.size() + 5 && name.ends_with(".tmp");
}

}  // namespace

TEST_CASE("SIGTERM, SIGINT and SIGHUP mid-write remove the temporary and end the process by the signal",
          "[base][write][signal]") {
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    CAPTURE(sig);
    const rs::testing::TempDir dir;
    dir.write("out.rsb", "the old image");
    const Killed k = killMidWrite(dir.file("out.rsb"), sig);
    // Mid-write: the old file and one temporary beside it.
    REQUIRE(k.midWrite.size() == 2);
    CHECK(k.midWrite[1] == "out.rsb");
    CHECK(isTemporaryOf(k.midWrite[0], "out.rsb"));
    // Ended by the signal itself (a shell sees 128 + N), the temporary gone,
    // the old file as it was.
    CHECK(WIFSIGNALED(k.status));
    CHECK(WTERMSIG(k.status) == sig);
    CHECK(signalFolderNames(dir.path()) == std::vector<std::string>{"out.rsb"});
    CHECK(rs::testing::readBytes(dir.file("out.rsb")) == "the old image");
  }
}

TEST_CASE("SIGKILL mid-write leaves the temporary (no handler sees it): the check above can fail",
          "[base][write][signal]") {
  const rs::testing::TempDir dir;
  const Killed k = killMidWrite(dir.file("new.svg"), SIGKILL);
  REQUIRE(k.midWrite.size() == 1);
  CHECK(isTemporaryOf(k.midWrite[0], "new.svg"));
  CHECK(WIFSIGNALED(k.status));
  const std::vector<std::string> after = signalFolderNames(dir.path());
  REQUIRE(after.size() == 1);
  CHECK(isTemporaryOf(after[0], "new.svg"));
}

TEST_CASE("a handler of SIGINT the program set stays in charge: the write goes on to its end", "[base][write][signal]") {
  // The serial layer, the debugger and the terminal pendant handle Ctrl-C
  // themselves; a write under way then is not cut short.
  static volatile sig_atomic_t seen = 0;
  struct sigaction mine {}, before {};
  mine.sa_handler = [](int) { seen = 1; };
  sigemptyset(&mine.sa_mask);
  REQUIRE(::sigaction(SIGINT, &mine, &before) == 0);
  const rs::testing::TempDir dir;
  std::string error;
  const bool written = rs::base::writeFileAtomically(
      dir.file("out.txt"),
      [](std::ostream& out) {
        out << "first half ";
        ::raise(SIGINT);
        out << "second half";
        return static_cast<bool>(out);
      },
      error);
  struct sigaction during {};
  ::sigaction(SIGINT, nullptr, &during);
  ::sigaction(SIGINT, &before, nullptr);
  CHECK(written);
  CHECK(seen == 1);
  CHECK(during.sa_handler == mine.sa_handler);  // never replaced
  CHECK(rs::testing::readBytes(dir.file("out.txt")) == "first half second half");
  CHECK(signalFolderNames(dir.path()) == std::vector<std::string>{"out.txt"});
}

TEST_CASE("the handler is there only while a temporary is", "[base][write][signal]") {
  struct sigaction before {}, fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  ::sigaction(SIGTERM, &fallback, &before);
  {
    const rs::base::RemovedOnSignal guard("/nonexistent/.x.tmp");
    struct sigaction during {};
    ::sigaction(SIGTERM, nullptr, &during);
    CHECK(during.sa_handler != SIG_DFL);
  }
  struct sigaction after {};
  ::sigaction(SIGTERM, &before, &after);
  CHECK(after.sa_handler == SIG_DFL);
}
