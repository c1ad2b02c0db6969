// Degrees at the edges (tables, programs, the paper), radians inside.
#pragma once

#include <cmath>
#include <numbers>

namespace rs::kinematics {

inline constexpr double kDegToRad = std::numbers::pi / 180.0;
inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// An angle in degrees brought into (-180, 180].
inline double normalizeDegrees(double degrees) {
  double r = std::remainder(degrees, 360.0);  // exact, in [-180, 180]
  if (r <= -180.0) r += 360.0;
  return r + 0.0;  // no -0
}

}  // namespace rs::kinematics
