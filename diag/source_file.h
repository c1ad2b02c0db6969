// A source file held in memory: its name, its bytes, where each line starts.
// Every AST node and diagnostic points into one of these by line and column.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/packed_numbers.h"
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
  /// A leading byte-order mark is dropped (withoutByteOrderMark). Text past
  /// 4 GiB is dropped too: no reader accepts a file of that size.
  SourceFile(std::string name, std::string text);

  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }
  std::uint32_t lineCount() const { return static_cast<std::uint32_t>(lineStarts_.size()); }
  /// The text of a line (1-based), without its line break. Constant time
  /// (at most 16 steps), whatever the line's length.
  std::string_view line(std::uint32_t number) const;
  LoneCarriageReturn findLoneCarriageReturn() const;
  /// The byte offset in text() of column `pos.col` of line `pos.line`
  /// (columns count characters; a byte that is not UTF-8 counts as one), or
  /// of the line's end when the line is shorter (the text's end when there
  /// is no such line). Reads at most a few KiB,
  /// however long the line: long lines keep checkpoints (below).
  std::size_t offsetOf(Pos pos) const;

 private:
  // Every kCheckpointBytes of a line longer than that: where a character
  // starts and its column, so that offsetOf never counts columns from the
  // start of a 10 MB line.
  struct Checkpoint {
    std::size_t offset = 0;
    std::uint32_t line = 0;
    std::uint32_t col = 0;
  };
  static constexpr std::size_t kCheckpointBytes = 4096;

  std::string name_;
  std::string text_;
  void addCheckpoints(std::uint32_t line);

  // Packed (base/packed_numbers.h): about a byte a line where 4-byte
  // offsets were 4 (the index was a compile's third-largest holding, after
  // the source and the image); a line is found in at most 16 steps. Every
  // reader refuses files far below 4 GiB (256 MiB at most).
  base::RisingNumbers lineStarts_;
  std::vector<Checkpoint> checkpoints_;  // sorted by offset, hence by (line, col)
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

/// Steps over whole characters of `text` from byte `i` (a character's
/// start), counting one column each (a byte that is not UTF-8 is one
/// character), and stops at `end`, once `col` reaches `untilCol`, or at the
/// first character that starts at or after `untilByte`: the byte reached.
std::size_t stepColumns(std::string_view text, std::size_t i, std::size_t end, std::uint32_t& col,
                        std::uint32_t untilCol, std::size_t untilByte);

}  // namespace rs::diag
