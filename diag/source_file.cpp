#include "diag/source_file.h"

#include <algorithm>
#include <cstring>

namespace rs::diag {

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  if (const std::size_t mark = text_.size() - withoutByteOrderMark(text_).size()) text_.erase(0, mark);
  lineStarts_.push_back(0);
  const char* const begin = text_.data();
  const char* const end = begin + text_.size();
  // memchr: the library's vectorised search, much faster than a byte loop.
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p))));) {
    if (++p == end) break;
    lineStarts_.push_back(static_cast<std::size_t>(p - begin));
  }
}

std::string_view SourceFile::line(std::uint32_t number) const {
  if (number == 0 || number > lineStarts_.size()) return {};
  const std::size_t start = lineStarts_[number - 1];
  std::size_t end = text_.find('\n', start);
  if (end == std::string::npos) end = text_.size();
  if (end > start && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(start, end - start);
}

LoneCarriageReturn SourceFile::findLoneCarriageReturn() const {
  const char* const begin = text_.data();
  const char* const end = begin + text_.size();
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\r', static_cast<std::size_t>(end - p))));
       ++p) {
    if (p + 1 < end && p[1] == '\n') continue;
    const std::size_t at = static_cast<std::size_t>(p - begin);
    // The line it is on: the last line start at or before it.
    std::size_t line = 0, lo = 0, hi = lineStarts_.size();
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (lineStarts_[mid] <= at) line = mid, lo = mid + 1;
      else hi = mid;
    }
    const std::string_view before = std::string_view(text_).substr(lineStarts_[line], at - lineStarts_[line]);
    std::uint32_t col = 1;
    for (std::size_t i = 0; i < before.size(); i += std::max<std::size_t>(utf8SequenceLength(before, i), 1)) ++col;
    return {true, {static_cast<std::uint32_t>(line + 1), col}};
  }
  return {};
}

namespace {

// Where byte `at` is, when every byte before it is valid UTF-8: columns
// count characters (lead bytes), as the lexer's do.
Pos positionOf(std::string_view text, std::size_t at) {
  Pos pos{1, 1};
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') pos = {pos.line + 1, 1};
    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++pos.col;
  }
  return pos;
}

}  // namespace

Utf8Problem findInvalidUtf8(std::string_view text) {
  constexpr std::uint64_t kHighBits = 0x8080808080808080ull;
  for (std::size_t i = 0; i < text.size();) {
    // Programs are mostly ASCII: skip it eight bytes at a time.
    std::uint64_t word;
    if (i + 8 <= text.size() && (std::memcpy(&word, text.data() + i, 8), (word & kHighBits) == 0)) {
      i += 8;
      continue;
    }
    const std::size_t n = utf8SequenceLength(text, i);
    if (n == 0) return {true, positionOf(text, i), static_cast<unsigned char>(text[i])};
    i += n;
  }
  return {};
}

}  // namespace rs::diag
