// An open document: its text as the editor has it, kept in step with
// incremental edits, and a line index that converts between the three ways
// of naming a place: LSP positions (0-based line, and a column counted in
// UTF-16 code units, or in bytes when UTF-8 was negotiated), byte offsets,
// and the compiler's diag::Pos (1-based line, column in characters).
//
// Lines end at LF; a CR before it belongs to the line break (a lone CR is
// text, as the compiler reads it).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/source_file.h"

namespace rs::lsp {

enum class Encoding { Utf16, Utf8 };

struct Position {
  std::uint32_t line = 0;
  std::uint32_t character = 0;
  bool operator==(const Position&) const = default;
  auto operator<=>(const Position&) const = default;
};

struct Range {
  Position start, end;
  bool operator==(const Range&) const = default;
};

/// What a file is, from its language id or its name.
enum class Language { Program, Description, Stimuli, Urdf, Other };
Language languageOf(std::string_view languageId, std::string_view uri);

class Document {
 public:
  Document(std::string uri, Language language, std::int64_t version, std::string text);

  const std::string& uri() const { return uri_; }
  Language language() const { return language_; }
  std::int64_t version() const { return version_; }
  const std::string& text() const { return text_; }
  /// Counts every change: analyses remember the revision they were made for.
  std::uint64_t revision() const { return revision_; }
  /// Set when the editor sent bytes that were not UTF-8 (each became U+FFFD).
  bool hadInvalidUtf8() const { return invalidUtf8_; }
  void setHadInvalidUtf8(bool bad) { invalidUtf8_ = bad; }

  /// Replaces `range` (or, without one, the whole text) with `text`.
  void edit(const std::optional<Range>& range, std::string_view text, Encoding enc);
  void setVersion(std::int64_t version) { version_ = version; }

  std::uint32_t lineCount() const { return static_cast<std::uint32_t>(lineStarts_.size()); }
  /// Line `i` (0-based) without its line break; empty past the end.
  std::string_view line(std::uint32_t i) const;
  std::size_t lineStart(std::uint32_t i) const;

  /// The byte offset of a position, clamped to its line and the text.
  std::size_t offsetOf(Position p, Encoding enc) const;
  Position positionOf(std::size_t offset, Encoding enc) const;
  /// A compiler position (line 0: the start of the file).
  Position fromPos(diag::Pos pos, Encoding enc) const;
  diag::Pos toPos(Position p, Encoding enc) const;
  /// The range of `length` bytes from a compiler position.
  Range rangeOf(diag::Pos pos, std::size_t length, Encoding enc) const;
  /// The range of the word (a run of characters other than blanks and ';')
  /// starting at `pos`: what a diagnostic there underlines (at least one
  /// character when the line has one).
  Range wordAt(diag::Pos pos, Encoding enc) const;

 private:
  void index();

  std::string uri_;
  Language language_;
  std::int64_t version_ = 0;
  std::string text_;
  std::vector<std::size_t> lineStarts_;
  std::uint64_t revision_ = 0;
  bool invalidUtf8_ = false;
};

/// The range a diagnostic at column `col` (1-based, in characters) of line
/// `lineIndex` (0-based) underlines: the word there (a run of characters
/// other than blanks and ';'), at least one character when the line has
/// one. `line` is the line as the compiler read it; `lead` counts the units
/// before it that the compiler does not see (a byte-order mark).
Range wordRange(std::string_view line, std::uint32_t lineIndex, std::uint32_t col, std::uint32_t lead, Encoding enc);

/// Column units of `text` (a piece of one line) in the encoding.
std::uint32_t unitsOf(std::string_view text, Encoding enc);
/// Bytes of `line` that `units` columns cover (clamped; never inside a character).
std::size_t bytesFor(std::string_view line, std::uint32_t units, Encoding enc);

}  // namespace rs::lsp
