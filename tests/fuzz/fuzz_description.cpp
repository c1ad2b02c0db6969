// libFuzzer target: any bytes as a description (.rsd), read as the CLI
// reads --cell FILE: parsed, then its first workcell (or robot) built. Names
// are looked up in the file only: an empty search path, because looking a
// missing name up in the standard library parses every file of it (about
// 4 ms an input, 20 times the rest), and those files are ours, not the
// untrusted input. Every mistake is a positioned diagnostic; nothing
// crashes or goes superlinear.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "compiler/description/library.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = [] {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("robotsim-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / "fuzz.rsd";
  }();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  rs::compiler::Library library({});
  (void)library.workcell(file.string());
  return 0;
}
