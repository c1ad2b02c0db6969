#include "compiler/program/lexer.h"

#include <fmt/format.h>

#include "RobotProgramParser.h"

namespace rs::compiler {

using P = rs_grammar::RobotProgramParser;

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isIdentPart(char c) { return isIdentStart(c) || isDigit(c); }

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

Lexer::Lexer(const diag::SourceFile& source, diag::Diagnostics& diagnostics)
    : source_(source), diagnostics_(diagnostics), text_(source.text()) {}

antlr4::TokenFactory<antlr4::CommonToken>* Lexer::getTokenFactory() {
  return antlr4::CommonTokenFactory::DEFAULT.get();
}

std::unique_ptr<antlr4::Token> Lexer::nextToken() {
  return std::make_unique<SourceToken>(text_, scan(), pulled_++);
}

void Lexer::skipBlanksAndComments() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t') {
      ++pos_, ++col_;
    } else if (c == ';') {
      // Comments may hold any UTF-8: columns count characters, not bytes.
      // A lone CR is blank space (see below), so only LF or CR LF end a comment.
      for (; pos_ < text_.size() && text_[pos_] != '\n' &&
             !(text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n');
           ++pos_)
        if ((static_cast<unsigned char>(text_[pos_]) & 0xC0) != 0x80) ++col_;
    } else if (c == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n')) {
      ++pos_, ++col_;  // a lone CR is blank space, not a line break
    } else {
      return;
    }
  }
}

void Lexer::badCharacter() {
  const auto c = static_cast<unsigned char>(text_[pos_]);
  const std::size_t n = std::max<std::size_t>(diag::utf8SequenceLength(text_, pos_), 1);  // the source is valid UTF-8
  std::string shown = (c >= 0x20 && c < 0x7F) || c >= 0x80 ? fmt::format("'{}'", text_.substr(pos_, n))
                                                           : fmt::format("U+{:04X}", static_cast<unsigned>(c));
  if ((c == '+' || c == '-') && !(pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1])))
    diagnostics_.error({line_, col_}, fmt::format("a sign must be followed by digits, found {}", shown),
                       "bad-character");
  else if (c == '!' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '=')
    diagnostics_.error({line_, col_}, fmt::format("unexpected character {}", shown),
                       diag::Hint{"JMPVAR compares with <, > or =; there is no not-equal: jump with = past the "
                                  "instructions for the other case"},
                       "bad-character");
  else
    diagnostics_.error({line_, col_}, fmt::format("unexpected character {}", shown), "bad-character");
  pos_ += n;
  ++col_;
}

void Lexer::skipRestOfLine() {
  diagnostics_.error({line_, col_},
                     fmt::format("more than {} words on one line: the rest of the line is skipped", kMaxLineWords),
                     "line-too-long");
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos)
    end = text_.size();
  else if (end > pos_ && text_[end - 1] == '\r')
    --end;  // the NEWLINE token is "\r\n"
  for (; pos_ < end; ++pos_)
    if ((static_cast<unsigned char>(text_[pos_]) & 0xC0) != 0x80) ++col_;
}

