// base::formatSeconds and formatSecondsExactly: milliseconds as people read
// them, and a written time with every digit it was written with.
#include <catch2/catch.hpp>

#include "base/seconds.h"

TEST_CASE("seconds: three decimals, and as many as a written time needs", "[base][seconds]") {
  using rs::base::formatSeconds;
  using rs::base::formatSecondsExactly;
  CHECK(formatSeconds(500) == "0.001");  // rounded, halves up
  CHECK(formatSeconds(12'345'000) == "12.345");
  CHECK(formatSecondsExactly(0) == "0.000");
  CHECK(formatSecondsExactly(500) == "0.0005");
  CHECK(formatSecondsExactly(1'234'567) == "1.234567");
  CHECK(formatSecondsExactly(2'500'100) == "2.5001");
  CHECK(formatSecondsExactly(12'345'000) == "12.345");
  CHECK(formatSecondsExactly(-1'500) == "-0.0015");
  CHECK(formatSecondsExactly(-2'000'000) == "-2.000");
}
