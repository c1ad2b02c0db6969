// libFuzzer target: `robotsim test --spec`'s walk of a submissions folder
// (tools/testrun/submissions.h) over any tree the bytes describe. Each input
// builds, in a fresh folder, directories, files, FIFOs and symbolic links
// (to files and folders inside, to a folder beside it, absolute, to a device, to
// nowhere, to themselves, through `..`), then walks it, named one of
// several ways. What the walk gives must hold:
// - every file it grades is a regular file inside the folder once every
//   link is followed, and no file comes twice;
// - every `.rsp` link under the folder that leads out of it (or nowhere)
//   is refused by name, and a refused path is never graded;
// - no file is opened (a FIFO would block), nothing crashes.
// The tree is built with *at() calls that never follow a link (a file
// written through a link would land outside the fresh folder).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "launch/confined_path.h"
#include "tools/testrun/submissions.h"

namespace fs = std::filesystem;

namespace {

void require(bool ok) {
  if (!ok) __builtin_trap();
}

// Places in the tree (relative to the folder graded).
const char* const kNames[] = {"a.rsp", "b.rsp", "d", "d/c.rsp", "d/e", "d/e/f.rsp", "g.txt", "d/h.rsp",
                              "link.rsp", "d/link.rsp", "dl", "d/dl", "x y.rsp", "d/e/deep.rsp", "\x1b]0;t\x07.rsp",
                              ".hidden.rsp"};
// Where a link may point (relative to the link's folder, or absolute;
// "@" stands for the folder graded, "%" for the folder beside it).
const char* const kTargets[] = {"a.rsp", "../outside/secret.rsp", "%/passwd", "../outside", "d", ".", "..", "../..",
                                "nowhere.rsp", "link.rsp", "d/../../outside/secret.rsp", "@/a.rsp", "%/secret.rsp",
                                "@", "%", "e/f.rsp", "../a.rsp", "dl/c.rsp", "/dev/zero", "/"};

template <std::size_t N>
const char* pick(const char* const (&list)[N], std::uint8_t byte) {
  return list[byte % N];
}

std::string expand(std::string target, const fs::path& root, const fs::path& outside) {
  if (!target.empty() && target[0] == '@') target = root.string() + target.substr(1);
  else if (!target.empty() && target[0] == '%') target = outside.string() + target.substr(1);
  return target;
}

// The folder `parts` (all but the last) under `rootFd`, made where
// missing, opened one level at a time without following a link: -1 when one
// of them is not a real folder. Nothing is ever made, or written, through
// a link: the links this target makes point out of the folder.
int openParent(int rootFd, const std::vector<std::string>& parts) {
  int fd = ::dup(rootFd);
  for (std::size_t i = 0; fd >= 0 && i + 1 < parts.size(); ++i) {
    ::mkdirat(fd, parts[i].c_str(), 0700);
    const int next = ::openat(fd, parts[i].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    ::close(fd);
    fd = next;
  }
  return fd;
}

// The input's tree: three bytes an entry (what, where, to what). Every
// call makes its last part only where nothing is (O_EXCL, mkdirat,
// symlinkat and mkfifoat never follow it).
void build(const std::uint8_t* data, std::size_t size, const fs::path& root, const fs::path& outside) {
  const int rootFd = ::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  require(rootFd >= 0);
  for (std::size_t i = 0; i + 2 < size && i < 3 * 24; i += 3) {
    std::vector<std::string> parts;
    for (const fs::path& part : fs::path(pick(kNames, data[i + 1]))) parts.push_back(part.string());
    const int parent = openParent(rootFd, parts);
    if (parent < 0) continue;
    const char* last = parts.back().c_str();
    switch (data[i] % 4) {
      case 0: ::mkdirat(parent, last, 0700); break;
      case 1: {
        const int fd = ::openat(parent, last, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0600);
        if (fd < 0) break;
        require(::write(fd, "END\n", 4) == 4);
        ::close(fd);
        break;
      }
      case 2: ::symlinkat(expand(pick(kTargets, data[i + 2]), root, outside).c_str(), parent, last); break;
      case 3: ::mkfifoat(parent, last, 0600); break;
    }
    ::close(parent);
  }
  ::close(rootFd);
}

// Every .rsp symbolic link under the folder, walked without following links.
std::vector<fs::path> programLinks(const fs::path& root) {
  std::vector<fs::path> links;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_symlink(ec) && it->path().extension() == ".rsp") links.push_back(it->path());
  return links;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fs::path base = fs::temp_directory_path() / ("robotsim-fuzz-walk-" + std::to_string(::getpid()));
  const fs::path root = base / "submissions", outside = base / "outside";
  std::error_code ec;
  fs::remove_all(base, ec);
  fs::create_directories(root);
  fs::create_directories(outside);
  std::ofstream(outside / "secret.rsp") << "; a file outside the folder graded\nEND\n";
  std::ofstream(outside / "passwd") << "root:x:0:0:a stand-in for a system file, never one of the machine's\n";
  build(size ? data + 1 : data, size ? size - 1 : 0, root, outside);

  // The folder named absolute, relative, with a trailing slash, or as "./".
  const std::uint8_t how = size ? data[0] % 4 : 0;
  const fs::path cwd = fs::current_path();
  const std::string named = how == 0   ? root.string()
                            : how == 1 ? fs::relative(root, cwd).string()
                            : how == 2 ? root.string() + "/"
                                       : (fs::relative(root, cwd) / ".").string();
  const rs::testrun::SubmissionWalk walk = rs::testrun::findSubmissions({named});
  require(walk.errors.empty());

  const fs::path home = fs::canonical(root);
  std::set<std::string> graded;
  for (const std::string& f : walk.files) {
    require(graded.insert(f).second);
    const fs::path target = fs::canonical(fs::absolute(f), ec);
    require(!ec && rs::launch::isInside(home, target) && fs::is_regular_file(target));
  }
  require(std::is_sorted(walk.files.begin(), walk.files.end()));
  std::set<std::string> refused;
  for (const rs::testrun::RefusedLink& r : walk.refused) {
    require(refused.insert(fs::absolute(r.path).lexically_normal().string()).second);
    require(!graded.count(r.path));
  }
  for (const fs::path& link : programLinks(root)) {
    const fs::path target = fs::canonical(link, ec);
    const bool leaves = ec || !rs::launch::isInside(home, target);
    require(!leaves || refused.count(fs::absolute(link).lexically_normal().string()) == 1);
  }
  fs::remove_all(base, ec);
  return 0;
}
