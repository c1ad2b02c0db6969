// The compiler's way through a program: the words of one line at a time,
// straight from the lexer. The grammar's `line` rule
// (grammar/RobotProgram.g4) takes any sequence of the lexer's word tokens,
// so running the generated parser over a line (a rule context and a tree
// node per word, freed at the next line) changes nothing but the time it
// takes: the AST builder reads the words directly. `robotsim ast --tree`
// still parses the whole file with ANTLR (ParseTree, parse_tree.h), and a
// test checks that both give the same AST and the same diagnostics
// (tests/compiler/test_line_parser.cpp). Memory does not grow with the
// file: only the current line's words are held.
#pragma once

#include <span>
#include <vector>

#include "compiler/program/lexer.h"

namespace rs::compiler {

class LineReader {
 public:
  /// Reads `source` (valid UTF-8, outliving the reader); the lexer's
  /// errors go to `diagnostics`.
  LineReader(const diag::SourceFile& source, diag::Diagnostics& diagnostics);

  /// The next line's words (no NEWLINE or EOF), valid until the next call;
  /// false after the last line. Lines are as ANTLR's `program` rule sees
  /// them: a file of N line breaks has N + 1 lines.
  bool next(std::span<const RawToken>& words);

 private:
  Lexer lexer_;
  std::vector<RawToken> words_;
  bool ended_ = false;  // the last line (the one that ends at EOF) was read
};

}  // namespace rs::compiler
