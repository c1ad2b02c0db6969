// The builder behind buildAst (ast_builder.h), shared by its files: one
// line's tokens split into label, head and operands (ast_builder.cpp),
// an instruction's operands read by its opcode's format
// (ast_operands.cpp), a POINTS row and its tool pose (ast_points.cpp).
// Private to the compiler: only those files include it.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "RobotProgramParser.h"
#include "base/ascii.h"
#include "compiler/program/ast_builder.h"
#include "compiler/program/lexer.h"

namespace rs::compiler::detail {

using P = rs_grammar::RobotProgramParser;

using base::sameName;

inline diag::Pos posOf(const RawToken& t) { return t.pos; }

// The written text of a token: a view into the source, not a copy.
inline std::string_view textOf(const diag::SourceFile& src, const RawToken& t) {
  return std::string_view(src.text()).substr(t.begin, t.end - t.begin);
}

struct Word {  // one operand as written
  size_t type;
  std::string_view text;
  diag::Pos pos;
};

using vm::isReservedWord;
using vm::kMaxNameLength;  // as the image format allows

class Builder {
 public:
  Builder(const diag::SourceFile& src, std::span<const vm::MotorSpec> motors, diag::Diagnostics& d, AstSink& sink)
      : src_(src), motors_(motors), diag_(d), sink_(sink) {}

  /// One line's words, in order (no NEWLINE or EOF).
  void line(std::span<const RawToken> tokens);
  void finish();

 private:
  void instruction(const RawToken& head, const std::vector<Word>& words);
  void point(const RawToken& head, const std::vector<Word>& words);
  bool operands(Instruction& in, std::string_view mnemonic, const std::vector<Word>& w);
  bool looksLikePoint(std::string_view head, const std::vector<Word>& words) const;
  bool pose(PointDef& p, const std::vector<Word>& words);
  bool poseVector(const std::vector<Word>& w, std::size_t& i, std::string_view what, PoseVector& out);
  bool coordinate(const Word& w, std::string_view what, double& out);
  bool delayWithUnit(const std::vector<Word>& w);
  bool twoWordComparison(const std::vector<Word>& w);
  bool checkName(std::string_view what, std::string_view name, diag::Pos pos);

  // Operand readers: each reports what it expected and returns false.
  bool integer(const Word& w, std::string_view what, Value& out);
  /// Every word as an integer (each bad one reported); on any error `out`
  /// is left empty, so later checks skip the operand list.
  bool integers(const std::vector<Word>& words, std::string_view what, std::vector<Value>& out);
  bool seconds(const Word& w, Value& out);
  bool name(const Word& w, std::string_view what, std::string_view& out, diag::Pos& pos);
  bool onOff(const Word& w, bool& out);
  bool compare(const Word& w, vm::Compare& out);
  bool jump(const Word& w, JumpRef& out);
  std::string motorLetters() const;

  const diag::SourceFile& src_;
  std::span<const vm::MotorSpec> motors_;
  diag::Diagnostics& diag_;
  AstSink& sink_;
  Instruction in_;  // the one being built (kept for its vector's capacity)
  PointDef point_;  // the same
  std::uint32_t instructions_ = 0;
  diag::Pos pointsHeader_;
  std::vector<Word> words_;
  bool inPoints_ = false;
  std::uint32_t endLine_ = 0;  // the last END instruction's line, 0 before any
  std::string_view pendingLabel_;
  diag::Pos pendingLabelPos_;
};

}  // namespace rs::compiler::detail
