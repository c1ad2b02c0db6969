// The colours of the pictures: the EGA palette (model/workcell/ega_palette.h,
// the one table of the 16 colours and their names) and the background.
#pragma once

#include "model/workcell/ega_palette.h"

namespace rs::render {

using workcell::colorName;
using workcell::kEga;
using workcell::Rgb;
using workcell::rgb;

/// The picture's background: darker than every EGA colour but BLACK.
inline constexpr Rgb kBackground = {0x10, 0x12, 0x1C};

}  // namespace rs::render
