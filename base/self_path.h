// Where the running program lives, so that an installed or copied robotsim
// finds what it ships beside itself (its library of robots and cells, its
// helper commands) without a path compiled in from the tree it was built in.
#pragma once

#include <filesystem>

namespace rs::base {

/// The running executable's own path (Linux: /proc/self/exe, links
/// resolved), or an empty path when the system will not say.
std::filesystem::path runningExecutable();

}  // namespace rs::base
