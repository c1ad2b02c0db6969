#include "compiler/lexer.h"

#include <fmt/format.h>

#include "RobotProgramParser.h"

namespace rs::compiler {

using P = rs_grammar::RobotProgramParser;

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isIdentPart(char c) { return isIdentStart(c) || isDigit(c); }

std::size_t utf8Length(unsigned char lead) {
  if (lead < 0x80) return 1;
  if ((lead & 0xE0) == 0xC0) return 2;
  if ((lead & 0xF0) == 0xE0) return 3;
  return 4;
}

}  // namespace

std::string_view tokenTypeName(size_t type) {
  switch (type) {
    case P::IDENT: return "IDENT";
    case P::NUMBER: return "NUMBER";
    case P::CMP: return "CMP";
    case P::COLON: return "COLON";
    case P::NEWLINE: return "NEWLINE";
    case antlr4::Token::EOF: return "EOF";
    default: return "?";
  }
}

Lexer::Lexer(const SourceFile& source, Diagnostics& diagnostics)
    : source_(source), diagnostics_(diagnostics), text_(source.text()) {}

antlr4::TokenFactory<antlr4::CommonToken>* Lexer::getTokenFactory() {
  return antlr4::CommonTokenFactory::DEFAULT.get();
}

std::unique_ptr<antlr4::Token> Lexer::make(size_t type, std::size_t begin, std::uint32_t col) {
  auto token = std::make_unique<antlr4::CommonToken>(std::make_pair(this, nullptr), type,
                                                     antlr4::Token::DEFAULT_CHANNEL, begin, pos_ - 1);
  token->setText(type == antlr4::Token::EOF ? std::string("<EOF>") : std::string(text_.substr(begin, pos_ - begin)));
  token->setLine(line_);
  token->setCharPositionInLine(col - 1);
  return token;
}

void Lexer::skipBlanksAndComments() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t') {
      ++pos_, ++col_;
    } else if (c == ';') {
      while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
    } else if (c == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n')) {
      ++pos_, ++col_;  // a lone CR is blank space, not a line break
    } else {
      return;
    }
  }
}

void Lexer::badCharacter() {
  const auto c = static_cast<unsigned char>(text_[pos_]);
  const std::size_t n = std::min(utf8Length(c), text_.size() - pos_);
  std::string shown = (c >= 0x20 && c < 0x7F) || c >= 0x80 ? fmt::format("'{}'", text_.substr(pos_, n))
                                                           : fmt::format("U+{:04X}", static_cast<unsigned>(c));
  if ((c == '+' || c == '-') && !(pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1])))
    diagnostics_.error({line_, col_}, fmt::format("a sign must be followed by digits, found {}", shown));
  else
    diagnostics_.error({line_, col_}, fmt::format("unexpected character {}", shown));
  pos_ += n;
  ++col_;
}

std::unique_ptr<antlr4::Token> Lexer::nextToken() {
  for (;;) {
    skipBlanksAndComments();
    const std::size_t begin = pos_;
    const std::uint32_t col = col_;
    if (pos_ >= text_.size()) return make(antlr4::Token::EOF, begin, col);
    const char c = text_[pos_];
    if (c == '\n' || c == '\r') {
      pos_ += c == '\r' ? 2 : 1;  // "\r\n" (a lone '\r' was skipped as blank)
      auto token = make(P::NEWLINE, begin, col);
      ++line_;
      col_ = 1;
      return token;
    }
    if (isIdentStart(c)) {
      while (pos_ < text_.size() && isIdentPart(text_[pos_])) ++pos_;
    } else if (isDigit(c) || ((c == '+' || c == '-') && pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1]))) {
      ++pos_;
      while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      if (pos_ + 1 < text_.size() && text_[pos_] == '.' && isDigit(text_[pos_ + 1])) {
        ++pos_;
        while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      }
      col_ += static_cast<std::uint32_t>(pos_ - begin);
      return make(P::NUMBER, begin, col);
    } else if (c == '<' || c == '>' || c == '=') {
      ++pos_;
    } else if (c == ':') {
      ++pos_;
      col_ += 1;
      return make(P::COLON, begin, col);
    } else {
      badCharacter();
      continue;
    }
    col_ += static_cast<std::uint32_t>(pos_ - begin);
    return make(isIdentStart(c) ? P::IDENT : P::CMP, begin, col);
  }
}

}  // namespace rs::compiler
