#include "base/seconds.h"

#include <fmt/format.h>

namespace rs::base {

std::string formatSeconds(std::int64_t micros) {
  const char* sign = micros < 0 ? "-" : "";
  const std::uint64_t u = micros < 0 ? 0 - static_cast<std::uint64_t>(micros) : static_cast<std::uint64_t>(micros);
  const std::uint64_t ms = (u + 500) / 1000;
  return fmt::format("{}{}.{:03}", sign, ms / 1000, ms % 1000);
}

}  // namespace rs::base
