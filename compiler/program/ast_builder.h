// A line's words -> AST. Checks each line's shape against the opcode table
// (how many operands, of which kind) and converts numbers, so later passes
// work on typed operands only.
#pragma once

#include <span>

#include "compiler/program/ast.h"
#include "diag/diagnostic.h"
#include "compiler/program/line_reader.h"
#include "compiler/program/parse_tree.h"
#include "vm/image.h"

namespace rs::compiler {

/// What the builder hands on, in source order, as soon as each is built:
/// the compiler checks and encodes an instruction at once (AstSink in
/// translator.h), so the whole program's AST is never held; buildAst below
/// collects them into a Program.
class AstSink {
 public:
  virtual ~AstSink() = default;
  /// Valid during the call only (the builder reuses it for the next).
  virtual void instruction(const Instruction& in) = 0;
  virtual void pointsHeader(diag::Pos pos) = 0;
  virtual void point(const PointDef& point) = 0;
};

/// From each line's words in turn, to `sink` (the compiler's way).
void buildAst(const diag::SourceFile& source, LineReader& lines, std::span<const vm::MotorSpec> motors,
              diag::Diagnostics& diagnostics, AstSink& sink);

/// From the whole file's parse tree (`robotsim ast`).
Program buildAst(ParseTree& tree, std::span<const vm::MotorSpec> motors, diag::Diagnostics& diagnostics);
/// From each line's words in turn: the same AST.
Program buildAst(const diag::SourceFile& source, LineReader& lines, std::span<const vm::MotorSpec> motors,
                 diag::Diagnostics& diagnostics);


/// The mnemonic closest to a misspelled one ("MOVX" -> "MOVE"), or empty.
std::string_view closestMnemonic(std::string_view word);

}  // namespace rs::compiler
