// Reading a URDF file in the helper program robotsim-urdf. urdfdom,
// tinyxml2 and Assimp come from Debian as shared libraries only, and the
// robotsim command is linked statically (docs/install.md): so the command
// runs the helper, which links them, and reads its answer
// (urdf_read_wire.h), as `render` runs in its helper. The helper is found
// beside the running executable, installed or in the build tree.
#pragma once

#include <filesystem>
#include <vector>

#include "model/urdf/urdf_read.h"

namespace rs::urdf {

/// Where robotsim-urdf may be, first found wins, from the running
/// executable's folder, each only where its layout holds: beside a helper
/// (robotsim-*, in LIBEXECDIR/robotsim), the installed layout's from a
/// folder named as BINDIR (BINDIR/../libexec/robotsim), the build tree's
/// (BUILD/libexec/robotsim, also from BUILD/tests and BUILD/bench).
std::vector<std::filesystem::path> urdfHelperCandidates();

/// readUrdfFile, done by robotsim-urdf; with `text`, that text is read as
/// the file's (an editor's unsaved buffer), `path` naming it.
UrdfRead readUrdfInHelper(const std::filesystem::path& path, const UrdfOptions& options,
                          const std::string* text = nullptr);

}  // namespace rs::urdf
