#include "base/number_text.h"

#include <cmath>
#include <fmt/format.h>

namespace rs::base {

std::string formatNumber(double v) {
  if (std::abs(v) < 5e-5) return "0";
  std::string s = fmt::format("{:.4f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

}  // namespace rs::base
