// Loading what the user named: a `.rsp` source (compiled here) or a `.rsb`
// image (recognised by its magic number, whatever the file is called).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "base/file_io.h"
#include "compiler/compiler.h"
#include "compiler/library.h"
#include "runtime/stimuli.h"
#include "model/workcell/model.h"

namespace rs::cli {

struct LoadedProgram {
  std::optional<diag::SourceFile> source;  // set when FILE was source text
  std::optional<vm::Image> image;              // set when it compiled / verified
  std::vector<diag::Diagnostic> diagnostics;
  /// The description files read for --cell, kept for their source lines.
  std::shared_ptr<const compiler::Library> descriptions;
  bool ok() const { return image.has_value(); }
  /// The source text of a diagnostic's file, if it was read.
  const diag::SourceFile* sourceOf(const std::string& file) const;
};

inline constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

LoadedProgram loadProgram(const std::string& path, const compiler::Target& target);

/// Every diagnostic, each under its own file's source line when known.
void printDiagnostics(std::ostream& err, const std::vector<diag::Diagnostic>& diags, const LoadedProgram& program);

/// Stimuli from a stimuli file (when named) and the --input changes, in
/// that order; every error becomes a diagnostic. False on any error.
bool loadStimuli(const std::string& file, const std::vector<std::string>& inputs, runtime::Stimuli& stimuli,
                 std::vector<diag::Diagnostic>& diags);

/// The workcell an image carries, checked against the image itself (its
/// robot must have exactly the image's motors); an error message, or empty.
std::string decodeImageCell(const vm::Image& image, std::optional<workcell::Workcell>& cell);

/// The default machine: the paper's Rhino SCARA (stdlib/default_robot.h).
compiler::Target defaultTarget();

/// The machine of a workcell: its first robot's motors (arm, then gripper).
compiler::Target cellTarget(const workcell::Workcell& cell);

}  // namespace rs::cli
