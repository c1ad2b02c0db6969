// A motor target against the motor's range: the one check every layer
// makes (the compiler, the verifier, the interpreter, the simulated and the
// serial machine, the teach pendant) and the words each says it in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "vm/image.h"

namespace rs::vm {

/// True if `value` lies in the motor's encoder range, ends included. Takes
/// 64 bits: a relative move's sum may leave 32 before it is checked.
constexpr bool inRange(const MotorSpec& m, std::int64_t value) { return value >= m.min && value <= m.max; }

/// "outside its range MIN..MAX": how every message says a value is not in range.
std::string outsideRange(const MotorSpec& m);

/// "motor A target 121 is outside its range 0..120": a move refused.
std::string targetOutsideRange(const MotorSpec& m, std::int64_t target);

/// The first of `targets` outside its motor's range (motor i for target
/// i), none if every one is in range.
std::optional<std::size_t> firstOutOfRange(std::span<const MotorSpec> motors, std::span<const std::int32_t> targets);

}  // namespace rs::vm
