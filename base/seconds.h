// Simulated time for people: microseconds as seconds with three decimals,
// or with as many as a time someone wrote needs.
#pragma once

#include <cstdint>
#include <string>

namespace rs::base {

/// "12.345", "-0.001": microseconds rounded to the nearest millisecond
/// (halves up, the same digits on every machine).
std::string formatSeconds(std::int64_t micros);

/// "12.345", "0.0005", "1.234567": three decimals, more where the
/// microseconds need them (trailing zeros dropped), so that a time written
/// in a test ("during 0..0.0005") is printed as written, not rounded.
std::string formatSecondsExactly(std::int64_t micros);

}  // namespace rs::base
