// Parse tree -> AST. Checks each line's shape against the opcode table
// (how many operands, of which kind) and converts numbers, so later passes
// work on typed operands only.
#pragma once

#include <span>

#include "compiler/ast.h"
#include "diag/diagnostic.h"
#include "compiler/parse_tree.h"
#include "vm/image.h"

namespace rs::compiler {

/// From the whole file's parse tree (`robotsim ast`).
Program buildAst(ParseTree& tree, std::span<const vm::MotorSpec> motors, diag::Diagnostics& diagnostics);
/// From each line's parse tree in turn (the compiler): the same AST.
Program buildAst(const diag::SourceFile& source, LineParser& parser, std::span<const vm::MotorSpec> motors,
                 diag::Diagnostics& diagnostics);


/// The mnemonic closest to a misspelled one ("MOVX" -> "MOVE"), or empty.
std::string_view closestMnemonic(std::string_view word);

}  // namespace rs::compiler
