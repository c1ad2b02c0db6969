// Where robotsim's own library of robots, grippers, objects and workcells
// is: found from the running executable, never from a path compiled in from
// the tree it was built in, so that an installed or copied robotsim works
// with its source gone (docs/install.md, "Where the library is").
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

namespace rs::compiler {

/// The folders robotsim looks in for its library, in order, from the
/// running executable's folder EXE: EXE/../share/robotsim/stdlib (an
/// installed prefix: bin/ beside share/; the relative path is CMake's, from
/// GNUInstallDirs) and EXE/share/robotsim/stdlib (a folder holding the
/// executable and share/, as the build tree is laid out). A helper program
/// (`robotsim-NAME`, in LIBEXECDIR/robotsim: render, animate, plot, teach
/// and debug run there, tools/cli/lib/helpers.h) looks instead from its folder to
/// the installed library and to the build tree's (EXE/../../share/...).
/// Empty when the system will not say where the executable is.
std::vector<std::filesystem::path> libraryDirCandidates();

/// The first of libraryDirCandidates() that is a folder, links resolved
/// (the build tree's gives the source's stdlib/), or nullopt.
std::optional<std::filesystem::path> libraryDir();

}  // namespace rs::compiler
