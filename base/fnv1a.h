// FNV-1a, 64 bits (Fowler, Noll and Vo's hash: xor in a byte, multiply by
// the prime): short and well spread, for hash tables and fingerprints. No
// defence against someone who chooses the bytes to collide.
#pragma once

#include <cstdint>
#include <string_view>

#include "base/ascii.h"

namespace rs::base {

namespace fnv1a_detail {
inline constexpr std::uint64_t kOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kPrime = 1099511628211ull;

template <bool kFoldCase>
constexpr std::uint64_t hash(std::string_view bytes) {
  std::uint64_t h = kOffsetBasis;
  for (const char c : bytes) h = (h ^ static_cast<unsigned char>(kFoldCase ? asciiUpper(c) : c)) * kPrime;
  return h;
}
}  // namespace fnv1a_detail

/// FNV-1a of the bytes as they are.
constexpr std::uint64_t fnv1a(std::string_view bytes) { return fnv1a_detail::hash<false>(bytes); }

/// FNV-1a of the bytes with ASCII letters upper-cased: names that sameName
/// calls the same hash the same.
constexpr std::uint64_t fnv1aIgnoringCase(std::string_view bytes) { return fnv1a_detail::hash<true>(bytes); }

// The published test vectors: the empty string hashes to the offset basis, "a" to 0xaf63dc4c8601ec8c.
static_assert(fnv1a("") == 0xcbf29ce484222325ull && fnv1a("a") == 0xaf63dc4c8601ec8cull);
static_assert(fnv1aIgnoringCase("Label_1") == fnv1a("LABEL_1"));

}  // namespace rs::base
