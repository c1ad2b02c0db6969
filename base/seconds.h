// Simulated time for people: microseconds as seconds with three decimals.
#pragma once

#include <cstdint>
#include <string>

namespace rs::base {

/// "12.345", "-0.001": microseconds rounded to the nearest millisecond
/// (halves up, the same digits on every machine).
std::string formatSeconds(std::int64_t micros);

}  // namespace rs::base
