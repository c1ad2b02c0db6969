// ASCII letter case for the language's case-insensitive words (mnemonics,
// labels, points, variables, description and stimuli keywords): only the
// letters a-z/A-Z fold; every other byte compares as it is.
#pragma once

#include <string_view>

namespace rs::base {

constexpr char asciiUpper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

/// Equal but for ASCII letter case ("moveto" and "MOVETO").
constexpr bool sameName(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (asciiUpper(a[i]) != asciiUpper(b[i])) return false;
  return true;
}

}  // namespace rs::base
