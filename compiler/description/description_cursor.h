// The word reader of description lines (.rsd): one line's words, read
// left to right by what the statement expects next (a keyword, a number, a
// point, a name, a colour, an axis). Private to the description reader
// (description*.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/description/description.h"
#include "diag/diagnostic.h"

namespace rs::compiler::description_detail {

inline constexpr std::array<std::string_view, 16> kColorNames{
    "BLACK",    "BLUE",      "GREEN",      "CYAN",      "RED",      "MAGENTA",      "BROWN",  "LIGHTGRAY",
    "DARKGRAY", "LIGHTBLUE", "LIGHTGREEN", "LIGHTCYAN", "LIGHTRED", "LIGHTMAGENTA", "YELLOW", "WHITE"};

struct Word {
  size_t type;  // the RobotModelLexer token type
  std::string text;
  diag::Pos pos;
};

// "did you mean 'LINE'?" when `word` is a near miss of one of the
// keywords named in `list` ("LINE, BOX, ROTATE, MOVE, COLOR or END"): the
// suggestion is always a keyword the message itself offers.
std::string didYouMean(std::string_view word, std::string_view list);

// Reads one line's words left to right. Each reader reports what it
// expected at the word it stopped on (or at the end of the line) and
// returns false; the caller then drops the rest of the line, so one slip
// gives one message.
class Cursor {
 public:
  Cursor(const std::vector<Word>& words, diag::Pos lineEnd, diag::Diagnostics& d) : w_(words), end_(lineEnd), diag_(d) {}

  bool atEnd() const { return i_ >= w_.size(); }
  /// Whether no word of the line has been read yet.
  bool atLineStart() const { return i_ == 0; }
  const Word& peek() const { return w_[i_]; }
  diag::Pos pos() const { return atEnd() ? end_ : w_[i_].pos; }

  bool keyword(std::string_view kw);
  /// Whether the next word is the keyword, without taking it.
  bool isKeyword(std::string_view kw) const;
  /// Whether the next word is a name (or a keyword: they are names too).
  bool isName() const;
  /// An error at `at` (a word already read) with a hint; false.
  bool failAt(diag::Pos at, std::string message, std::string hint);
  bool fail(std::string_view what, std::string hint = {});
  /// "expected LINE, BOX, ... or END, found 'LIEN'" with the hint "did you
  /// mean 'LINE'?" when the word found is a near miss of one in the list.
  bool failOneOf(std::string_view keywords);
  bool number(double& out, std::string_view what);
  bool integer(std::int32_t& out, std::string_view what);
  bool point(Point3& out, std::string_view what);
  bool name(NameRef& out, std::string_view what);
  /// A file name: the words written together, with nothing between them
  /// ("../programs/left.rsp" is several words of the lexer).
  bool path(NameRef& out, std::string_view what);
  bool letter(char& out, diag::Pos& at);
  bool onOff(bool& out);
  bool color(workcell::Color& out);
  bool axis(int& out);
  /// The hint of every later error of this line that has none of its own
  /// ("a WIRE line reads WIRE SOURCE TO IN n ..."): the form of the
  /// statement being read, so no mistake in a device line is left without
  /// one. Both views must outlive the cursor (static text).
  void setFormHint(std::string_view keyword, std::string_view form) { formKeyword_ = keyword, form_ = form; }

 private:
  void error(diag::Pos at, std::string message, std::string hint);
  bool exponent(std::string& written, std::string& plain) const;
  static std::string withoutExponent(std::string_view mantissa, int k);

  const std::vector<Word>& w_;
  std::size_t i_ = 0;
  diag::Pos end_;
  diag::Diagnostics& diag_;
  std::string_view formKeyword_, form_;
};

}  // namespace rs::compiler::description_detail
