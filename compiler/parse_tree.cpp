#include "compiler/parse_tree.h"

#include <fmt/format.h>

#include "RobotProgramParser.h"
#include "compiler/lexer.h"

namespace rs::compiler {

namespace {

using P = rs_grammar::RobotProgramParser;

// Turns ANTLR's syntax errors into our diagnostics, in our words: the
// grammar is so flat that "unexpected X" plus a hint says all there is.
class SyntaxErrors final : public antlr4::BaseErrorListener {
 public:
  explicit SyntaxErrors(Diagnostics& d) : diagnostics_(d) {}
  void syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t line, size_t col, const std::string&,
                   std::exception_ptr) override {
    const Pos pos{static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(col + 1)};
    if (!token) return diagnostics_.error(pos, "syntax error");
    const std::string text = token->getType() == antlr4::Token::EOF ? "end of file"
                             : token->getType() == P::NEWLINE       ? "end of line"
                                                                    : fmt::format("'{}'", token->getText());
    std::string hint;
    if (token->getType() == P::NUMBER || token->getType() == P::CMP)
      hint = ": a line starts with an instruction, a label or a point name";
    else if (token->getType() == P::COLON)
      hint = ": a label is a name followed by ':' at the start of a line";
    diagnostics_.error(pos, fmt::format("unexpected {}{}", text, hint));
  }

 private:
  Diagnostics& diagnostics_;
};

}  // namespace

ParseTree::ParseTree(const SourceFile& source, Diagnostics& diagnostics)
    : source_(source),
      lexer_(std::make_unique<Lexer>(source, diagnostics)),
      tokens_(std::make_unique<TokenArray>(*lexer_)),
      parser_(std::make_unique<P>(tokens_.get())) {
  // Two stages, as ANTLR's authors recommend for speed: first SLL
  // prediction with an error strategy that gives up at the first error (no
  // recovery bookkeeping on every loop); only a file with a syntax error is
  // parsed again with full recovery, so that every error gets reported.
  parser_->removeErrorListeners();
  parser_->setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
  parser_->getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
  try {
    root_ = parser_->program();
    return;
  } catch (const antlr4::ParseCancellationException&) {
  }
  // The token stream keeps every token, so the lexer does not run (or
  // report its errors) a second time.
  recovered_ = true;
  tokens_->seek(0);
  parser_->reset();
  SyntaxErrors listener(diagnostics);
  parser_->addErrorListener(&listener);
  parser_->setErrorHandler(std::make_shared<antlr4::DefaultErrorStrategy>());
  parser_->getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::LL);
  root_ = parser_->program();
  parser_->removeErrorListeners();
}

ParseTree::~ParseTree() = default;

std::string ParseTree::toStringTree() {
  return root_->toStringTree(parser_.get());
}

}  // namespace rs::compiler
