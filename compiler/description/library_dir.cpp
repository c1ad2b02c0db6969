#include "compiler/description/library_dir.h"

#include <system_error>

#include "base/self_path.h"

// Set by CMake (CMakeLists.txt, "install"): the library's folder relative
// to the executable's, in an installed prefix (from the command's folder,
// and from the helpers' LIBEXECDIR/robotsim), and in a flat folder (and
// from its libexec/robotsim: the build tree's helpers).
#ifndef ROBOTSIM_LIBRARY_FROM_BINDIR
#error "ROBOTSIM_LIBRARY_FROM_BINDIR: the build defines it (CMakeLists.txt)"
#endif
#ifndef ROBOTSIM_LIBRARY_FROM_LIBEXECDIR
#error "ROBOTSIM_LIBRARY_FROM_LIBEXECDIR: the build defines it (CMakeLists.txt)"
#endif
#ifndef ROBOTSIM_LIBRARY_FROM_PREFIX
#error "ROBOTSIM_LIBRARY_FROM_PREFIX: the build defines it (CMakeLists.txt)"
#endif

namespace rs::compiler {

namespace fs = std::filesystem;

std::vector<fs::path> libraryDirCandidates() {
  const fs::path exe = base::runningExecutable();
  if (exe.empty()) return {};
  const fs::path dir = exe.parent_path();
  // A helper program (robotsim-render and its links) looks from LIBEXECDIR/robotsim;
  // robotsim itself never does, so a lone copy of it finds no library two folders up.
  if (exe.filename().string().starts_with("robotsim-"))
    return {(dir / ROBOTSIM_LIBRARY_FROM_LIBEXECDIR).lexically_normal(),
            (dir / "../.." / ROBOTSIM_LIBRARY_FROM_PREFIX).lexically_normal()};
  return {(dir / ROBOTSIM_LIBRARY_FROM_BINDIR).lexically_normal(),
          (dir / ROBOTSIM_LIBRARY_FROM_PREFIX).lexically_normal()};
}

// Links resolved: in the build tree the library's files are the source's
// stdlib/ (an editor's go-to-definition lands on the file a developer edits).
std::optional<fs::path> libraryDir() {
  for (const fs::path& candidate : libraryDirCandidates()) {
    std::error_code ec;
    if (!fs::is_directory(candidate, ec)) continue;
    const fs::path real = fs::canonical(candidate, ec);
    return ec ? candidate : real;
  }
  return std::nullopt;
}

}  // namespace rs::compiler
