// Everything the server knows about one version of a program, from one
// compile: its diagnostics, its index of names (program_index.h), the
// machine it was checked against, and, on first use, the times of its
// default run (what `robotsim run PROG` would do, bounded so that a
// program that loops forever costs a bounded time).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/compiler.h"
#include "launch/cell_directive.h"
#include "lsp/cell_context.h"
#include "lsp/program_index.h"
#include "vm/machine.h"

namespace rs::lsp {

/// The default run stops after this many instructions or this much
/// simulated time (the CLI's default), whichever comes first.
inline constexpr std::uint64_t kHintRunSteps = 100'000;
inline constexpr vm::Micros kHintRunTime = vm::Micros{3600} * 1'000'000;

struct InstructionTimes {
  vm::Micros start = 0;  ///< of its first execution
  vm::Micros end = 0;
  std::uint64_t runs = 0;  ///< 0: never ran
};

struct DefaultRun {
  std::vector<InstructionTimes> times;  ///< per instruction (0-based)
  std::string outcome;                  ///< how it ended, a phrase ("finished at 3.5 s")
};

class ProgramAnalysis {
 public:
  /// `path` names the file (it may be ""); `directive` is the program's own
  /// cell directive, if any.
  ProgramAnalysis(std::string path, std::string text, std::shared_ptr<const CellContext> cell,
                  std::optional<launch::CellDirective> directive);
  ProgramAnalysis(const ProgramAnalysis&) = delete;
  ProgramAnalysis& operator=(const ProgramAnalysis&) = delete;

  const diag::SourceFile& source() const { return source_; }
  const ProgramIndex& index() const { return index_; }
  const compiler::CompileResult& compiled() const { return compiled_; }
  const CellContext& cell() const { return *cell_; }
  const std::optional<launch::CellDirective>& directive() const { return directive_; }
  /// Runs the program once, on first call (nothing when it has errors).
  const DefaultRun& defaultRun() const;

 private:
  diag::SourceFile source_;
  ProgramIndex index_;
  compiler::CompileResult compiled_;
  std::shared_ptr<const CellContext> cell_;
  std::optional<launch::CellDirective> directive_;
  mutable std::optional<DefaultRun> run_;
};

/// Diagnostics a server keeps for one document at most (the rest counted).
inline constexpr std::size_t kMaxDiagnostics = 1000;

/// Seconds for people: "1.5 s", "0.333334 s".
std::string formatSeconds(vm::Micros t);

}  // namespace rs::lsp
