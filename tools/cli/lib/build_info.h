// What robotsim --version names about the build itself. The definition is
// generated at build time (scripts/build_info.cmake) from CMake's
// project(VERSION), git, and the build type.
#pragma once

#include <string_view>

namespace rs::cli {

struct BuildInfo {
  std::string_view version;    ///< CMakeLists.txt's project(robotsim VERSION ...)
  std::string_view commit;     ///< short hash, "-modified" if the tree differed; or "unknown"
  std::string_view buildType;  ///< CMAKE_BUILD_TYPE: Release, Debug, ...
};

BuildInfo buildInfo();

}  // namespace rs::cli
