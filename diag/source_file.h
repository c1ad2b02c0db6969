// A source file held in memory: its name, its bytes, where each line starts.
// Every AST node and diagnostic points into one of these by line and column.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/text.h"

namespace rs::diag {

/// A position in a source file: 1-based line, 1-based column counted in
/// characters (code points), as editors and GNU-style messages count them.
struct Pos {
  std::uint32_t line = 0;
  std::uint32_t col = 0;
  bool operator==(const Pos&) const = default;
};

/// Text without the UTF-8 byte-order mark some editors (on Windows) put at
/// the start of a file: it is not part of the first line.
constexpr std::string_view withoutByteOrderMark(std::string_view text) {
  constexpr std::string_view kMark = "\xEF\xBB\xBF";
  return text.substr(0, kMark.size()) == kMark ? text.substr(kMark.size()) : text;
}

/// Where the first carriage return that is not followed by a line feed is
/// (old Mac line ends, or a stray one), if any.
struct LoneCarriageReturn {
  bool found = false;
  Pos pos;
};

class SourceFile {
 public:
  /// A leading byte-order mark is dropped (withoutByteOrderMark).
  SourceFile(std::string name, std::string text);

  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }
  std::uint32_t lineCount() const { return static_cast<std::uint32_t>(lineStarts_.size()); }
  /// The text of a line (1-based), without its line break.
  std::string_view line(std::uint32_t number) const;
  LoneCarriageReturn findLoneCarriageReturn() const;

 private:
  std::string name_;
  std::string text_;
  std::vector<std::size_t> lineStarts_;
};

/// The position of the first byte that is not valid UTF-8, if any.
struct Utf8Problem {
  bool found = false;
  Pos pos;
  unsigned char byte = 0;
};
Utf8Problem findInvalidUtf8(std::string_view text);

/// Length of the valid UTF-8 sequence starting at text[i], or 0 (base/text.h).
using base::utf8SequenceLength;

}  // namespace rs::diag
