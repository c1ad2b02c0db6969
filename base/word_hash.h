// A hash of a key of 64-bit words, for the memories that remember work by
// everything it depends on (the sweep's moves, the robot's sight): one
// multiply a word, then splitmix64's finaliser once. Those keys are looked
// up on every move, so the hash is kept to that (with the finaliser on
// every word it was a fifth of a pick-and-place run's time).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rs::base {

struct WordsHash {
  std::size_t operator()(const std::vector<std::uint64_t>& key) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.size();
    for (const std::uint64_t w : key) h = (std::rotl(h, 23) ^ w) * 0x9e3779b97f4a7c15ULL;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

}  // namespace rs::base
