// The fast sine/cosine in degrees used by forward kinematics.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "model/kinematics/trig.h"

using rs::kinematics::sinCosDegrees;

TEST_CASE("sinCosDegrees agrees with std::sin and std::cos", "[kinematics]") {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> small(-720, 720), large(-1e7, 1e7);
  double worst = 0;
  for (int k = 0; k < 200000; ++k) {
    const double degrees = k % 4 == 0 ? large(engine) : small(engine);
    double s = 0, c = 0;
    sinCosDegrees(degrees, s, c);
    // std::sin of the rounded radians is itself off by up to |radians|·1e-16.
    const double radians = degrees * std::numbers::pi / 180;
    const double slack = std::abs(radians) * 2.3e-16;
    worst = std::max(worst, std::max(std::abs(s - std::sin(radians)), std::abs(c - std::cos(radians))) - slack);
  }
  CHECK(worst < 4e-16);
}

TEST_CASE("sinCosDegrees is exact at right angles", "[kinematics]") {
  const double expected[][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};
  for (int k = -8; k <= 8; ++k) {
    double s = 0, c = 0;
    sinCosDegrees(90.0 * k, s, c);
    const auto& e = expected[((k % 4) + 4) % 4];
    INFO(90 * k << " degrees");
    CHECK(s == e[0]);
    CHECK(c == e[1]);
  }
  double s = 0, c = 0;
  sinCosDegrees(30, s, c);
  CHECK(s == Approx(0.5).margin(1e-16));
}

TEST_CASE("sinCosDegrees passes NaN, infinities and huge angles to libm", "[kinematics]") {
  double s = 0, c = 0;
  sinCosDegrees(std::numeric_limits<double>::quiet_NaN(), s, c);
  CHECK(std::isnan(s));
  CHECK(std::isnan(c));
  sinCosDegrees(std::numeric_limits<double>::infinity(), s, c);
  CHECK(std::isnan(s));
  sinCosDegrees(1e300, s, c);
  CHECK(std::isfinite(s));
  CHECK(s * s + c * c == Approx(1.0));
}
