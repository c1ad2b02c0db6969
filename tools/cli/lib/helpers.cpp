#include "tools/cli/lib/helpers.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "base/file_io.h"
#include "base/self_path.h"
#include "base/text.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/helper_handshake.h"

extern char** environ;

namespace rs::cli {

namespace {

// The hint of every refusal: where robotsim's own helpers come from.
constexpr std::string_view kReinstallHint =
    "  hint: reinstall robotsim (its helpers are part of it); in a build tree, `cmake --build BUILD --target "
    "robotsim` builds them; a copied robotsim needs the libexec/robotsim folder at one of those places\n";

int refuse(std::ostream& err, std::string_view command, const std::filesystem::path& path, const std::string& why) {
  err << fmt::format("robotsim: error: '{}' runs in a helper program, and {} {}\n{}", command,
                     base::safeText(path.string()), why, kReinstallHint);
  return kExitBadInput;
}

// Replaces this process with the program open as `fd` (the file checked,
// not whatever is at its name now), argv[0] its path, argv[1..] ours.
void execOpened(int fd, const std::filesystem::path& path, int argc, const char* const* argv) {
  std::vector<std::string> args{path.string()};
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  std::vector<char*> pointers;
  for (std::string& a : args) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  ::fexecve(fd, pointers.data(), environ);
}

}  // namespace

const Command* commandLeftToHelper(std::span<const Command> table, int argc, const char* const* argv) {
  if (argc < 2) return nullptr;
  const std::string_view word = argv[1];
  for (const Command& row : table)
    if (row.name == word) return row.inHelper && row.run == nullptr ? &row : nullptr;
  return nullptr;
}

bool leavesRowsToHelpers(std::span<const Command> table) {
  for (const Command& row : table)
    if (row.inHelper && row.run == nullptr) return true;
  return false;
}

std::vector<std::filesystem::path> helperCandidates(const std::filesystem::path& executable, std::string_view command) {
  const std::filesystem::path dir = executable.parent_path();
  const std::string file = fmt::format("robotsim-{}", command);
  std::vector<std::filesystem::path> candidates;
  // The installed layout only for an executable installed as that layout
  // has it, in a folder named as BINDIR is: a lone copy in D/x/ never
  // looks in D/libexec/, which is no folder of its own.
  if (dir.filename() == ROBOTSIM_BINDIR_NAME)
    candidates.push_back((dir / ROBOTSIM_LIBEXEC_FROM_BINDIR / file).lexically_normal());
  candidates.push_back(dir / "libexec" / "robotsim" / file);
  return candidates;
}

int execHelper(std::string_view command, int argc, const char* const* argv, std::ostream& err) {
  const std::filesystem::path self = base::runningExecutable();
  struct stat selfFile {};
  if (self.empty() || ::stat("/proc/self/exe", &selfFile) != 0) {
    err << fmt::format(
        "robotsim: error: '{}' runs in a helper program, found beside robotsim, but /proc/self/exe does not say "
        "where robotsim is\n  hint: run robotsim on Linux with /proc mounted\n",
        command);
    return kExitBadInput;
  }
  const std::vector<std::filesystem::path> candidates = helperCandidates(self, command);
  for (const std::filesystem::path& path : candidates) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 && errno == ENOENT) continue;  // not there (or a link to nothing)
    // Opened once: the file checked below is the file run.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return refuse(err, command, path, fmt::format("cannot be opened: {}", std::strerror(errno)));
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      ::close(fd);
      return refuse(err, command, path, S_ISREG(st.st_mode) ? "cannot be read" : base::notRegularFileReason(st.st_mode));
    }
    // A link (or a copy by hard link) back to robotsim would run this again, and again.
    if (st.st_dev == selfFile.st_dev && st.st_ino == selfFile.st_ino) {
      ::close(fd);
      return refuse(err, command, path, "is robotsim itself (a link back to it?), not its helper");
    }
    if (const std::string why = whyNotOurHelper(fd); !why.empty()) {
      ::close(fd);
      return refuse(err, command, path, why);
    }
    execOpened(fd, path, argc, argv);
    const int error = errno;
    ::close(fd);
    return refuse(err, command, path, fmt::format("cannot be run: {}", std::strerror(error)));
  }
  err << fmt::format("robotsim: error: '{}' runs in a helper program that is missing: looked for\n", command);
  for (const std::filesystem::path& path : candidates) err << fmt::format("  {}\n", base::safeText(path.string()));
  err << kReinstallHint;
  return kExitBadInput;
}

}  // namespace rs::cli
