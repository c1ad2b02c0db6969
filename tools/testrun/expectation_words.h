// The words of a `; expect:`, `; test:` or scenario line, each with its
// column, and the reader expectation.cpp's grammar takes them from: the
// first problem is the line's error, at the word that caused it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "vm/machine.h"

namespace rs::testrun::words {

struct Word {
  std::string_view text;
  std::uint32_t col = 0;
};

inline bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// The column of byte `offset`: columns count characters (UTF-8
/// sequences), as the compiler's do.
std::uint32_t columnOf(std::string_view line, std::size_t offset);

/// The words of `line` from byte `from` on, each with its column, in one
/// pass over the line.
std::vector<Word> wordsOf(std::string_view line, std::size_t from);

/// `w` is `keyword`, in any case.
bool is(const Word& w, std::string_view keyword);

class LineReader {
 public:
  LineReader(std::vector<Word> words, std::uint32_t line, std::uint32_t endCol)
      : words_(std::move(words)), line_(line), endCol_(endCol) {}

  bool done() const { return next_ >= words_.size(); }
  const Word* peek() const { return done() ? nullptr : &words_[next_]; }
  bool accept(std::string_view keyword);
  /// Takes the words `phrase` is made of when they all come next.
  bool acceptPhrase(std::span<const std::string_view> phrase);
  std::optional<Word> take(std::string_view what);
  bool keyword(std::string_view keyword);
  bool integer(std::string_view what, std::int64_t& v, std::int64_t lo, std::int64_t hi);
  bool real(std::string_view what, double& v);
  bool seconds(std::string_view what, vm::Micros& micros);
  bool onOff(bool& on);
  /// `left.motors`: takes `left` off the next word (whose rest, `motors`,
  /// is then the next word) when it has a dot inside it; nullopt (and
  /// nothing taken) when it has none.
  std::optional<Word> robotPrefix();
  bool end();
  bool fail(std::string message) { return failAt(done() ? endCol_ : words_[next_].col, std::move(message)); }
  bool failAt(std::uint32_t col, std::string message);
  std::optional<diag::Diagnostic>& error() { return error_; }

 private:
  std::vector<Word> words_;
  std::size_t next_ = 0;
  std::uint32_t line_;
  std::uint32_t endCol_;
  std::optional<diag::Diagnostic> error_;
};

}  // namespace rs::testrun::words
