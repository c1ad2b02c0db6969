// A hash of a key of 64-bit words, for the memories that remember work by
// everything it depends on (the sweep's moves, the robot's sight, the
// belts' plans): one multiply a word, then splitmix64's finaliser once.
// Those keys are looked up on every move and every wake, so the hash is
// kept to that (with the finaliser on every word it was a fifth of a
// pick-and-place run's time), and the words go to four lanes that do not
// wait for each other (one chain of multiplies waited ~5 cycles a word).
// Only speed depends on it: a memory compares whole keys.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rs::base {

struct WordsHash {
  std::size_t operator()(const std::vector<std::uint64_t>& key) const {
    constexpr std::uint64_t kOdd = 0x9e3779b97f4a7c15ULL;
    const std::uint64_t* w = key.data();
    const std::size_t n = key.size();
    std::uint64_t a = kOdd ^ n, b = 0x243f6a8885a308d3ULL, c = 0x13198a2e03707344ULL, d = 0xa4093822299f31d0ULL;
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
      a = (std::rotl(a, 23) ^ w[i]) * kOdd;
      b = (std::rotl(b, 23) ^ w[i + 1]) * kOdd;
      c = (std::rotl(c, 23) ^ w[i + 2]) * kOdd;
      d = (std::rotl(d, 23) ^ w[i + 3]) * kOdd;
    }
    for (; i < n; ++i) a = (std::rotl(a, 23) ^ w[i]) * kOdd;
    std::uint64_t h = a ^ std::rotl(b, 16) ^ std::rotl(c, 32) ^ std::rotl(d, 48);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

}  // namespace rs::base
