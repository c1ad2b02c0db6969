// What a language server needs to know about a program's names, from the
// one compile that gives its diagnostics: an AstSink the compiler tees
// every instruction and point to (compiler::compile with an observer), so
// there is no second parser. It records each instruction's shape and every
// occurrence of a name, definition or use, in source order:
//
//   labels     defined by "name:", used by GOTO, GOSUB, JMPIN, JMPVAR
//   points     defined after POINTS, used by MOVEP
//   variables  written by SET and ADD, read by JMPVAR (no definition:
//              the first write stands for one)
//   jumps by number: a use of the instruction of that number
//
// Names are views into the source, which must outlive the index.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/program/ast_builder.h"
#include "diag/source_file.h"

namespace rs::lsp {

enum class NameKind : std::uint8_t { Label, Point, Variable, Instruction };

struct Occurrence {
  NameKind kind = NameKind::Label;
  bool definition = false;
  diag::Pos pos;
  std::uint32_t length = 0;       ///< bytes written (names and numbers are ASCII)
  std::string_view name;          ///< as written (Instruction: the number's text)
  std::uint32_t instruction = 0;  ///< Instruction: the 1-based number it names
};

struct IndexedInstruction {
  std::uint32_t number = 0;  ///< 1-based
  diag::Pos pos;             ///< of the mnemonic
  std::string_view mnemonic;
  vm::Op op = vm::Op::End;
  bool known = true;
  std::string_view label;    ///< defined on it, if any
  diag::Pos labelPos;
  std::string_view targetLabel;   ///< a jump to a label
  std::uint32_t targetNumber = 0;  ///< a jump by number
  std::string_view name;     ///< its point or variable, if any
  /// An instruction that takes an input (WAITFOR, JMPIN): its number as
  /// written, where, and the state it asks for.
  std::int64_t input = 0;
  diag::Pos inputPos;
  std::uint32_t inputLength = 0;
  bool inputOn = false;
};

struct IndexedPoint {
  std::string_view name;
  diag::Pos pos;
  std::vector<std::int32_t> values;  ///< as many as were written and read; for a pose, as resolved
  std::string_view pose;             ///< a point written as a tool pose: the pose ("AT ..."), else empty
};

class ProgramIndex final : public compiler::AstSink {
 public:
  explicit ProgramIndex(const diag::SourceFile& source);

  void instruction(const compiler::Instruction& in) override;
  void pointsHeader(diag::Pos pos) override { pointsHeader_ = pos; }
  void point(const compiler::PointDef& p) override;
  /// After the compile: notes which labels are subroutine entries.
  void finish();

  const std::vector<IndexedInstruction>& instructions() const { return instructions_; }
  const std::vector<IndexedPoint>& points() const { return points_; }
  const std::vector<Occurrence>& occurrences() const { return occurrences_; }
  /// Line 0 when the program has no POINTS section.
  diag::Pos pointsHeader() const { return pointsHeader_; }

  /// The occurrence covering a position (the character under the cursor,
  /// or the one just before it, as editors ask at a word's end).
  const Occurrence* occurrenceAt(diag::Pos pos) const;
  /// Every occurrence of the same name (any case) and kind, in source order.
  std::vector<const Occurrence*> occurrencesOf(const Occurrence& o) const;
  /// The definition of what `o` names, if the program has one.
  const Occurrence* definitionOf(const Occurrence& o) const;
  /// The instruction on a source line (1-based), if any.
  const IndexedInstruction* instructionOnLine(std::uint32_t line) const;
  const IndexedInstruction* instructionNumbered(std::uint32_t number) const;
  const IndexedPoint* point(std::string_view name) const;
  /// Labels that a GOSUB names: subroutine entries.
  bool isSubroutine(std::string_view label) const;
  /// The instruction a label is on.
  const IndexedInstruction* labelled(std::string_view label) const;

 private:
  void add(NameKind kind, bool definition, diag::Pos pos, std::string_view name, std::uint32_t instruction = 0);
  std::uint32_t lengthAt(diag::Pos pos) const;

  const diag::SourceFile& source_;
  std::vector<IndexedInstruction> instructions_;
  std::vector<IndexedPoint> points_;
  std::vector<Occurrence> occurrences_;
  diag::Pos pointsHeader_;
  std::set<std::string> subroutines_;  // upper-cased labels a GOSUB names
};

/// Positions in source order.
inline bool before(diag::Pos a, diag::Pos b) { return a.line != b.line ? a.line < b.line : a.col < b.col; }

}  // namespace rs::lsp
