// Runs the generated ANTLR parser over the hand-written lexer: the
// grammar's start rule `program`, one tree for the whole file, kept alive
// (for `robotsim ast --tree`, and for teaching). Syntax errors become
// diagnostics; the parser recovers and goes on, so one run reports them
// all. The compiler itself reads a line's words without the parser
// (LineReader, line_reader.h): the `line` rule takes any sequence of them.
#pragma once

#include <memory>

#include "diag/diagnostic.h"
#include "diag/source_file.h"

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
  ParseTree(const diag::SourceFile& source, diag::Diagnostics& diagnostics);
  ~ParseTree();
  ParseTree(const ParseTree&) = delete;
  ParseTree& operator=(const ParseTree&) = delete;

  const diag::SourceFile& source() const { return source_; }
  /// The root: a RobotProgramParser::ProgramContext.
  antlr4::ParserRuleContext* root() const { return root_; }
  /// True when the parser met syntax errors and recovered (the tree may
  /// then hold error nodes).
  bool recovered() const { return recovered_; }
  /// The tree in LISP form, as ANTLR prints it (for `robotsim ast --tree`).
  std::string toStringTree();

 private:
  const diag::SourceFile& source_;
  std::unique_ptr<Lexer> lexer_;
  std::unique_ptr<TokenArray> tokens_;
  std::unique_ptr<rs_grammar::RobotProgramParser> parser_;
  antlr4::ParserRuleContext* root_ = nullptr;
  bool recovered_ = false;
};

}  // namespace rs::compiler
