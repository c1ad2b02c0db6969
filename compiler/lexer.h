// The hand-written lexer: produces exactly the token types of
// grammar/RobotProgram.g4 behind ANTLR's TokenSource interface, so the
// generated parser runs on it unchanged. It exists for speed (no UTF-32
// input stream, no lexer ATN) and for messages: a stray character becomes a
// diagnostic with its position instead of an ANTLR token-recognition error.
#pragma once

#include <antlr4-runtime.h>

#include <memory>
#include <string>

#include "compiler/diagnostics.h"
#include "compiler/source.h"

namespace rs::compiler {

class Lexer final : public antlr4::TokenSource {
 public:
  /// The source must be valid UTF-8 (see findInvalidUtf8) and outlive the lexer.
  Lexer(const SourceFile& source, Diagnostics& diagnostics);

  std::unique_ptr<antlr4::Token> nextToken() override;
  size_t getLine() const override { return line_; }
  size_t getCharPositionInLine() override { return col_ - 1; }
  antlr4::CharStream* getInputStream() override { return nullptr; }
  std::string getSourceName() override { return source_.name(); }
  antlr4::TokenFactory<antlr4::CommonToken>* getTokenFactory() override;

 private:
  std::unique_ptr<antlr4::Token> make(size_t type, std::size_t begin, std::uint32_t col);
  void skipBlanksAndComments();
  void badCharacter();

  const SourceFile& source_;
  Diagnostics& diagnostics_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t col_ = 1;
  bool atEnd_ = false;
};

/// Token type name as the grammar spells it ("IDENT", "NUMBER", ...).
std::string_view tokenTypeName(size_t type);

}  // namespace rs::compiler
