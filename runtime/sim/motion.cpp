#include "runtime/sim/motion.h"

#include <algorithm>
#include <cmath>

namespace rs::runtime {
namespace {

// 128-bit integers: D·a reaches 2^63 and D·u(τ) 2^116 within the bounds the
// verifier keeps (D < 2^32, a <= 10^9, v / a < 1000 s).
__extension__ typedef __int128 Wide;

constexpr Wide kMicrosPerSecond = 1'000'000;
constexpr Wide kMicros2PerSecond2 = kMicrosPerSecond * kMicrosPerSecond;

Wide ceilDiv(Wide n, Wide d) { return (n + d - 1) / d; }

// The phases of a trapezoid or a triangle, in whole microseconds: ta
// accelerating, tc cruising (0 for a triangle), then ta braking.
struct Phases {
  Wide ta = 0, tc = 0;
};

Phases phasesOf(Wide v, Wide a, Wide d) {
  if (d * a >= v * v) return {ceilDiv(v * kMicrosPerSecond, a), ceilDiv((d * a - v * v) * kMicrosPerSecond, v * a)};
  // The least th with a·th² >= d (th in µs, so a·th² >= d·10^12): a double
  // square root for a start, then whole steps until it is exact.
  const Wide need = d * kMicros2PerSecond2;
  Wide th = static_cast<Wide>(std::ceil(std::sqrt(static_cast<double>(need) / static_cast<double>(a))));
  while (a * th * th < need) ++th;
  while (th > 0 && a * (th - 1) * (th - 1) >= need) --th;
  return {th, 0};
}

}  // namespace

vm::Micros travelTime(const vm::MotorSpec& motor, std::int64_t distance) {
  if (distance <= 0) return 0;
  if (motor.actuation > 0) return motor.actuation;
  // |distance| < 2^32, so distance * 10^6 < 2^53: no overflow.
  if (motor.acceleration <= 0) return (distance * 1'000'000 + motor.speed - 1) / motor.speed;
  const Phases p = phasesOf(motor.speed, motor.acceleration, distance);
  return static_cast<vm::Micros>(2 * p.ta + p.tc);
}

std::int64_t coveredAt(const vm::MotorSpec& motor, std::int64_t distance, vm::Micros elapsed) {
  if (elapsed <= 0 || distance <= 0) return 0;
  if (motor.actuation > 0) return elapsed >= motor.actuation ? distance : elapsed * distance / motor.actuation;
  if (motor.acceleration <= 0) {
    // Before the end, elapsed * speed < distance * 10^6 + speed: no overflow.
    if (elapsed >= travelTime(motor, distance)) return distance;
    return elapsed * motor.speed / 1'000'000;
  }
  const Phases p = phasesOf(motor.speed, motor.acceleration, distance);
  const Wide t = elapsed, total = 2 * p.ta + p.tc;
  if (t >= total) return distance;
  const Wide whole = 2 * p.ta * (p.ta + p.tc);  // u(total)
  Wide u = 0;
  if (t <= p.ta) u = t * t;
  else if (t <= p.ta + p.tc) u = 2 * p.ta * t - p.ta * p.ta;
  else u = whole - (total - t) * (total - t);
  return static_cast<std::int64_t>(Wide{distance} * u / whole);
}

vm::Micros lockStepTime(const vm::MotorSpec& motor, std::int64_t distance) {
  if (distance <= 0) return 0;
  return (distance * 1'000'000 + motor.speed - 1) / motor.speed;
}

std::int32_t positionAt(const MotorSegment& s, const vm::MotorSpec& motor, vm::Micros t) {
  if (t <= s.start) return s.from;
  if (t >= s.end) return s.to;
  const std::int64_t distance = s.to > s.from ? std::int64_t{s.to} - s.from : std::int64_t{s.from} - s.to;
  const Wide span = s.end - s.start, part = Wide{distance} * (t - s.start);
  const std::int64_t covered = !s.lockStep ? coveredAt(motor, distance, t - s.start)
                               : s.lead    ? static_cast<std::int64_t>((part + span - 1) / span)
                                           : static_cast<std::int64_t>(part / span);
  return static_cast<std::int32_t>(s.to > s.from ? s.from + covered : s.from - covered);
}

}  // namespace rs::runtime
