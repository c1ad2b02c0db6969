// base::formatNumber: the one rule for printing lengths and angles.
#include <catch2/catch.hpp>

#include "base/number_text.h"

using rs::base::formatNumber;

TEST_CASE("formatNumber keeps 4 decimals at most and drops trailing zeros", "[base]") {
  CHECK(formatNumber(90.0) == "90");
  CHECK(formatNumber(-469.46294) == "-469.4629");
  CHECK(formatNumber(0.5) == "0.5");
  CHECK(formatNumber(1.23456) == "1.2346");
  CHECK(formatNumber(100.0) == "100");
}

TEST_CASE("formatNumber never prints -0, whatever the decimals", "[base]") {
  CHECK(formatNumber(-0.0) == "0");
  CHECK(formatNumber(-0.00004) == "0");   // rounds to -0.0000
  CHECK(formatNumber(-0.00006) == "-0.0001");
  CHECK(formatNumber(-0.004, 2) == "0");  // rounds to -0.00
  CHECK(formatNumber(-0.006, 2) == "-0.01");
}

TEST_CASE("formatNumber with fewer decimals, as the trace's offsets use", "[base]") {
  CHECK(formatNumber(40.0, 2) == "40");
  CHECK(formatNumber(19.996, 2) == "20");
  CHECK(formatNumber(2.5, 2) == "2.5");
  CHECK(formatNumber(1234.0, 0) == "1234");  // no decimal point: no zeros to drop
  CHECK(formatNumber(-0.4, 0) == "0");
}
