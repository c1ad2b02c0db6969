#include "base/seconds.h"

#include <fmt/format.h>

namespace rs::base {

std::string formatSeconds(std::int64_t micros) {
  const char* sign = micros < 0 ? "-" : "";
  const std::uint64_t u = micros < 0 ? 0 - static_cast<std::uint64_t>(micros) : static_cast<std::uint64_t>(micros);
  const std::uint64_t ms = (u + 500) / 1000;
  return fmt::format("{}{}.{:03}", sign, ms / 1000, ms % 1000);
}

std::string formatSecondsExactly(std::int64_t micros) {
  if (micros % 1000 == 0) return formatSeconds(micros);
  const char* sign = micros < 0 ? "-" : "";
  const std::uint64_t u = micros < 0 ? 0 - static_cast<std::uint64_t>(micros) : static_cast<std::uint64_t>(micros);
  std::string text = fmt::format("{}{}.{:06}", sign, u / 1000000, u % 1000000);
  while (text.back() == '0') text.pop_back();  // never below three decimals: the last three are not all zero
  return text;
}

}  // namespace rs::base
