// The hand-written lexer: produces exactly the token types of
// grammar/RobotProgram.g4, so the generated parser runs on it unchanged. It
// exists for speed (no UTF-32 input stream, no lexer ATN, no allocation per
// token) and for messages: a stray character becomes a diagnostic with its
// position instead of an ANTLR token-recognition error.
#pragma once

#include <antlr4-runtime.h>

#include <deque>
#include <memory>
#include <string>

#include "compiler/diagnostics.h"
#include "compiler/source.h"

namespace rs::compiler {

/// One token as the lexer sees it: a type from the grammar and a span.
struct RawToken {
  size_t type = 0;
  std::size_t begin = 0;  // byte offsets into the source, end exclusive
  std::size_t end = 0;
  Pos pos;
};

class Lexer final : public antlr4::TokenSource {
 public:
  /// The source must be valid UTF-8 (see findInvalidUtf8) and outlive the lexer.
  Lexer(const SourceFile& source, Diagnostics& diagnostics);

  /// The next token; EOF (again and again) at the end.
  RawToken scan();

  // antlr4::TokenSource, for ANTLR tools that pull tokens one at a time.
  std::unique_ptr<antlr4::Token> nextToken() override;
  size_t getLine() const override { return line_; }
  size_t getCharPositionInLine() override { return col_ - 1; }
  antlr4::CharStream* getInputStream() override { return nullptr; }
  std::string getSourceName() override { return source_.name(); }
  antlr4::TokenFactory<antlr4::CommonToken>* getTokenFactory() override;

  /// Fills `token` (a fresh CommonToken) from a raw token.
  void fill(antlr4::CommonToken& token, const RawToken& raw, size_t index);

 private:
  void skipBlanksAndComments();
  void badCharacter();

  const SourceFile& source_;
  Diagnostics& diagnostics_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t col_ = 1;
};

/// The whole file lexed up front into one contiguous store, served to the
/// parser through ANTLR's TokenStream interface: no per-token allocation,
/// no buffering logic on every consume().
class TokenArray final : public antlr4::TokenStream {
 public:
  explicit TokenArray(Lexer& lexer);

  antlr4::Token* LT(ssize_t k) override;
  antlr4::Token* get(size_t index) const override;
  antlr4::TokenSource* getTokenSource() const override { return &lexer_; }
  std::string getText(const antlr4::misc::Interval& interval) override;
  std::string getText() override;
  std::string getText(antlr4::RuleContext* ctx) override;
  std::string getText(antlr4::Token* start, antlr4::Token* stop) override;
  void consume() override;
  size_t LA(ssize_t i) override;
  ssize_t mark() override { return 0; }
  void release(ssize_t) override {}
  size_t index() override { return p_; }
  void seek(size_t index) override { p_ = std::min(index, tokens_.size() - 1); }
  size_t size() override { return tokens_.size(); }
  std::string getSourceName() const override { return lexer_.getSourceName(); }

 private:
  Lexer& lexer_;
  std::deque<antlr4::CommonToken> tokens_;  // deque: stable addresses
  size_t p_ = 0;
};

/// Token type name as the grammar spells it ("IDENT", "NUMBER", ...).
std::string_view tokenTypeName(size_t type);

}  // namespace rs::compiler
