// Sine and cosine of an angle in degrees, fast and exact at right angles.
//
// Why not std::sin/std::cos: forward kinematics needs one sine/cosine pair
// per revolute joint, and glibc's pair costs ~17 ns here, too much for the
// 100 ns budget of a 6-axis arm. Degrees also allow an exact range
// reduction (subtracting a multiple of 90 is exact), so cos 90° is 0, not
// 6e-17, and a robot at right angles has exact zeros in its matrices.
#pragma once

#include <cmath>
#include <cstdint>

#include "model/kinematics/angles.h"

namespace rs::kinematics {

/// Taylor coefficients (-1)^k / (2k+1)! and (-1)^k / (2k)!, k = 0..8.
// clang-format off
inline constexpr double kSinTaylor[] = {1.0, -1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880, -1.0 / 39916800,
                                        1.0 / 6227020800, -1.0 / 1307674368000};
inline constexpr double kCosTaylor[] = {1.0, -1.0 / 2, 1.0 / 24, -1.0 / 720, 1.0 / 40320, -1.0 / 3628800,
                                        1.0 / 479001600, -1.0 / 87178291200, 1.0 / 20922789888000};
// clang-format on

/// sin and cos of x radians for |x| <= π/4: Taylor series to x^15 and
/// x^16, whose first omitted terms are below 5e-17. Evaluated in powers of
/// t = x² by Estrin's scheme (pairs, then pairs of pairs), which keeps the
/// chain of dependent multiplications short.
inline void sinCosReduced(double x, double& s, double& c) {
  const double t = x * x, t2 = t * t, t4 = t2 * t2;
  const auto& S = kSinTaylor;
  const auto& C = kCosTaylor;
  const double s03 = (S[0] + S[1] * t) + t2 * (S[2] + S[3] * t);
  const double s47 = (S[4] + S[5] * t) + t2 * (S[6] + S[7] * t);
  const double c03 = (C[0] + C[1] * t) + t2 * (C[2] + C[3] * t);
  const double c47 = (C[4] + C[5] * t) + t2 * (C[6] + C[7] * t);
  s = x * (s03 + t4 * s47);
  c = c03 + t4 * (c47 + t4 * C[8]);
}

/// s = sin(degrees), c = cos(degrees), within a few ulp of the exact values
/// and exact at multiples of 90. Falls back to std::sin/std::cos for
/// angles beyond ±1e15 degrees and for NaN or infinities.
inline void sinCosDegrees(double degrees, double& s, double& c) {
  if (!(std::abs(degrees) < 1e15)) {
    s = std::sin(degrees * kDegToRad);
    c = std::cos(degrees * kDegToRad);
    return;
  }
  // Round to the nearest quarter turn by adding and removing 1.5·2^52 (no
  // libm call; valid below 2^51, and compilers keep it without -ffast-math).
  constexpr double kRound = 6755399441055744.0;
  const double quarter = (degrees * (1.0 / 90.0) + kRound) - kRound;
  const double reduced = degrees - 90.0 * quarter;  // exact, about [-45, 45]
  double sr, cr;
  sinCosReduced(reduced * kDegToRad, sr, cr);
  switch (static_cast<std::int64_t>(quarter) & 3) {
    case 0: s = sr, c = cr; break;
    case 1: s = cr, c = -sr; break;
    case 2: s = -sr, c = -cr; break;
    default: s = -cr, c = sr; break;
  }
}

}  // namespace rs::kinematics
