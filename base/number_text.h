// A number as people read it in tables, hovers and the terminal pendant:
// the one rule every printer of lengths and angles follows.
#pragma once

#include <string>

namespace rs::base {

/// `decimals` at most (4 unless said), trailing zeros dropped, never "-0":
/// "90", "-469.4629"; formatNumber(0.004, 2) is "0".
std::string formatNumber(double v, int decimals = 4);

}  // namespace rs::base
