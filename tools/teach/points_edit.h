// Lossless editing of a program's POINTS section. A program is a text file
// a student wrote by hand, with comments, blank lines and columns lined up;
// TEACH must change the taught points and nothing else. So the text is kept
// as its lines, each with its own line end, and an edit rewrites only the
// one row it concerns (or inserts one): every other byte stays.
//
// A new or changed row is laid out like its neighbours: the name where the
// row's (or the last row's) name starts, each value right-aligned to the
// column its neighbours end at (left-aligned where they all start at one
// column and end at different ones), a trailing comment kept at its column;
// a row whose separators hold tabs keeps its separators as they are. When
// a value is too wide for its column, the row grows by one space. Without
// a POINTS line, one is added after the last line, where the language
// wants it (docs/language.md, "File structure").
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rs::teach {

/// A row of the POINTS section as the file spells it.
struct PointRow {
  std::string name;
  std::vector<std::int32_t> values;
  std::size_t line = 0;   ///< 0-based line of the file
  bool readable = true;   ///< false: a value is not a whole number (the compiler reports it)
  bool pose = false;      ///< written as a tool pose: `NAME AT x y z ...` (then not readable as counts)
};

class PointsText {
 public:
  /// Any text: what is not a point row is kept as it is and never touched.
  explicit PointsText(std::string_view text);

  std::string text() const;
  const std::vector<PointRow>& points() const { return points_; }
  /// The row named `name` (any case), as an index into points().
  std::optional<std::size_t> find(std::string_view name) const;
  /// Row `i` of points() as the file spells it, without its line end.
  std::string_view rowText(std::size_t i) const { return lines_[points_[i].line].body; }
  /// 0-based line of the POINTS line, if there is one.
  std::optional<std::size_t> pointsLine() const { return pointsLine_; }

  // Edits. Each returns "" when done, or why not (the text is then unchanged).
  /// A new row after the last point (a POINTS line first, if missing).
  std::string add(std::string_view name, std::span<const std::int32_t> values);
  /// New values for an existing point (a point written as a pose becomes
  /// a row of counts, laid out like the rows of counts).
  std::string replace(std::string_view name, std::span<const std::int32_t> values);
  /// An existing point written as the tool pose `pose` ("AT 240 900 -40
  /// APPROACH 0 -1 0"): its name and comment stay where they are.
  std::string replacePose(std::string_view name, std::string_view pose);
  std::string remove(std::string_view name);
  std::string rename(std::string_view from, std::string_view to);

 private:
  struct Line {
    std::string body;  // without its line end
    std::string end;   // "\n", "\r\n" or "" (the last line, unterminated)
  };
  void reparse();
  std::string lineEnd() const;
  std::string layoutRow(std::string_view name, std::span<const std::int32_t> values,
                        std::optional<std::size_t> templateLine, bool keepComment) const;
  /// The line a new row of counts is laid out after: the last readable row without tabs, else the last row.
  std::optional<std::size_t> countsTemplate() const;
  /// `row` followed by the comment of line `line`, at its column where it fits.
  std::string withComment(std::string row, std::size_t line) const;

  std::vector<Line> lines_;
  std::vector<PointRow> points_;
  std::optional<std::size_t> pointsLine_;
};

/// Why `name` cannot name a new point ("" when it can): the language's
/// name syntax, at most 64 characters (vm::kMaxNameLength), not a reserved
/// word (an instruction, ON, OFF, POINTS).
std::string checkPointName(std::string_view name);

}  // namespace rs::teach
