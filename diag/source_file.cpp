#include "diag/source_file.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>

namespace rs::diag {

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  if (const std::size_t mark = text_.size() - withoutByteOrderMark(text_).size()) text_.erase(0, mark);
  if (text_.size() > UINT32_MAX) text_.resize(UINT32_MAX);
  const char* const begin = text_.data();
  const char* const end = begin + text_.size();
  // memchr: the library's vectorised search, much faster than a byte loop.
  // Counted first, so that the index is allocated once, at its size.
  std::size_t breaks = 0;
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p))));)
    ++breaks, ++p;
  lineStarts_.reserve(breaks + 1);
  lineStarts_.push_back(0);
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p))));) {
    if (++p == end) break;
    lineStarts_.push_back(static_cast<std::uint32_t>(p - begin));
  }
  // Only a line longer than kCheckpointBytes gets checkpoints: found from
  // the distance between line starts, walked in order (a byte a line).
  std::uint32_t n = 0;
  std::size_t previous = 0;
  for (auto it = lineStarts_.begin();; ++it) {
    const std::size_t next = it == lineStarts_.end() ? text_.size() + 1 : *it;
    if (n > 0 && next - previous > kCheckpointBytes + 1) addCheckpoints(n);
    if (it == lineStarts_.end()) break;
    previous = next, ++n;
  }
}

void SourceFile::addCheckpoints(std::uint32_t n) {
  const std::string_view l = line(n);
  if (l.size() <= kCheckpointBytes) return;
  const auto start = static_cast<std::size_t>(l.data() - text_.data());
  const std::size_t end = start + l.size();
  std::uint32_t col = 1;
  for (std::size_t at = start;;) {
    at = stepColumns(text_, at, end, col, UINT32_MAX, at + kCheckpointBytes);
    if (at >= end) break;
    checkpoints_.push_back({at, n, col});
  }
}

std::string_view SourceFile::line(std::uint32_t number) const {
  if (number == 0 || number > lineStarts_.size()) return {};
  const std::size_t start = lineStarts_[number - 1];
  // The next line's start follows this line's '\n'; the last line ends the text.
  std::size_t end = number < lineStarts_.size() ? lineStarts_[number] - 1 : text_.size();
  if (number == lineStarts_.size() && end > start && text_[end - 1] == '\n') --end;
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
    std::size_t below = 0, above = lineStarts_.size();  // lineStarts_[below] <= at
    while (above - below > 1) {
      const std::size_t middle = below + (above - below) / 2;
      (lineStarts_[middle] <= at ? below : above) = middle;
    }
    const auto line = static_cast<std::uint32_t>(below + 1);
    std::uint32_t col = 1;
    stepColumns(text_, lineStarts_[line - 1], at, col, UINT32_MAX, at);
    return {true, {line, col}};
  }
  return {};
}

std::size_t SourceFile::offsetOf(Pos pos) const {
  if (pos.line == 0 || pos.line > lineCount()) return text_.size();
  const std::string_view l = line(pos.line);
  std::size_t at = static_cast<std::size_t>(l.data() - text_.data());
  const std::size_t end = at + l.size();
  std::uint32_t col = 1;
  // The last checkpoint at or before the column, if it is on this line.
  const auto after = std::upper_bound(checkpoints_.begin(), checkpoints_.end(), pos, [](Pos p, const Checkpoint& c) {
    return p.line != c.line ? p.line < c.line : p.col < c.col;
  });
  if (after != checkpoints_.begin() && std::prev(after)->line == pos.line) {
    at = std::prev(after)->offset;
    col = std::prev(after)->col;
  }
  return stepColumns(text_, at, end, col, std::max<std::uint32_t>(pos.col, 1), SIZE_MAX);
}

std::size_t stepColumns(std::string_view text, std::size_t i, std::size_t end, std::uint32_t& col,
                        std::uint32_t untilCol, std::size_t untilByte) {
  constexpr std::uint64_t kHighBits = 0x8080808080808080ull;
  while (i < end && col < untilCol && i < untilByte) {
    // Mostly ASCII: eight characters at a time.
    std::uint64_t word;
    if (i + 8 <= end && i + 8 <= untilByte && untilCol - col >= 8 &&
        (std::memcpy(&word, text.data() + i, 8), (word & kHighBits) == 0)) {
      i += 8;
      col += 8;
      continue;
    }
    i += std::max<std::size_t>(utf8SequenceLength(text, i), 1);
    ++col;
  }
  return i;
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
