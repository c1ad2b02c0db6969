#include "model/workcell/ega_palette.h"

namespace rs::workcell {

std::string_view colorName(Color c) {
  static constexpr std::array<std::string_view, 16> kNames = {
      "BLACK",    "BLUE",      "GREEN",      "CYAN",      "RED",      "MAGENTA",      "BROWN",  "LIGHTGRAY",
      "DARKGRAY", "LIGHTBLUE", "LIGHTGREEN", "LIGHTCYAN", "LIGHTRED", "LIGHTMAGENTA", "YELLOW", "WHITE",
  };
  return kNames[static_cast<std::size_t>(c) & 15];
}

}  // namespace rs::workcell
