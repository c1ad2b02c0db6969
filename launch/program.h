// From the files a user names to a program ready to run: the program
// (a `.rsp` source, compiled here, or a `.rsb` image, recognised by its
// magic number whatever the file is called), the workcell it runs on
// (`--cell`, or the one an image carries), and every diagnostic, each
// with its file's text for the caret. The one place `--cell` is loaded.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "compiler/program/compiler.h"
#include "compiler/description/library.h"
#include "diag/diagnostic.h"
#include "model/workcell/model.h"
#include "vm/image.h"

namespace rs::launch {

/// Programs and description files are refused over this size, from their
/// size, before they are read.
inline constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

struct LoadedCell;

/// What the user named.
struct ProgramRequest {
  std::string file;                  ///< program source or image
  std::string cell;                  ///< --cell: workcell or robot, file or library name ("" = none)
  std::vector<std::string> libDirs;  ///< --lib
  /// Grading (`robotsim test --spec`): the program is a submission, and its
  /// "; cell:" directive may name only a library robot or cell or a file
  /// inside its own folder (cell_directive.h's resolveSubmissionCell).
  bool submission = false;
  /// Set by the loader for such a directive's library name: looked up on
  /// the library path only (compiler::Library::lookUpNamesOnly).
  bool cellFromLibraryOnly = false;
  /// --max-errors: diagnostics kept and printed at most (0 = all); the rest
  /// are counted, and printDiagnostics says how many.
  std::size_t maxErrors = 0;
  std::string robot = {};  ///< --robot: the cell's robot the program runs on ("" = robot_choice.h)
  /// `cell` read and built already for this request (`run PROG --cell CELL`
  /// first looks whether the cell has other programs to run): loadCell
  /// gives it back, with its diagnostics, instead of reading it again.
  std::shared_ptr<const LoadedCell> loadedCell = {};
};

struct LoadedProgram {
  std::optional<diag::SourceFile> source;          ///< set when the file was source text
  std::shared_ptr<const vm::Image> image;          ///< set when it compiled / verified
  std::shared_ptr<const workcell::Workcell> cell;  ///< what it runs on, if a workcell
  std::vector<diag::Diagnostic> diagnostics;
  std::size_t maxErrors = 0;  ///< the request's: printDiagnostics shows at most this many (0 = all)
  diag::Omitted omitted;      ///< found beyond the first maxErrors, not kept
  /// The description files read for --cell, kept for their source lines.
  std::shared_ptr<const compiler::Library> descriptions;
  bool ok() const { return image != nullptr && !diag::hasErrors(diagnostics); }
  /// The source text of a diagnostic's file, if it was read.
  const diag::SourceFile* sourceOf(const std::string& file) const;
};

/// A cell loadCell read: what it gives back, and what a request may carry
/// so that a later load of the same cell does not read the files again.
struct LoadedCell {
  std::shared_ptr<const workcell::Workcell> cell;
  std::shared_ptr<const compiler::Library> descriptions;
  std::vector<diag::Diagnostic> diagnostics;
};

/// What a program is loaded for: what it must meet besides compiling.
enum class ProgramUse : std::uint8_t {
  /// run, check, compile, disasm: the program compiled for --cell's first
  /// robot (the image then carries the cell), else for the cell its
  /// "; cell: NAME" directive names (cell_directive.h), else for the default
  /// robot; an image runs on the cell it carries, and refuses --cell.
  Run,
  /// render, animate: the same, except that an image may be drawn on the
  /// --cell given (its robot must have the image's motors), and a program
  /// needs a workcell (--cell, or one its image carries).
  Draw,
};

/// The program of `request`, compiled or verified, with its cell, for `use`.
LoadedProgram loadProgram(const ProgramRequest& request, ProgramUse use = ProgramUse::Run);

/// loadProgram(request, ProgramUse::Draw), by the name its callers use.
inline LoadedProgram loadProgramToDraw(const ProgramRequest& request) {
  return loadProgram(request, ProgramUse::Draw);
}

/// --cell's workcell alone (render without a program, ast); its problems
/// go to `into`, whose descriptions keep the files' text.
std::shared_ptr<const workcell::Workcell> loadCell(const ProgramRequest& request, LoadedProgram& into);

/// The default machine: the paper's Rhino SCARA (stdlib/default_robot.h).
compiler::Target defaultTarget();
/// The machine of a workcell: the motors (arm, then gripper) of the robot
/// it drives (Workcell::drivenRobot; there must be one).
compiler::Target cellTarget(const workcell::Workcell& cell);

/// The diagnostics, each under its own file's source line when known: at
/// most program.maxErrors of them (0 = all), then a note of how many more
/// there were (those not printed and program.omitted).
void printDiagnostics(std::ostream& err, const std::vector<diag::Diagnostic>& diags, const LoadedProgram& program);

/// The same for any diagnostics: at most `max` (0 = all) printed, each with
/// the source `sourceOf` finds for its file, then the note counting those
/// not printed and `omitted`.
void printDiagnostics(std::ostream& err, std::span<const diag::Diagnostic> diags,
                      const std::function<const diag::SourceFile*(const std::string&)>& sourceOf, std::size_t max,
                      diag::Omitted omitted);

/// "robotsim: note: 3 more errors not shown; --max-errors 0 shows all", or
/// empty when nothing was left out.
std::string omittedNote(const diag::Omitted& omitted);

}  // namespace rs::launch
