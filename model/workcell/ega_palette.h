// The paper's 16 EGA colours as RGB, and their names: the one table for
// everything that shows or writes a colour (the stills, the line dumps and
// the HTML animation of runtime/render; the URDF export's materials).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "model/workcell/model.h"

namespace rs::workcell {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

/// The standard EGA palette, indexed by Color.
inline constexpr std::array<Rgb, 16> kEga = {{
    {0x00, 0x00, 0x00},  // 0 BLACK
    {0x00, 0x00, 0xAA},  // 1 BLUE
    {0x00, 0xAA, 0x00},  // 2 GREEN
    {0x00, 0xAA, 0xAA},  // 3 CYAN
    {0xAA, 0x00, 0x00},  // 4 RED
    {0xAA, 0x00, 0xAA},  // 5 MAGENTA
    {0xAA, 0x55, 0x00},  // 6 BROWN
    {0xAA, 0xAA, 0xAA},  // 7 LIGHTGRAY
    {0x55, 0x55, 0x55},  // 8 DARKGRAY
    {0x55, 0x55, 0xFF},  // 9 LIGHTBLUE
    {0x55, 0xFF, 0x55},  // 10 LIGHTGREEN
    {0x55, 0xFF, 0xFF},  // 11 LIGHTCYAN
    {0xFF, 0x55, 0x55},  // 12 LIGHTRED
    {0xFF, 0x55, 0xFF},  // 13 LIGHTMAGENTA
    {0xFF, 0xFF, 0x55},  // 14 YELLOW
    {0xFF, 0xFF, 0xFF},  // 15 WHITE
}};

inline Rgb rgb(Color c) { return kEga[static_cast<std::size_t>(c) & 15]; }

/// "LIGHTRED", as the description language spells it.
std::string_view colorName(Color c);

}  // namespace rs::workcell
