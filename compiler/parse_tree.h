// Runs the generated ANTLR parser over the hand-written lexer and keeps
// everything the resulting parse tree needs alive. Syntax errors become
// diagnostics; the parser recovers and goes on, so one run reports them all.
#pragma once

#include <memory>

#include "compiler/diagnostics.h"
#include "compiler/source.h"

namespace antlr4 {
class ParserRuleContext;
}
namespace rs_grammar {
class RobotProgramParser;
}

namespace rs::compiler {

class Lexer;
class TokenArray;

class ParseTree {
 public:
  /// Parses `source` (valid UTF-8); errors go to `diagnostics`.
  ParseTree(const SourceFile& source, Diagnostics& diagnostics);
  ~ParseTree();
  ParseTree(const ParseTree&) = delete;
  ParseTree& operator=(const ParseTree&) = delete;

  const SourceFile& source() const { return source_; }
  rs_grammar::RobotProgramParser& parser() { return *parser_; }
  /// The root: a RobotProgramParser::ProgramContext.
  antlr4::ParserRuleContext* root() const { return root_; }
  /// True when the parser met syntax errors and recovered (the tree may
  /// then hold error nodes).
  bool recovered() const { return recovered_; }
  /// The tree in LISP form, as ANTLR prints it (for `robotsim ast --tree`).
  std::string toStringTree();

 private:
  const SourceFile& source_;
  std::unique_ptr<Lexer> lexer_;
  std::unique_ptr<TokenArray> tokens_;
  std::unique_ptr<rs_grammar::RobotProgramParser> parser_;
  antlr4::ParserRuleContext* root_ = nullptr;
  bool recovered_ = false;
};

}  // namespace rs::compiler
