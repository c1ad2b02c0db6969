#include "tools/testrun/submissions.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "launch/confined_path.h"

namespace rs::testrun {

namespace fs = std::filesystem;
using launch::isInside;
using launch::resolve;

namespace {

bool isProgramName(const fs::path& p) { return p.extension() == ".rsp"; }

// One entry met under `folder` (canonical): graded, refused or passed by.
// Links are followed here and only here, after the check.
void visitEntry(const fs::path& entry, const fs::file_status& own, const fs::path& folder, std::set<std::string>& files,
                std::vector<RefusedLink>& refused) {
  const std::string name = entry.lexically_normal().string();
  if (!fs::is_symlink(own)) {
    if (fs::is_regular_file(own) && isProgramName(entry)) files.insert(name);
    return;
  }
  const diag::Result<fs::path> to = resolve(entry, true);
  std::error_code ec;
  const fs::file_status target = to ? fs::status(*to, ec) : fs::file_status();
  if (!to || !isInside(folder, *to)) {
    // Only what would have been graded, or walked, is worth a word.
    if (isProgramName(entry) || fs::is_directory(target))
      refused.push_back(
          {name, to ? to->string() : std::string(), folder.string(), to ? std::string() : to.failure().message});
    return;
  }
  if (fs::is_regular_file(target) && isProgramName(entry)) files.insert(name);
}

}  // namespace

SubmissionWalk findSubmissions(const std::vector<std::string>& paths) {
  SubmissionWalk walk;
  std::set<std::string> files;
  for (const std::string& p : paths) {
    std::error_code ec;
    const fs::file_status st = fs::status(p, ec);
    if (ec || !fs::exists(st)) {
      const fs::file_status own = fs::symlink_status(p, ec);
      if (!ec && fs::is_symlink(own)) {  // a link to nowhere, named
        const diag::Result<fs::path> folder = resolve(fs::absolute(p).parent_path(), true);
        const diag::Result<fs::path> link = resolve(p, true);
        walk.refused.push_back({fs::path(p).lexically_normal().string(), "", folder ? folder->string() : std::string(),
                                link ? std::string() : link.failure().message});
        continue;
      }
      walk.errors.push_back({p, {}, diag::Severity::Error, "no such file or folder"});
      continue;
    }
    if (!fs::is_directory(st)) {  // a file named: confined to its own folder
      const diag::Result<fs::path> folder = resolve(fs::absolute(p).parent_path(), true);
      if (!folder) {
        walk.errors.push_back({p, {}, diag::Severity::Error, "cannot follow its folder: " + folder.failure().message});
        continue;
      }
      visitEntry(p, fs::symlink_status(p, ec), *folder, files, walk.refused);
      continue;
    }
    const diag::Result<fs::path> folder = resolve(p, true);
    if (!folder) {
      walk.errors.push_back({p, {}, diag::Severity::Error, "cannot follow: " + folder.failure().message});
      continue;
    }
    fs::recursive_directory_iterator it(p, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      std::error_code own;
      const fs::file_status status = it->symlink_status(own);
      if (!own) visitEntry(it->path(), status, *folder, files, walk.refused);
    }
    if (ec) walk.errors.push_back({p, {}, diag::Severity::Error, "cannot list: " + ec.message()});
  }
  walk.files.assign(files.begin(), files.end());
  std::sort(walk.refused.begin(), walk.refused.end(),
            [](const RefusedLink& a, const RefusedLink& b) { return a.path < b.path; });
  walk.refused.erase(std::unique(walk.refused.begin(), walk.refused.end(),
                                 [](const RefusedLink& a, const RefusedLink& b) { return a.path == b.path; }),
                     walk.refused.end());
  return walk;
}

diag::Diagnostic refusalOf(const RefusedLink& link) {
  const std::string message =
      link.target.empty()
          ? fmt::format("a symbolic link that cannot be followed ({}): not graded", link.reason)
          : fmt::format("a symbolic link to {}, outside the folder graded ({}): not graded", link.target, link.folder);
  return {link.path,
          {},
          diag::Severity::Error,
          message,
          "submission-outside-folder",
          "a submission is graded inside its folder: copy the file there instead of linking to it"};
}

}  // namespace rs::testrun
