// The one diagnostic type of robotsim: every reader (programs, descriptions,
// stimuli files, images, serial settings, later test files and editor
// messages) reports with it, at the position it knows. Collected, never
// thrown, so one run reports everything it finds.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "diag/source_file.h"

namespace rs::diag {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  std::string file;
  Pos pos;  ///< line 0: the whole file (or a command-line option)
  Severity severity = Severity::Error;
  std::string message;  ///< a sentence without the position
  /// Stable, for tools and editors: which check found it ("undefined-label"),
  /// the same across releases and wordings.
  std::string_view code = {};
};

std::string_view severityName(Severity s);

/// True when any of them is an error (warnings do not count).
bool hasErrors(std::span<const Diagnostic> diagnostics);

class Diagnostics {
 public:
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}
  void error(Pos pos, std::string message) { add(pos, Severity::Error, std::move(message)); }
  void warning(Pos pos, std::string message) { add(pos, Severity::Warning, std::move(message)); }
  void add(Pos pos, Severity s, std::string message);

  bool hasErrors() const { return errors_ > 0; }
  std::size_t errorCount() const { return errors_; }
  const std::vector<Diagnostic>& all() const { return list_; }
  /// Sorted by position (stable), the order they are printed in.
  std::vector<Diagnostic> sorted() const;

 private:
  std::string file_;
  std::vector<Diagnostic> list_;
  std::size_t errors_ = 0;
};

/// A source line made safe to print, cut to a window around the caret
/// column, and the blanks (spaces, or tabs where the line has them) that
/// put a caret under that column.
struct DisplayLine {
  std::string text;
  std::string caretIndent;
};
DisplayLine displayLine(std::string_view line, std::uint32_t caretCol);

/// "file:line:col: error: message", then the source line and a caret under
/// the column when the source is known.
std::string render(const Diagnostic& d, const SourceFile* source);

}  // namespace rs::diag
