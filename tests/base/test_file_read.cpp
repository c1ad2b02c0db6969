// base::readFile opens without blocking (a FIFO must not hang it: issue
// 32), yet still waits, as a blocking open would, for a write lease
// another program holds to be given up: teach holds one on the program
// file while it settles a write (file_swap.h), and a `robotsim check` or
// the language server reading the file then must get the settled bytes,
// not "Resource temporarily unavailable".
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <thread>

#include "base/file_io.h"
#include "tests/cli/cli_support.h"

TEST_CASE("readFile waits for a write lease to be given up, then reads", "[base][read]") {
  const rs::testing::TempDir dir;
  const std::string path = dir.write("p.rsp", "the settled bytes");
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  REQUIRE(fd >= 0);
  ::fcntl(fd, F_SETSIG, SIGURG);  // the break is signalled to no one (no owner), and SIGURG is ignored anyway
  if (::fcntl(fd, F_SETLEASE, F_WRLCK) != 0) {
    ::close(fd);
    WARN("this file system grants no leases: nothing to wait for here");
    return;
  }
  std::thread holder([fd] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::fcntl(fd, F_SETLEASE, F_UNLCK);
  });
  const auto started = std::chrono::steady_clock::now();
  const rs::base::FileRead read = rs::base::readFile(path, 1024);
  const auto waited = std::chrono::steady_clock::now() - started;
  holder.join();
  ::close(fd);
  INFO(read.error);
  REQUIRE(read.bytes);
  CHECK(*read.bytes == "the settled bytes");
  CHECK(waited >= std::chrono::milliseconds(250));  // it waited for the lease, as a blocking open does
}
