#include "tools/cli/lib/completion_query.h"

#include <filesystem>
#include <set>
#include <string_view>
#include <system_error>

#include "base/text.h"
#include "compiler/description/library.h"
#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

namespace {

// NAME of every NAME.rsd in `dir` (nothing when it is not a folder).
void rsdNamesIn(const std::filesystem::path& dir, std::set<std::string>& names) {
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::filesystem::path& p = it->path();
    std::error_code typeError;
    if (p.extension() == ".rsd" && it->is_regular_file(typeError)) names.insert(p.stem().string());
  }
}

}  // namespace

std::vector<std::string> libraryNames(const std::string& kind, const std::vector<std::string>& libDirs) {
  std::set<std::string> names;
  for (const std::filesystem::path& dir : compiler::librarySearchPath(libDirs)) {
    rsdNamesIn(dir, names);
    rsdNamesIn(dir / "robots", names);
    if (kind == "cells") rsdNamesIn(dir / "workcells", names);
  }
  return {names.begin(), names.end()};
}

int completionQuery(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  const std::string_view kind = argc > 0 ? argv[0] : "";
  std::vector<std::string> libDirs;
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--lib" && i + 1 < argc) {
      libDirs.emplace_back(argv[++i]);
      continue;
    }
    err << "robotsim: error: __complete: unexpected '" << base::safeText(argv[i]) << "'\n"
        << "  usage: robotsim __complete cells|robots [--lib DIR]...\n";
    return kExitBadInput;
  }
  if (kind != "cells" && kind != "robots") {
    err << "robotsim: error: __complete: unknown kind '" << base::safeText(kind) << "'\n"
        << "  usage: robotsim __complete cells|robots [--lib DIR]... (the shell completions ask this)\n";
    return kExitBadInput;
  }
  for (const std::string& name : libraryNames(std::string(kind), libDirs)) out << name << '\n';
  return kExitOk;
}

}  // namespace rs::cli
