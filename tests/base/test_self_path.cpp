// runningExecutable: the path an installed robotsim finds its library from.
#include <catch2/catch.hpp>

#include <filesystem>

#include "base/self_path.h"

namespace fs = std::filesystem;

TEST_CASE("runningExecutable names the file this test program runs from", "[base]") {
  fs::path self = rs::base::runningExecutable();
  REQUIRE(self.is_absolute());
  REQUIRE(fs::is_regular_file(self));
  // The same file as the kernel's own link, compared by device and inode.
  CHECK(fs::equivalent(self, "/proc/self/exe"));
  CHECK(self.filename().string().find("robotsim") != std::string::npos);
}
