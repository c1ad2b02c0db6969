#include "tools/cli/lib/helper_handshake.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <vector>

#include "base/text.h"
#include "tools/cli/lib/build_info.h"

extern char** environ;

namespace rs::cli {

namespace {

constexpr std::string_view kHelperWord = "robotsim-helper ";
constexpr std::size_t kMaxAnswer = 512;  // a line; more is no helper's

// How the program ended, for the message.
std::string endingOf(int status) {
  if (WIFEXITED(status)) return fmt::format("exited with status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return fmt::format("was ended by signal {}", WTERMSIG(status));
  return "ended";
}

}  // namespace

std::string helperHandshakeLine() {
  const BuildInfo info = buildInfo();
  return fmt::format("{}{} {} {}\n", kHelperWord, info.version, info.commit, info.buildType);
}

std::string whyNotOurHelper(int fd, double seconds) {
  int answer[2];
  if (::pipe2(answer, O_CLOEXEC) != 0) return fmt::format("could not be asked: {}", std::strerror(errno));
  // The file as opened (it cannot be swapped for another between this
  // question and the exec): /proc/self/fd/N, kept open in the child (a
  // dup2 onto itself clears close-on-exec), so that a script there is read
  // by its interpreter and answers, or not, as a program would.
  std::string self = fmt::format("/proc/self/fd/{}", fd);
  std::string word(kHelperHandshakeWord);
  char* argv[] = {self.data(), word.data(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, answer[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fd, fd);
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, self.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(answer[1]);
  if (spawned != 0) {
    ::close(answer[0]);
    return fmt::format("cannot be run: {}", std::strerror(spawned));
  }
  std::string got;
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (got.size() <= kMaxAnswer) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    pollfd p{answer[0], POLLIN, 0};
    const int ready = left > 0 ? ::poll(&p, 1, static_cast<int>(left)) : 0;
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) {
      timedOut = ready == 0;
      break;
    }
    char buffer[256];
    const ssize_t n = ::read(answer[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(answer[0]);
  if (timedOut || got.size() > kMaxAnswer) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timedOut) return fmt::format("did not answer robotsim's handshake within {} s", seconds);
  const std::string expected = helperHandshakeLine();
  if (got == expected && WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  if (got.starts_with(kHelperWord) && got.size() <= kMaxAnswer)
    return fmt::format("is the helper of another build of robotsim (it says '{}'; this robotsim is '{}')",
                       base::safeText(got.substr(0, got.find('\n'))),
                       expected.substr(0, expected.size() - 1));
  if (got.empty()) return fmt::format("did not answer robotsim's handshake (it printed nothing and {})", endingOf(status));
  return fmt::format("did not answer robotsim's handshake (it printed '{}'{} and {})",
                     base::safeText(std::string_view(got).substr(0, 60)), got.size() > 60 ? "..." : "", endingOf(status));
}

}  // namespace rs::cli
