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

/// Another place a diagnostic concerns (the first definition of a name
/// defined twice): printed after it as a note, shown by editors beside it.
struct Related {
  std::string file;
  Pos pos;
  std::string message;
  bool operator==(const Related&) const = default;
};

struct Diagnostic {
  std::string file;
  Pos pos;  ///< line 0: the whole file (or a command-line option)
  Severity severity = Severity::Error;
  std::string message;  ///< a sentence without the position
  /// Stable, for tools and editors: which check found it ("undefined-label"),
  /// the same across releases and wordings.
  std::string_view code = {};
  /// How to get past it, when the tool knows ("allow more with
  /// --max-steps N"); printed on its own line after the source line.
  std::string hint = {};
  /// Other places it concerns, each with why.
  std::vector<Related> related = {};
};

std::string_view severityName(Severity s);

/// True when any of them is an error (warnings do not count).
bool hasErrors(std::span<const Diagnostic> diagnostics);

/// Diagnostics left out (not kept, or not shown), by severity; notes count
/// as warnings.
struct Omitted {
  std::size_t errors = 0;
  std::size_t warnings = 0;
  bool any() const { return errors + warnings > 0; }
  void count(Severity s) { ++(s == Severity::Error ? errors : warnings); }
  Omitted& operator+=(const Omitted& o) {
    errors += o.errors;
    warnings += o.warnings;
    return *this;
  }
};

/// A diagnostic's hint, for Diagnostics::error and warning.
struct Hint {
  std::string text;
};

/// The collector every reader reports to. With a limit (`keep` > 0) it
/// keeps only the first `keep` diagnostics by position, those sorted()
/// would list first, and counts the others (omitted()): a file with a
/// million errors costs a million counts, not a million stored messages.
class Diagnostics {
 public:
  explicit Diagnostics(std::string file, std::size_t keep = 0) : file_(std::move(file)), keep_(keep) {}
  /// `code`: the stable name of the check (Diagnostic::code); `related`:
  /// other places it concerns, in this collector's file.
  void error(Pos pos, std::string message, std::string_view code = {}, std::vector<Related> related = {}) {
    add(pos, Severity::Error, std::move(message), code, std::move(related));
  }
  void warning(Pos pos, std::string message, std::string_view code = {}, std::vector<Related> related = {}) {
    add(pos, Severity::Warning, std::move(message), code, std::move(related));
  }
  /// With a hint: how to get past it, when the reader knows ("did you mean
  /// 'PICK'?"). A type of its own, so a hint is never taken for a code.
  void error(Pos pos, std::string message, Hint hint, std::string_view code = {}) {
    add(pos, Severity::Error, std::move(message), code, {}, std::move(hint.text));
  }
  void warning(Pos pos, std::string message, Hint hint, std::string_view code = {}) {
    add(pos, Severity::Warning, std::move(message), code, {}, std::move(hint.text));
  }
  void add(Pos pos, Severity s, std::string message, std::string_view code = {}, std::vector<Related> related = {},
           std::string hint = {});
  /// A related place in this collector's file.
  Related relatedAt(Pos pos, std::string message) const { return {file_, pos, std::move(message)}; }

  /// Counts every error reported, kept or not.
  bool hasErrors() const { return errors_ > 0; }
  std::size_t errorCount() const { return errors_; }
  /// Those kept: in the order reported when there is no limit.
  const std::vector<Diagnostic>& all() const { return list_; }
  /// Those kept, sorted by position (stable), the order they are printed in.
  std::vector<Diagnostic> sorted() const;
  /// Those not kept (none without a limit).
  Omitted omitted() const { return omitted_; }

 private:
  // With a limit: a max-heap of the kept ones' keys, the last by position
  // (then by order reported) on top, each naming its slot in list_.
  struct Key {
    Pos pos;
    std::size_t seq = 0;
    std::size_t slot = 0;
  };
  Diagnostic make(Pos pos, Severity s, std::string message, std::string_view code, std::vector<Related> related,
                  std::string hint) const;
  static bool before(const Key& a, const Key& b) {
    if (a.pos.line != b.pos.line) return a.pos.line < b.pos.line;
    return a.pos.col != b.pos.col ? a.pos.col < b.pos.col : a.seq < b.seq;
  }

  std::string file_;
  std::size_t keep_ = 0;
  std::vector<Diagnostic> list_;
  std::vector<Key> heap_;  // with a limit only
  std::size_t reported_ = 0;
  std::size_t errors_ = 0;
  Omitted omitted_;
};

/// A source line made safe to print, cut to a window of at most 100
/// columns around the caret (`…` where it is cut), and the blanks (spaces,
/// or tabs where the line has them) that put a caret under that column. Its
/// cost is that of the window, however long the line.
struct DisplayLine {
  std::string text;
  std::string caretIndent;
};
DisplayLine displayLine(const SourceFile& source, Pos pos);

/// `text` quoted in a message: as it is when short, else its first `max`
/// characters and `…`, so that a 10 MB word does not make a 10 MB message
/// (64: the longest name a program may use is quoted whole).
std::string excerpt(std::string_view text, std::size_t max = 64);

/// "file:line:col: error: message", then the source line and a caret under
/// the column when the source is known, the hint, and each related place as
/// a "file:line:col: note: message" line.
std::string render(const Diagnostic& d, const SourceFile* source);

}  // namespace rs::diag
