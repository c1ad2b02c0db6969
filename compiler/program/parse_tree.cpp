#include "compiler/program/parse_tree.h"

#include <fmt/format.h>

#include "RobotProgramParser.h"
#include "compiler/program/lexer.h"

namespace rs::compiler {

namespace {

using P = rs_grammar::RobotProgramParser;

// Turns an ANTLR syntax error into a diagnostic (see configure() for why
// there should never be one).
class SyntaxErrors final : public antlr4::BaseErrorListener {
 public:
  explicit SyntaxErrors(diag::Diagnostics& d) : diagnostics_(d) {}
  void syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t line, size_t col, const std::string&,
                   std::exception_ptr) override {
    const diag::Pos pos{static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(col + 1)};
    diagnostics_.error(
        pos, token ? fmt::format("unexpected '{}'", diag::excerpt(token->getText())) : std::string("syntax error"),
        "syntax");
  }

 private:
  diag::Diagnostics& diagnostics_;
};

// The grammar accepts any sequence of words on a line, so the recovery
// bookkeeping ANTLR's default strategy does before every loop iteration
// (sync() copies an IntervalSet each time) can never pay off. Errors, should one ever occur, are still reported and
// recovered from by the default strategy's other methods.
class NoLoopSync final : public antlr4::DefaultErrorStrategy {
 public:
  void sync(antlr4::Parser*) override {}
};

// The generated parser, with room for a line's words made once: a rule's
// children vector otherwise grows 1, 2, 4, 8, one allocation each.
class RobotProgramParser final : public P {
 public:
  using P::P;
  void enterRule(antlr4::ParserRuleContext* context, size_t state, size_t ruleIndex) override {
    if (ruleIndex == P::RuleLine) context->children.reserve(8);
    P::enterRule(context, state, ruleIndex);
  }
};

// The grammar accepts any sequence of words on a line, so the parser meets
// an error only if the grammar and the lexer ever disagree; the listener
// still turns that into a diagnostic rather than a crash.
void configure(P& parser, SyntaxErrors& listener) {
  parser.removeErrorListeners();
  parser.addErrorListener(&listener);
  parser.setErrorHandler(std::make_shared<NoLoopSync>());
  // SLL prediction: exact for this LL(1) grammar, and the fastest mode.
  parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
}

}  // namespace

ParseTree::ParseTree(const diag::SourceFile& source, diag::Diagnostics& diagnostics)
    : source_(source),
      lexer_(std::make_unique<Lexer>(source, diagnostics)),
      tokens_(std::make_unique<TokenArray>(*lexer_, source.text())),
      parser_(std::make_unique<RobotProgramParser>(tokens_.get())) {
  const std::size_t errorsBefore = diagnostics.errorCount();
  SyntaxErrors listener(diagnostics);
  configure(*parser_, listener);
  root_ = parser_->program();
  recovered_ = diagnostics.errorCount() > errorsBefore;
  parser_->removeErrorListeners();
}

ParseTree::~ParseTree() = default;

std::string ParseTree::toStringTree() {
  return root_->toStringTree(parser_.get());
}

}  // namespace rs::compiler
