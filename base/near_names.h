// "Did you mean ...?": the nearest of some names to a word that matched
// none of them (a misspelled instruction, command, label, keyword), by edit
// distance ignoring ASCII letter case. Cheap on purpose: a word longer than
// kMaxNearWord letters is never anyone's near miss.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <vector>

#include "base/ascii.h"

namespace rs::base {

inline constexpr std::size_t kMaxNearWord = 32;

/// Levenshtein distance, ignoring ASCII letter case.
inline std::size_t nameDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (asciiUpper(a[i - 1]) == asciiUpper(b[j - 1]) ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// The first of `names` nearest to `word` at most `maxDistance` edits away
/// (a different name, not `word` itself in another case), or "". `nameOf`
/// gives the name of an element (for a list of records, not of strings).
template <class Names, class NameOf>
std::string_view nearestNameBy(std::string_view word, const Names& names, NameOf nameOf, std::size_t maxDistance = 2) {
  if (word.size() > kMaxNearWord) return {};
  std::string_view best;
  std::size_t bestDistance = maxDistance + 1;
  for (const auto& candidate : names) {
    const std::string_view name(nameOf(candidate));
    if (name.size() > word.size() + maxDistance || word.size() > name.size() + maxDistance) continue;
    const std::size_t d = nameDistance(word, name);
    if (d < bestDistance) bestDistance = d, best = name;
  }
  return best;
}

template <class Names>
std::string_view nearestName(std::string_view word, const Names& names, std::size_t maxDistance = 2) {
  return nearestNameBy(word, names, [](const auto& n) -> std::string_view { return std::string_view(n); }, maxDistance);
}

/// How far a misspelling of `word` may be from what was meant: one edit in
/// a name of at most three letters (else "N" would suggest any two-letter
/// name), two in a longer one.
inline std::size_t typoDistance(std::string_view word) { return word.size() <= 3 ? 1 : 2; }

}  // namespace rs::base
