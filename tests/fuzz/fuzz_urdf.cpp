// libFuzzer target: any bytes as a URDF file, through robotsim's own code
// around urdfdom (model/urdf/urdf_read.h: the XML checks, urdfdom, the
// chain, the D-H frames, the motors, the geometry). Every mistake is a
// positioned diagnostic; nothing crashes, hangs or goes superlinear. Mesh
// files are looked up beside a file name in an empty folder.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "model/urdf/urdf_read.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string file = [] {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("robotsim-fuzz-urdf-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / "fuzz.urdf").string();
  }();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)rs::urdf::readUrdfText(text, file, {});
  return 0;
}
