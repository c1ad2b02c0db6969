// Inputs that are not files (issue 32): every command that reads a
// program, a stimuli file, a scenario, a cell or a debugger script waited
// for ever on a FIFO (the open itself blocks until someone writes), and
// the debug adapter, stuck in its launch, answered nothing more, not even
// `disconnect`. Each is run here as a process with a FIFO nobody writes,
// under a deadline (a command that waits is killed, and the test fails
// instead of hanging): it must refuse the FIFO by name, as what it is,
// with exit code 2, and the adapter must answer the launch with an error
// and then the disconnect.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tests/support/piped_process.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"
#include "tests/support/build_facts.h"

extern char** environ;

namespace {

using rs::testing::CliResult;
using rs::testing::TempDir;

constexpr const char* kFifoReason = "is a FIFO (a named pipe), not a regular file";

// this build's robotsim with `args`, standard input /dev/null, both outputs in
// `dir`; killed after `seconds` (code -1 then).
CliResult runWithDeadline(const TempDir& dir, std::vector<std::string> args, double seconds = 20) {
  const std::string out = dir.file("fifo.out"), err = dir.file("fifo.err");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  args.insert(args.begin(), rs::testing::robotsimBinary());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  REQUIRE(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  const int status = rstest::waitForExit(pid, seconds);
  CliResult r;
  r.code = status == -1 ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : -2;
  r.out = rs::testing::readBytes(out);
  r.err = rs::testing::readBytes(err);
  return r;
}

std::string makeFifo(const TempDir& dir, const std::string& name) {
  const std::string path = dir.file(name);
  REQUIRE(::mkfifo(path.c_str(), 0600) == 0);
  return path;
}

}  // namespace

TEST_CASE("every command refuses a FIFO given as its program, stimuli, scenario, cell or script, by name",
          "[cli][fifo]") {
  const TempDir dir;
  const std::string fifo = makeFifo(dir, "input.rsp");
  const std::string scenario = makeFifo(dir, "world.rstest");
  const std::string program = std::string(ROBOTSIM_SOURCE_DIR) + "/examples/first_moves.rsp";
  // A program whose own lines name the FIFO: its cell, its stimuli file.
  const std::string namesCell = dir.write("cell.rsp", "; cell: input.rsp\n        END\n");
  const std::string namesStimuli = dir.write("stim.rsp", "; test: stimuli input.rsp\n; expect: finished\n        END\n");
  struct Case {
    std::vector<std::string> args;
    std::string named;  // the path the refusal names
  };
  const std::vector<Case> cases{
      {{"run", fifo}, fifo},
      {{"check", fifo}, fifo},
      {{"disasm", fifo}, fifo},
      {{"tokens", fifo}, fifo},
      {{"ast", fifo}, fifo},
      {{"test", fifo}, fifo},
      {{"debug", fifo}, fifo},
      {{"compile", fifo, "-o", dir.file("out.rsb")}, fifo},
      {{"render", fifo, "-o", dir.file("out.svg")}, fifo},
      {{"animate", fifo, "-o", dir.file("out.html")}, fifo},
      {{"teach", fifo}, fifo},
      {{"run", program, "--stimuli", fifo}, fifo},
      {{"run", program, "--cell", fifo}, fifo},
      {{"check", namesCell}, dir.file("input.rsp")},
      {{"test", namesStimuli}, dir.file("input.rsp")},
      {{"test", scenario}, scenario},
      {{"debug", program, "--commands", fifo}, fifo},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const CliResult r = runWithDeadline(dir, c.args);
    INFO("out: " << r.out << "\nerr: " << r.err);
    CHECK(r.code == 2);
    const std::string said = r.out + r.err;
    CHECK(said.find(c.named) != std::string::npos);
    CHECK(said.find(kFifoReason) != std::string::npos);
  }
  CHECK(!std::filesystem::exists(dir.file("out.rsb")));
}

TEST_CASE("a character device as a program is refused without being read", "[cli][fifo]") {
  // Before, /dev/zero was read up to the 256 MiB limit; /dev/tty would wait for a key.
  const TempDir dir;
  const CliResult r = runWithDeadline(dir, {"check", "/dev/zero"});
  CHECK(r.code == 2);
  CHECK(r.err == "/dev/zero: error: cannot read file: is a character device, not a regular file\n");
}

TEST_CASE("robotsim dap: a launch of a FIFO is answered with an error, and the disconnect after it too",
          "[cli][fifo][dap]") {
  const TempDir dir;
  const std::string fifo = makeFifo(dir, "prog.rsp");
  const rstest::PipedProcess dap = rstest::spawnRobotsim({"dap"});
  ::signal(SIGPIPE, SIG_IGN);
  std::string bytes;
  for (const std::string& body :
       {std::string(R"({"seq":1,"type":"request","command":"initialize","arguments":{}})"),
        R"({"seq":2,"type":"request","command":"launch","arguments":{"program":")" + fifo + R"("}})",
        std::string(R"({"seq":3,"type":"request","command":"disconnect","arguments":{}})")})
    bytes += rs::wire::frameMessage(body);
  REQUIRE(::write(dap.in, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size()));
  // Everything it says until it closes its output, within 20 s.
  std::string said;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
    pollfd p{dap.out, POLLIN, 0};
    if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
    char buffer[4096];
    const ssize_t n = ::read(dap.out, buffer, sizeof buffer);
    if (n <= 0) break;
    said.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(dap.in);
  ::close(dap.out);
  const int status = rstest::waitForExit(dap.pid, 10);
  std::map<int, rs::wire::Json> responses;
  for (const rs::wire::Frame& f : rs::wire::parseFrames(said)) {
    REQUIRE(f.kind == rs::wire::Frame::Kind::Message);
    const rs::wire::Json m = rs::wire::Json::parse(f.body);
    if (m.value("type", "") == "response") responses[m.at("request_seq").get<int>()] = m;
  }
  INFO(said);
  REQUIRE(responses.count(2) == 1);
  CHECK(responses[2].at("success") == false);
  CHECK(responses[2].at("message").get<std::string>().find(kFifoReason) != std::string::npos);
  REQUIRE(responses.count(3) == 1);
  CHECK(responses[3].at("success") == true);
  REQUIRE(status != -1);  // it ended by itself
  CHECK(WIFEXITED(status));
}
