#include "model/urdf/urdf_read_remote.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <system_error>

#include "base/self_path.h"
#include "model/urdf/urdf_read_wire.h"

extern char** environ;

namespace rs::urdf {

namespace fs = std::filesystem;

namespace {

#if !defined(ROBOTSIM_LIBEXEC_FROM_BINDIR) || !defined(ROBOTSIM_BINDIR_NAME)
#error "ROBOTSIM_LIBEXEC_FROM_BINDIR, ROBOTSIM_BINDIR_NAME: the build defines them (CMakeLists.txt)"
#endif

// The helper's answer is the robot with its lines: a large mesh's edges
// make it large, never this large.
constexpr std::size_t kMaxAnswerBytes = std::size_t{1} << 30;

UrdfRead failed(const fs::path& path, std::string message, std::string hint) {
  UrdfRead out;
  out.diagnostics.push_back({path.string(), {}, diag::Severity::Error, std::move(message), "urdf-helper", std::move(hint)});
  return out;
}

}  // namespace

std::vector<fs::path> urdfHelperCandidates() {
  const fs::path exe = base::runningExecutable();
  if (exe.empty()) return {};
  const fs::path dir = exe.parent_path();
  const std::string file = "robotsim-urdf";
  // Only where a layout puts it, as for every helper (tools/cli/lib/
  // helpers.h): a lone copy of robotsim in D/x/ never looks in D/.
  std::vector<fs::path> out;
  if (exe.filename().string().starts_with("robotsim-")) out.push_back(dir / file);  // a helper, among its siblings
  if (dir.filename() == ROBOTSIM_BINDIR_NAME) out.push_back((dir / ROBOTSIM_LIBEXEC_FROM_BINDIR / file).lexically_normal());
  out.push_back(dir / "libexec" / "robotsim" / file);
  if (dir.filename() == "tests" || dir.filename() == "bench")  // the build tree's test and bench programs
    out.push_back((dir / ".." / "libexec" / "robotsim" / file).lexically_normal());
  return out;
}

UrdfRead readUrdfInHelper(const fs::path& path, const UrdfOptions& options, const std::string* text) {
  // An editor's text over the limit is refused here: the helper would stop
  // reading it at the limit, and the rest would be written to no one.
  if (text && text->size() > kMaxUrdfBytes) return UrdfRead{std::nullopt, {urdfTooLarge(path.string(), text->size())}};
  fs::path helper;
  for (const fs::path& candidate : urdfHelperCandidates()) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) {
      helper = candidate;
      break;
    }
  }
  if (helper.empty())
    return failed(path, "cannot read URDF files: robotsim's helper robotsim-urdf, which reads them, is missing",
                  "reinstall robotsim; in a build tree, `cmake --build BUILD --target robotsim` builds it");
  std::vector<std::string> args{helper.string(), "read", path.string(), "--precision", fmt::format("{}", options.precision)};
  if (!options.tip.empty()) args.insert(args.end(), {"--tip", options.tip});
  if (text) args.push_back("--stdin");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int fds[2], in[2] = {-1, -1};
  if (::pipe2(fds, O_CLOEXEC) != 0 || (text && ::pipe2(in, O_CLOEXEC) != 0))
    return failed(path, fmt::format("cannot run robotsim-urdf: {}", std::strerror(errno)), "");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  if (text) posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  else posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (text) {
    // The helper reads all of its input before it writes: write it all, then read.
    ::close(in[0]);
    if (spawned == 0)
      for (std::size_t done = 0; done < text->size();) {
        const ssize_t put = ::write(in[1], text->data() + done, text->size() - done);
        if (put < 0 && errno == EINTR) continue;
        if (put <= 0) break;
        done += static_cast<std::size_t>(put);
      }
    ::close(in[1]);
  }
  if (spawned != 0) {
    ::close(fds[0]);
    return failed(path, fmt::format("cannot run {}: {}", helper.string(), std::strerror(spawned)), "reinstall robotsim");
  }
  std::string answer;
  char buffer[1 << 16];
  bool tooLarge = false;
  for (;;) {
    const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    if (answer.size() + static_cast<std::size_t>(got) > kMaxAnswerBytes) {
      tooLarge = true;
      break;
    }
    answer.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (tooLarge) return failed(path, "the robot read from this URDF file is too large (more than 1 GiB of lines)", "");
  if (!WIFEXITED(status) || answer.empty())
    return failed(path, fmt::format("robotsim-urdf stopped without an answer reading this file{}",
                                    WIFSIGNALED(status) ? fmt::format(" (signal {})", WTERMSIG(status)) : ""),
                  "this is a bug in robotsim: please report it with the file");
  return decodeUrdfRead(answer, path.string());
}

}  // namespace rs::urdf