RawToken Lexer::scan() {
  for (;;) {
    skipBlanksAndComments();
    RawToken t;
    t.begin = pos_;
    t.pos = {line_, col_};
    if (pos_ >= text_.size()) {
      t.type = antlr4::Token::EOF;
      t.end = pos_;
      return t;
    }
    const char c = text_[pos_];
    if (c == '\n' || c == '\r') {
      pos_ += c == '\r' ? 2 : 1;  // "\r\n" (a lone '\r' was skipped as blank)
      t.type = P::NEWLINE;
      t.end = pos_;
      ++line_;
      col_ = 1;
      lineWords_ = 0;
      return t;
    }
    const bool word = isIdentStart(c) || isDigit(c) || c == '<' || c == '>' || c == '=' || c == ':' ||
                      ((c == '+' || c == '-') && pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1]));
    if (word && lineWords_ == kMaxLineWords) {
      skipRestOfLine();
      continue;
    }
    lineWords_ += word ? 1 : 0;
    if (isIdentStart(c)) {
      t.type = P::IDENT;
      while (pos_ < text_.size() && isIdentPart(text_[pos_])) ++pos_;
    } else if (isDigit(c) || ((c == '+' || c == '-') && pos_ + 1 < text_.size() && isDigit(text_[pos_ + 1]))) {
      t.type = P::NUMBER;
      ++pos_;
      while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      if (pos_ + 1 < text_.size() && text_[pos_] == '.' && isDigit(text_[pos_ + 1])) {
        ++pos_;
        while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
      }
    } else if (c == '<' || c == '>' || c == '=') {
      t.type = P::CMP;
      ++pos_;
    } else if (c == ':') {
      t.type = P::COLON;
      ++pos_;
    } else {
      badCharacter();
      continue;
    }
    t.end = pos_;
    col_ += static_cast<std::uint32_t>(pos_ - t.begin);  // tokens are ASCII
    return t;
  }
}

std::string SourceToken::getText() const {
  if (type_ == kEof) return "<EOF>";
  return std::string(source_ + begin_, end_ - begin_);
}

std::string SourceToken::toString() const {
  // The shape of antlr4::CommonToken::toString(), for ANTLR's own messages.
  return fmt::format("[@{},{}:{}='{}',<{}>,{}:{}]", index_, begin_, static_cast<long long>(end_) - 1, getText(),
                     static_cast<long long>(getType()), line_, col_ - 1);
}

TokenArray::TokenArray(Lexer& lexer, std::string_view source) : lexer_(lexer), source_(source) {
  tokens_.reserve(source.size() / 4 + 1);
  for (;;) {
    const RawToken raw = lexer_.scan();
    tokens_.emplace_back(source_, raw, tokens_.size());
    if (raw.type == antlr4::Token::EOF) break;
  }
}

antlr4::Token* TokenArray::LT(ssize_t k) {
  if (k == 0) return nullptr;
  const ssize_t i = static_cast<ssize_t>(p_) + (k > 0 ? k - 1 : k);
  if (i < 0) return nullptr;
  return &tokens_[std::min(static_cast<size_t>(i), tokens_.size() - 1)];
}

size_t TokenArray::LA(ssize_t i) {
  if (i == 1) return tokens_[p_].getType();  // the parser asks this before every word
  const antlr4::Token* t = LT(i);
  return t ? t->getType() : antlr4::Token::INVALID_TYPE;
}

antlr4::Token* TokenArray::get(size_t index) const {
  if (index >= tokens_.size()) throw antlr4::IndexOutOfBoundsException("token index out of range");
  return const_cast<SourceToken*>(&tokens_[index]);
}

void TokenArray::seek(size_t index) { p_ = std::min(index, tokens_.size() - 1); }

void TokenArray::consume() {
  if (tokens_[p_].getType() == antlr4::Token::EOF) throw antlr4::IllegalStateException("cannot consume EOF");
  ++p_;
}

std::string TokenArray::getText(const antlr4::misc::Interval& interval) {
  std::string out;
  if (interval.a < 0 || interval.b < 0) return out;
  const auto first = static_cast<size_t>(interval.a);
  const auto last = std::min(static_cast<size_t>(interval.b), size() - 1);
  for (auto i = first; i <= last; ++i)
    if (tokens_[i].getType() != antlr4::Token::EOF) out += tokens_[i].getText();
  return out;
}

std::string TokenArray::getText() { return getText(antlr4::misc::Interval(size_t{0}, size() - 1)); }

std::string TokenArray::getText(antlr4::RuleContext* ctx) { return getText(ctx->getSourceInterval()); }

std::string TokenArray::getText(antlr4::Token* start, antlr4::Token* stop) {
  if (!start || !stop) return {};
  return getText(antlr4::misc::Interval(start->getTokenIndex(), stop->getTokenIndex()));
}

}  // namespace rs::compiler
