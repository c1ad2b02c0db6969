// Everything the server knows about one version of a program, from one
// compile: its diagnostics, its index of names (program_index.h), the
// machine it was checked against, its image, and, once the run worker has
// made it, the run `robotsim check` makes of it (checked_run.h), for the
// run-time diagnostics, hovers and inlay hints.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "compiler/stimuli/stimuli.h"
#include "launch/cell_directive.h"
#include "tools/lsp/cell_context.h"
#include "tools/lsp/checked_run.h"
#include "tools/lsp/document.h"
#include "tools/lsp/program_index.h"
#include "vm/machine.h"

namespace rs::lsp {

/// The stimuli file beside a program (NAME.stim for NAME.rsp), as hovers
/// and the server's checks of inputs read it.
struct StimuliBeside {
  std::string file;                        ///< its name, "" when there is none
  std::optional<stimuli::Stimuli> parsed;  ///< none: no file, or it has errors
};

class ProgramAnalysis {
 public:
  /// `path` names the file (it may be ""); `directive` is the program's own
  /// cell directive, if any.
  ProgramAnalysis(std::string path, std::string text, std::shared_ptr<const CellContext> cell,
                  std::optional<launch::CellDirective> directive, StimuliBeside stimuli = {});
  ProgramAnalysis(const ProgramAnalysis&) = delete;
  ProgramAnalysis& operator=(const ProgramAnalysis&) = delete;

  const diag::SourceFile& source() const { return source_; }
  const ProgramIndex& index() const { return index_; }
  /// The compile's diagnostics and what it left out (its image is image()).
  const compiler::CompileResult& compiled() const { return compiled_; }
  /// The image, when the program compiled without errors.
  const std::shared_ptr<const vm::Image>& image() const { return image_; }
  bool ok() const { return image_ != nullptr; }
  const CellContext& cell() const { return *cell_; }
  const std::optional<launch::CellDirective>& directive() const { return directive_; }
  const StimuliBeside& stimuli() const { return stimuli_; }
  /// The LSP range a diagnostic at `pos` underlines, from this version's
  /// text (the same as the document's at this version; usable from any
  /// thread, unlike the document, which the next edit changes).
  Range wordAt(diag::Pos pos, Encoding enc) const;

  // The checked run, made by the run worker (any thread may ask).
  /// Marks the run as asked for: true the first time (the caller then
  /// hands it to the run worker), false once it was.
  bool askForRun() const;
  /// The worker's result.
  void runMade(CheckedRun run) const;
  /// The run, once made; waits up to `wait` for one that is queued or
  /// being made (null at once when none was asked for).
  const CheckedRun* run(std::chrono::milliseconds wait = std::chrono::milliseconds(0)) const;
  /// Abandons the run (a newer version exists): see RunControl.
  RunControl& runControl() const { return control_; }
  /// A hover or inlay hints were answered before the run was made: the
  /// client is asked to refresh its hints once it is.
  void noteAnsweredWithoutRun() const { answeredWithoutRun_.store(true, std::memory_order_relaxed); }
  bool answeredWithoutRun() const { return answeredWithoutRun_.load(std::memory_order_relaxed); }

 private:
  bool byteOrderMark_;  // before source_, which drops the mark
  diag::SourceFile source_;
  ProgramIndex index_;
  compiler::CompileResult compiled_;
  std::shared_ptr<const vm::Image> image_;
  std::shared_ptr<const CellContext> cell_;
  std::optional<launch::CellDirective> directive_;
  StimuliBeside stimuli_;

  enum class RunState : std::uint8_t { None, Queued, Made };
  mutable std::mutex runMutex_;
  mutable std::condition_variable runMadeSignal_;
  mutable RunState runState_ = RunState::None;
  mutable std::optional<CheckedRun> run_;
  mutable RunControl control_;
  mutable std::atomic<bool> answeredWithoutRun_ = false;
};

/// Diagnostics a server keeps for one document at most (the rest counted).
inline constexpr std::size_t kMaxDiagnostics = 1000;

/// Seconds for people: "1.5 s", "0.333334 s".
std::string formatSeconds(vm::Micros t);

}  // namespace rs::lsp
