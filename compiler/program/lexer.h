// The hand-written lexer: produces exactly the token types of
// grammar/RobotProgram.g4, so the generated parser runs on it unchanged. It
// exists for speed (no UTF-32 input stream, no lexer ATN, no allocation per
// token) and for messages: a stray character becomes a diagnostic with its
// position instead of an ANTLR token-recognition error.
#pragma once

#include <antlr4-runtime.h>

#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "diag/source_file.h"

namespace rs::compiler {

/// One token as the lexer sees it: a type from the grammar and a span.
struct RawToken {
  size_t type = 0;
  std::size_t begin = 0;  // byte offsets into the source, end exclusive
  std::size_t end = 0;
  diag::Pos pos;
};

/// A token as the parser sees it: 32 bytes, no copy of its text (getText()
/// reads the source), so a line's tokens fit in a cache line or two.
class SourceToken final : public antlr4::Token {
 public:
  SourceToken(std::string_view source, const RawToken& raw, size_t index)
      : source_(source.data()), begin_(static_cast<std::uint32_t>(raw.begin)),
        end_(static_cast<std::uint32_t>(raw.end)), line_(raw.pos.line), col_(raw.pos.col),
        index_(static_cast<std::uint32_t>(index)), type_(static_cast<std::uint32_t>(raw.type)) {}

  std::string getText() const override;
  size_t getType() const override { return type_ == kEof ? antlr4::Token::EOF : type_; }
  size_t getLine() const override { return line_; }
  size_t getCharPositionInLine() const override { return col_ - 1; }
  size_t getChannel() const override { return antlr4::Token::DEFAULT_CHANNEL; }
  size_t getTokenIndex() const override { return index_; }
  size_t getStartIndex() const override { return begin_; }
  size_t getStopIndex() const override { return end_ - 1; }
  antlr4::TokenSource* getTokenSource() const override { return nullptr; }
  antlr4::CharStream* getInputStream() const override { return nullptr; }
  std::string toString() const override;

 private:
  static constexpr std::uint32_t kEof = 0xFFFFFFFF;  // antlr4::Token::EOF, narrowed
  const char* source_;
  std::uint32_t begin_, end_, line_, col_, index_, type_;
};

/// Words (tokens other than NEWLINE) a line may have: a label, an
/// instruction and one value for each of at most 26 motors need 29. The
/// lexer reports the first word beyond and skips the rest of the line, so
/// a line of a million words costs one error and no parse tree of a
/// million nodes.
inline constexpr std::uint32_t kMaxLineWords = 64;

class Lexer final : public antlr4::TokenSource {
 public:
  /// The source must be valid UTF-8 (see findInvalidUtf8) and outlive the lexer.
  Lexer(const diag::SourceFile& source, diag::Diagnostics& diagnostics);

  /// The next token; EOF (again and again) at the end.
  RawToken scan();

  // antlr4::TokenSource, for ANTLR tools that pull tokens one at a time.
  std::unique_ptr<antlr4::Token> nextToken() override;
  size_t getLine() const override { return line_; }
  size_t getCharPositionInLine() override { return col_ - 1; }
  antlr4::CharStream* getInputStream() override { return nullptr; }
  std::string getSourceName() override { return source_.name(); }
  antlr4::TokenFactory<antlr4::CommonToken>* getTokenFactory() override;


 private:
  void skipBlanksAndComments();
  void badCharacter();
  void skipRestOfLine();

  const diag::SourceFile& source_;
  diag::Diagnostics& diagnostics_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t col_ = 1;
  std::uint32_t lineWords_ = 0;  // words of the current line so far
  size_t pulled_ = 0;  // tokens handed out by nextToken()
};

/// The lexer's tokens served to the parser through ANTLR's TokenStream
/// interface, from one contiguous store holding every token of the file
/// (for a parse tree of the whole program: `robotsim ast --tree`): no
/// per-token allocation, no buffering logic on every consume(). The
/// compiler itself reads the lexer's words without the parser
/// (LineReader, line_reader.h).
class TokenArray final : public antlr4::TokenStream {
 public:
  TokenArray(Lexer& lexer, std::string_view source);

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
  void seek(size_t index) override;
  size_t size() override { return tokens_.size(); }
  std::string getSourceName() const override { return lexer_.getSourceName(); }

 private:
  Lexer& lexer_;
  std::string_view source_;
  std::vector<SourceToken> tokens_;  // filled once: never reallocated while the parser holds pointers
  size_t p_ = 0;                     // current token
};

/// Token type name as the grammar spells it ("IDENT", "NUMBER", ...).
std::string_view tokenTypeName(size_t type);

}  // namespace rs::compiler
