#include "compiler/parse_tree.h"

#include <fmt/format.h>

#include "RobotProgramParser.h"
#include "compiler/lexer.h"

namespace rs::compiler {

using P = rs_grammar::RobotProgramParser;

// Turns an ANTLR syntax error into a diagnostic (see the constructor for
// why there should never be one).
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

namespace {

// The grammar accepts any sequence of words on a line, so the recovery
// bookkeeping ANTLR's default strategy does before every loop iteration
// (sync() copies an IntervalSet each time: 16% of a compile) can never
// pay off. Errors, should one ever occur, are still reported and
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
      tokens_(std::make_unique<TokenArray>(*lexer_, source.text(), TokenArray::Mode::WholeFile)),
      parser_(std::make_unique<RobotProgramParser>(tokens_.get())) {
  const std::size_t errorsBefore = diagnostics.errorCount();
  SyntaxErrors listener(diagnostics);
  configure(*parser_, listener);
  root_ = parser_->program();
  recovered_ = diagnostics.errorCount() > errorsBefore;
  parser_->removeErrorListeners();
}

ParseTree::~ParseTree() = default;

LineParser::LineParser(const diag::SourceFile& source, diag::Diagnostics& diagnostics)
    : diagnostics_(diagnostics),
      lexer_(std::make_unique<Lexer>(source, diagnostics)),
      tokens_(std::make_unique<TokenArray>(*lexer_, source.text(), TokenArray::Mode::OneLine)),
      listener_(std::make_unique<SyntaxErrors>(diagnostics)),
      parser_(std::make_unique<RobotProgramParser>(tokens_.get())) {
  configure(*parser_, *listener_);
}

LineParser::~LineParser() = default;

antlr4::ParserRuleContext* LineParser::next() {
  for (;;) {
    parser_->getTreeTracker().reset();  // the previous line's tree
    // `line` stops before its NEWLINE or EOF (the lexer makes no other
    // token the rule does not take).
    if (started_ && !tokens_->nextLine()) return nullptr;
    started_ = true;
    const std::size_t errorsBefore = diagnostics_.errorCount();
    try {
      antlr4::ParserRuleContext* line = parser_->line();
      recovered_ = diagnostics_.errorCount() > errorsBefore;
      return line;
    } catch (const antlr4::IllegalStateException&) {
      // Error recovery tried to go past the line's end (the error itself
      // was reported): the line is dropped, and parsing goes on.
      if (diagnostics_.errorCount() == errorsBefore) {
        const antlr4::Token* t = tokens_->LT(1);
        diagnostics_.error({static_cast<std::uint32_t>(t->getLine()),
                            static_cast<std::uint32_t>(t->getCharPositionInLine() + 1)},
                           "syntax error: this line cannot be parsed", "syntax");
      }
    }
  }
}

std::string ParseTree::toStringTree() {
  return root_->toStringTree(parser_.get());
}

}  // namespace rs::compiler
