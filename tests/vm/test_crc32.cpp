// The image checksum: CRC-32 as zlib and IEEE 802.3 define it. robotsim
// calls zlib's crc32_z (vm/image_file.cpp); these check the wrapper
// against the standard check value, and against zlib's older crc32() entry
// on every length and alignment that matters to a loop of several bytes a
// step, and over pieces.
#include <catch2/catch.hpp>

#include <zlib.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "vm/image_file.h"

TEST_CASE("crc32 gives the standard check value", "[vm][image]") {
  const std::string_view check = "123456789";
  CHECK(rs::vm::crc32(reinterpret_cast<const std::uint8_t*>(check.data()), check.size()) == 0xCBF43926u);
  CHECK(rs::vm::crc32(nullptr, 0) == 0u);
}

TEST_CASE("crc32 agrees with zlib on every length and offset", "[vm][image]") {
  std::vector<std::uint8_t> bytes(300);
  std::uint32_t x = 12345;  // a fixed linear congruential sequence: any bytes do
  for (auto& b : bytes) b = static_cast<std::uint8_t>((x = x * 1103515245u + 12345u) >> 16);
  for (std::size_t offset = 0; offset < 4; ++offset)
    for (std::size_t length = 0; offset + length <= bytes.size(); length += 1 + length / 16) {
      const std::uint8_t* p = bytes.data() + offset;
      const auto zlib = static_cast<std::uint32_t>(::crc32(0L, p, static_cast<uInt>(length)));
      INFO("offset " << offset << " length " << length);
      CHECK(rs::vm::crc32(p, length) == zlib);
    }
}

TEST_CASE("crc32Update continues a CRC over pieces, as zlib's crc32 does", "[vm][image]") {
  std::vector<std::uint8_t> bytes(1000);
  std::uint32_t x = 777;
  for (auto& b : bytes) b = static_cast<std::uint8_t>((x = x * 1103515245u + 12345u) >> 16);
  for (std::size_t cut : {0, 1, 3, 4, 5, 64, 999, 1000}) {
    INFO("cut at " << cut);
    const std::uint32_t first = rs::vm::crc32(bytes.data(), cut);
    const std::uint32_t both = rs::vm::crc32Update(first, bytes.data() + cut, bytes.size() - cut);
    CHECK(both == static_cast<std::uint32_t>(::crc32(0L, bytes.data(), static_cast<uInt>(bytes.size()))));
  }
}
