#include "compiler/program/line_reader.h"

#include "RobotProgramParser.h"

namespace rs::compiler {

LineReader::LineReader(const diag::SourceFile& source, diag::Diagnostics& diagnostics)
    : lexer_(source, diagnostics) {
  words_.reserve(kMaxLineWords);
}

bool LineReader::next(std::span<const RawToken>& words) {
  if (ended_) return false;
  words_.clear();
  for (;;) {
    const RawToken t = lexer_.scan();
    if (t.type == rs_grammar::RobotProgramParser::NEWLINE) break;
    if (t.type == antlr4::Token::EOF) {
      ended_ = true;
      break;
    }
    words_.push_back(t);
  }
  words = words_;
  return true;
}

}  // namespace rs::compiler
