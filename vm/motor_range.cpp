#include "vm/motor_range.h"

#include <fmt/format.h>

#include <algorithm>

namespace rs::vm {

std::string outsideRange(const MotorSpec& m) { return fmt::format("outside its range {}..{}", m.min, m.max); }

std::string targetOutsideRange(const MotorSpec& m, std::int64_t target) {
  return fmt::format("motor {} target {} is {}", m.letter, target, outsideRange(m));
}

std::optional<std::size_t> firstOutOfRange(std::span<const MotorSpec> motors, std::span<const std::int32_t> targets) {
  const std::size_t n = std::min(motors.size(), targets.size());
  for (std::size_t i = 0; i < n; ++i)
    if (!inRange(motors[i], targets[i])) return i;
  return std::nullopt;
}

}  // namespace rs::vm
