#include "tools/cli/lib/version_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <ostream>

#include "base/text.h"
#include "compiler/description/library_dir.h"
#include "tools/cli/lib/build_info.h"
#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

void addVersionOptions(CLI::App* cmd, std::string& format) {
  format = "text";
  cmd->add_option("--format", format, "Output: text (one fact a line) or json (one object)")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->footer("Also `robotsim --version [--format json]`. The library is robotsim's own robots, grippers, objects "
              "and workcells, found from the executable's folder (docs/install.md).");
}

int versionCommand(const std::string& format, std::ostream& out) {
  const BuildInfo info = buildInfo();
  const std::optional<std::filesystem::path> library = compiler::libraryDir();
  if (format == "json") {
    nlohmann::ordered_json j;
    j["version"] = info.version;
    j["commit"] = info.commit;
    j["buildType"] = info.buildType;
    j["library"] = library ? nlohmann::ordered_json(base::safeText(library->string())) : nlohmann::ordered_json(nullptr);
    if (!library) {
      nlohmann::ordered_json looked = nlohmann::ordered_json::array();
      for (const auto& dir : compiler::libraryDirCandidates()) looked.push_back(base::safeText(dir.string()));
      j["libraryLookedIn"] = looked;
    }
    out << j.dump() << '\n';
    return kExitOk;
  }
  out << fmt::format("robotsim {}\ncommit: {}\nbuild type: {}\n", info.version, info.commit, info.buildType);
  if (library) {
    out << fmt::format("library: {}\n", base::safeText(library->string()));
  } else {
    std::vector<std::string> looked;
    for (const auto& dir : compiler::libraryDirCandidates()) looked.push_back(base::safeText(dir.string()));
    out << fmt::format("library: not found (looked in {}); only --lib and ROBOTSIM_PATH are searched\n",
                       looked.empty() ? std::string("nowhere: the executable's path is unknown")
                                      : fmt::format("{}", fmt::join(looked, ", ")));
  }
  return kExitOk;
}

}  // namespace rs::cli
