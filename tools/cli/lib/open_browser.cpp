#include "tools/cli/lib/open_browser.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace rs::cli {

namespace {

// Where the link goes: the user's own runtime folder (0700 by the system)
// when there is one, else the temporary folder.
std::string privateBase() {
  for (const char* name : {"XDG_RUNTIME_DIR", "TMPDIR"})
    if (const char* value = std::getenv(name); value && *value) return value;
  return "/tmp";
}

// The page that sends the browser on (a refresh, and a link for a browser
// that does not follow refreshes from files). The URL is ours: ASCII only,
// nothing to escape in an attribute.
std::string redirectPage(const std::string& url) {
  return fmt::format(
      "<!DOCTYPE html>\n<meta charset=\"utf-8\">\n<meta name=\"referrer\" content=\"no-referrer\">\n"
      "<meta http-equiv=\"refresh\" content=\"0;url={0}\">\n<title>robotsim</title>\n"
      "<p><a href=\"{0}\">Open the robotsim page</a></p>\n",
      url);
}

}  // namespace

PageLink::~PageLink() {
  if (!path_.empty()) ::unlink(path_.c_str());
  if (!folder_.empty()) ::rmdir(folder_.c_str());
}

bool openBrowser(const std::string& url, PageLink& link, std::string& error) {
  std::string folder = privateBase() + "/robotsim-page-XXXXXX";
  if (!::mkdtemp(folder.data())) {  // 0700
    error = fmt::format("cannot make a private folder in {}: {}", privateBase(), std::strerror(errno));
    return false;
  }
  link.folder_ = folder;
  const std::string path = folder + "/page.html";
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) {
    error = fmt::format("cannot write {}: {}", path, std::strerror(errno));
    return false;
  }
  link.path_ = path;
  const std::string page = redirectPage(url);
  const bool written = ::write(fd, page.data(), page.size()) == static_cast<ssize_t>(page.size());
  ::close(fd);
  if (!written) {
    error = fmt::format("cannot write {}", path);
    return false;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::string program = "xdg-open";
  std::string argument = path;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    error = fmt::format("cannot start xdg-open: {}", std::strerror(rc));
    return false;
  }
  return true;
}

}  // namespace rs::cli
