// The robots of a library that come from URDF files: found as descriptions
// are, read by the URDF helper (model/urdf/urdf_read_remote.h) once a file,
// their diagnostics kept with the library's and positioned in the file's text.
#include <filesystem>

#include "compiler/description/library.h"
#include "diag/read_input.h"
#include "model/urdf/urdf_read_remote.h"

namespace rs::compiler {

namespace fs = std::filesystem;

fs::path Library::findUrdf(const std::string& fileOrName, const fs::path& besides) const {
  std::error_code ec;
  const fs::path here = besides.empty() ? fs::path(fileOrName) : besides / fileOrName;
  if (!libraryNamesOnly_ && fs::exists(here, ec)) return here;
  for (const fs::path& dir : searchPath_)
    for (const fs::path& candidate : {dir / fileOrName, dir / "robots" / fileOrName})
      if (fs::is_regular_file(candidate, ec)) return candidate;
  return {};
}

std::optional<workcell::Robot> Library::urdfRobot(const fs::path& path) {
  std::error_code ec;
  const std::string key = fs::weakly_canonical(path, ec).string();
  if (auto it = urdfRobots_.find(key); it != urdfRobots_.end()) return it->second;
  const auto open = overlay_.find(key);  // an editor's unsaved text
  urdf::UrdfRead read = urdf::readUrdfInHelper(path, urdfOptions_, open == overlay_.end() ? nullptr : &open->second);
  bool positioned = false;
  for (diag::Diagnostic& d : read.diagnostics) {
    positioned = positioned || d.pos.line > 0;
    diagnostics_.push_back(std::move(d));
  }
  if (positioned) {
    diag::Result<std::string> text = open != overlay_.end()
                                         ? diag::Result<std::string>(open->second)
                                         : diag::readInput(path.string(), urdf::kMaxUrdfBytes, "cannot read URDF file");
    if (text) urdfSources_.push_back(std::make_unique<diag::SourceFile>(path.string(), std::move(*text)));
  }
  return urdfRobots_[key] = std::move(read.robot);
}

}  // namespace rs::compiler
