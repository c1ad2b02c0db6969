#include "tools/cli/lib/helpers.h"

#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "base/self_path.h"
#include "base/text.h"
#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

const Command* commandLeftToHelper(std::span<const Command> table, int argc, const char* const* argv) {
  if (argc < 2) return nullptr;
  const std::string_view word = argv[1];
  for (const Command& row : table)
    if (row.name == word) return row.inHelper && row.run == nullptr ? &row : nullptr;
  return nullptr;
}

std::vector<std::filesystem::path> helperCandidates(const std::filesystem::path& executable, std::string_view command) {
  const std::filesystem::path dir = executable.parent_path();
  const std::string file = fmt::format("robotsim-{}", command);
  return {(dir / ROBOTSIM_LIBEXEC_FROM_BINDIR / file).lexically_normal(), dir / "libexec" / "robotsim" / file};
}

int execHelper(std::string_view command, int argc, const char* const* argv, std::ostream& err) {
  const std::filesystem::path self = base::runningExecutable();
  if (self.empty()) {
    err << fmt::format(
        "robotsim: error: '{}' runs in a helper program, found beside robotsim, but /proc/self/exe does not say "
        "where robotsim is\n  hint: run robotsim on Linux with /proc mounted\n",
        command);
    return kExitBadInput;
  }
  const std::vector<std::filesystem::path> candidates = helperCandidates(self, command);
  for (const std::filesystem::path& path : candidates) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    std::vector<std::string> args{path.string()};
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
    std::vector<char*> pointers;
    for (std::string& a : args) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    ::execv(pointers[0], pointers.data());
    const int error = errno;
    err << fmt::format("robotsim: error: cannot run '{}''s helper {}: {}\n  hint: reinstall robotsim\n", command,
                       base::safeText(path.string()), std::strerror(error));
    return kExitBadInput;
  }
  err << fmt::format("robotsim: error: '{}' runs in a helper program that is missing: looked for\n", command);
  for (const std::filesystem::path& path : candidates) err << fmt::format("  {}\n", base::safeText(path.string()));
  err << fmt::format(
      "  hint: reinstall robotsim (its helpers are part of it); in a build tree, `cmake --build BUILD --target "
      "robotsim` builds them; a copied robotsim needs the libexec/robotsim folder at one of those places\n");
  return kExitBadInput;
}

}  // namespace rs::cli
