// base::PackedNumbers against a plain vector of the same numbers: random
// reads, a walk in order and equality, for sequences that fit in a byte,
// that rise by more than a byte can hold, that fall, and that are all
// exceptions.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "base/packed_numbers.h"

namespace {

template <class Table>
void checkPackedAgainst(const std::vector<std::uint32_t>& plain) {
  Table table;
  for (std::uint32_t v : plain) table.push_back(v);
  REQUIRE(table.size() == plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    INFO("at " << i);
    REQUIRE(table[i] == plain[i]);
  }
  CHECK(table.toVector() == plain);
  Table again;
  for (std::uint32_t v : plain) again.push_back(v);
  CHECK(again == table);
  if (!plain.empty()) {
    Table other;
    for (std::size_t i = 0; i < plain.size(); ++i) other.push_back(i + 1 == plain.size() ? plain[i] + 1 : plain[i]);
    CHECK_FALSE(other == table);
  }
}

std::vector<std::uint32_t> packedTestNumbers(std::mt19937& random, std::size_t n, int kind) {
  std::vector<std::uint32_t> v;
  std::uint32_t line = 1;
  for (std::size_t i = 0; i < n; ++i) {
    switch (kind) {
      case 0: line += random() % 3; v.push_back(line); break;                  // rises of a byte
      case 1: line += random() % 4 == 0 ? 300 + random() % 70000 : 1; v.push_back(line); break;  // long gaps
      case 2: v.push_back(random() % 600); break;                              // falls and rises
      default: v.push_back(static_cast<std::uint32_t>(random()) | 0x80000000u); break;  // all exceptions
    }
  }
  return v;
}

}  // namespace

TEST_CASE("packed numbers: every number read back, at random and in order", "[image]") {
  std::mt19937 random(20261126);
  for (int kind = 0; kind < 4; ++kind)
    for (std::size_t n : {0u, 1u, 15u, 16u, 17u, 33u, 1000u}) {
      INFO("kind " << kind << ", " << n << " numbers");
      const std::vector<std::uint32_t> plain = packedTestNumbers(random, n, kind);
      checkPackedAgainst<rs::base::RisingNumbers>(plain);
      checkPackedAgainst<rs::base::SmallNumbers>(plain);
    }
}

TEST_CASE("packed numbers: the edges of a byte", "[image]") {
  // 254 is the largest rise or number a byte holds; 255 is the escape.
  const std::vector<std::uint32_t> rises = {0, 254, 508, 763, 763, 1019, 0, 4294967295u, 4294967295u, 1};
  checkPackedAgainst<rs::base::RisingNumbers>(rises);
  checkPackedAgainst<rs::base::SmallNumbers>({254, 255, 256, 0, 1, 4294967295u});
  const rs::base::RisingNumbers fromList = {3, 4, 5};
  CHECK(fromList.toVector() == std::vector<std::uint32_t>{3, 4, 5});
}
