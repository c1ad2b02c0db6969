// A number as people read it in tables, hovers and the terminal pendant:
// the one rule every printer of lengths and angles follows.
#pragma once

#include <string>

namespace rs::base {

/// 4 decimals at most, trailing zeros dropped, never "-0": "90", "-469.4629".
std::string formatNumber(double v);

}  // namespace rs::base
