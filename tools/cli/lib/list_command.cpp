#include "tools/cli/lib/list_command.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>

#include "base/text.h"
#include "compiler/description/library.h"
#include "compiler/description/library_listing.h"
#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

void addListOptions(CLI::App* cmd, ListOptions& o) {
  cmd->add_option("--lib", o.libDirs, "Also list the descriptions in this directory (repeatable)")
      ->allow_extra_args(false);
  cmd->footer(
      "The search path is the library (stdlib/), then each --lib DIR, then each entry of ROBOTSIM_PATH. A name is "
      "found as NAME.rsd in a directory of the path or its kind's folder (robots/, grippers/, objects/, "
      "workcells/); the first on the path wins, and a later one with the same name is listed as hidden.");
}

int listCommand(const ListOptions& o, std::ostream& out, std::ostream& err) {
  const compiler::LibraryListing listing = compiler::listLibrary(compiler::librarySearchPath(o.libDirs));
  out << "library path (searched in this order):\n";
  for (const auto& dir : listing.searchPath) out << "  " << base::safeText(dir.string()) << '\n';
  std::size_t nameWidth = 0;
  for (const compiler::LibraryEntry& e : listing.entries) nameWidth = std::max(nameWidth, e.name.size());
  for (const compiler::LibraryEntry& e : listing.entries) {
    std::string what = e.summary.empty() ? "(no header comment)" : e.summary;
    if (e.hidden) what += fmt::format(" (hidden by the {} above; from {})", e.name, e.file.string());
    out << fmt::format("{:<9} {:<{}}  {}\n", e.kind, base::safeText(e.name), nameWidth, base::safeText(what));
  }
  // What no command can use either: said, so the listing hides nothing.
  for (const compiler::SkippedFile& s : listing.skipped)
    err << fmt::format("{}: warning: not listed: {}\n", base::safeText(s.file.string()), s.reason);
  return kExitOk;
}

}  // namespace rs::cli
