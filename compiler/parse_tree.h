// Runs the generated ANTLR parser over the hand-written lexer. Syntax errors
// become diagnostics; the parser recovers and goes on, so one run reports
// them all. Two drivers:
//  - ParseTree: the grammar's start rule `program`, one tree for the whole
//    file, kept alive (for `robotsim ast --tree`, and for teaching);
//  - LineParser: the rule `line`, one line at a time; each line's tree is
//    freed when the next is parsed, and only that line's tokens are held.
//    The compiler uses it: memory does not grow with the file, and the
//    tree being built is always in cache.
// Both build the same LineContext trees for the same line.
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
class SyntaxErrors;

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

class LineParser {
 public:
  /// Parses `source` (valid UTF-8) line by line; errors go to `diagnostics`.
  LineParser(const diag::SourceFile& source, diag::Diagnostics& diagnostics);
  ~LineParser();
  LineParser(const LineParser&) = delete;
  LineParser& operator=(const LineParser&) = delete;

  /// The next line's parse tree (a RobotProgramParser::LineContext), valid
  /// until the next call; nullptr after the last line.
  antlr4::ParserRuleContext* next();
  /// True when the parser met syntax errors on the line last returned and
  /// recovered (its tree may then hold error nodes).
  bool recovered() const { return recovered_; }

 private:
  diag::Diagnostics& diagnostics_;
  std::unique_ptr<Lexer> lexer_;
  std::unique_ptr<TokenArray> tokens_;
  std::unique_ptr<SyntaxErrors> listener_;
  std::unique_ptr<rs_grammar::RobotProgramParser> parser_;
  bool started_ = false;
  bool recovered_ = false;
};

}  // namespace rs::compiler
