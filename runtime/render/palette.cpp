#include "runtime/render/palette.h"

namespace rs::render {

std::string_view colorName(workcell::Color c) {
  static constexpr std::array<std::string_view, 16> kNames = {
      "BLACK",    "BLUE",      "GREEN",      "CYAN",      "RED",      "MAGENTA",      "BROWN",  "LIGHTGRAY",
      "DARKGRAY", "LIGHTBLUE", "LIGHTGREEN", "LIGHTCYAN", "LIGHTRED", "LIGHTMAGENTA", "YELLOW", "WHITE",
  };
  return kNames[static_cast<std::size_t>(c) & 15];
}

}  // namespace rs::render
