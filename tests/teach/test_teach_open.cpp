// robotsim teach --open, as a process: xdg-open (here a script on PATH
// that records what it was given, as the real one would hand it to the
// browser) never sees the token on its command line, where every local
// user can read it; it gets a file only this user can read, in a folder
// only this user can enter, that leads to the page. The file goes when
// teach ends.
#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "tests/cli/cli_support.h"
#include "tests/support/piped_process.h"
#include "tests/teach/raw_http.h"

namespace {

namespace fs = std::filesystem;

// Sets an environment variable for this scope (the child inherits it).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

}  // namespace

TEST_CASE("teach --open hands the browser a private file, never the token on a command line", "[teach][open]") {
  const rs::testing::TempDir dir;
  fs::create_directories(dir.path() / "bin");
  fs::create_directories(dir.path() / "runtime");
  const std::string log = dir.file("xdg-open.log");
  const std::string script = dir.write("bin/xdg-open",
                                       "#!/bin/sh\n"
                                       "{ echo \"ARGS $*\"; stat -c '%a' \"$1\"; stat -c '%a' \"$(dirname \"$1\")\"; "
                                       "cat \"$1\"; } > '" +
                                           log + ".part' && mv '" + log + ".part' '" + log + "'\n");
  REQUIRE(::chmod(script.c_str(), 0755) == 0);
  const std::string prog = dir.write("p.rsp", "        END\nPOINTS\n");
  const ScopedEnv path("PATH", dir.file("bin") + ":" + (std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin"));
  const ScopedEnv runtime("XDG_RUNTIME_DIR", dir.file("runtime"));
  rstest::PipedProcess p = rstest::spawnRobotsim({"teach", prog, "--cell", "scara-pick", "--open"});

  // The URL it prints, with the token.
  std::string out;
  std::smatch url;
  const std::regex urlPattern(R"(http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{32}))");
  char buffer[1024];
  while (!std::regex_search(out, url, urlPattern)) {
    const ssize_t n = ::read(p.out, buffer, sizeof buffer);
    REQUIRE(n > 0);
    out.append(buffer, static_cast<std::size_t>(n));
  }
  const std::string token = url[2];
  const int port = std::stoi(url[1]);
  for (int i = 0; i < 1000 && !fs::exists(log); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  REQUIRE(fs::exists(log));
  std::ifstream in(log);
  std::string args, fileMode, folderMode;
  std::getline(in, args);
  std::getline(in, fileMode);
  std::getline(in, folderMode);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

  CHECK(args.find(token) == std::string::npos);  // what ps shows of xdg-open
  const std::string file = args.substr(5);
  CHECK(file.starts_with(dir.file("runtime") + "/robotsim-page-"));
  CHECK(fileMode == "600");
  CHECK(folderMode == "700");
  CHECK(page.find(url[0].str()) != std::string::npos);  // it leads to the page, token and all
  // Not cpp-httplib's client: its <resolv.h> defines _res, which breaks
  // Eigen's headers after it in a unity batch of test files.
  const rawhttp::Socket c(port);
  c.send(fmt::format("GET /?token={} HTTP/1.1\r\nHost: 127.0.0.1:{}\r\n\r\n", token, port));
  CHECK(rawhttp::statusOf(c.receiveResponse(10)) == 200);

  ::kill(p.pid, SIGINT);
  const int status = rstest::waitForExit(p.pid, 20);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK_FALSE(fs::exists(file));
  CHECK_FALSE(fs::exists(fs::path(file).parent_path()));
  ::close(p.in);
  ::close(p.out);
}
