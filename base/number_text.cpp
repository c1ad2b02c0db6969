#include "base/number_text.h"

#include <fmt/format.h>

namespace rs::base {

std::string formatNumber(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? std::string("0") : s;
}

}  // namespace rs::base
