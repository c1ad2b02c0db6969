// The translator: semantic checks and code generation, one instruction at a time as the
// AST builder hands them on: names resolved (labels, points, variables),
// numbers in range, each instruction encoded at once (codegen.h); what
// needs the whole file (a label defined further down, a point of the
// POINTS section, a line number beyond the last instruction) is noted and
// resolved at the end, and control flow analysed then, on the code. So
// the compiler holds the image being built and the references still open,
// never the whole program's AST.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>

#include "compiler/program/ast.h"
#include "compiler/program/ast_builder.h"
#include "compiler/program/codegen.h"
#include "diag/diagnostic.h"
#include "vm/image.h"

namespace rs::compiler {

class Translator final : public AstSink {
 public:
  /// For `source`'s program: its size bounds what is reserved.
  Translator(const Target& target, const diag::SourceFile& source, diag::Diagnostics& diagnostics);
  ~Translator() override;
  Translator(const Translator&) = delete;
  Translator& operator=(const Translator&) = delete;

  void instruction(const Instruction& in) override;
  void pointsHeader(diag::Pos pos) override;
  void point(const PointDef& point) override;

  /// The values of the last point received (for a point written as a
  /// pose, its resolved encoder counts; empty when it could not be resolved).
  std::span<const std::int32_t> lastPointValues() const;

  /// Resolves what waited for the end of the file and analyses control
  /// flow; the image when no error was reported (by anyone).
  std::optional<vm::Image> finish();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace rs::compiler
