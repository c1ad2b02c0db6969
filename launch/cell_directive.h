// Which workcell a program runs on when the command line does not say: a
// directive comment in the program itself,
//
//   ; cell: scara-pick
//
// a whole-line comment anywhere in the file (the first one counts), naming
// a library cell or robot, or a description file (relative to the
// program's folder). `--cell` wins over it; without either a program runs
// on the default robot. The CLI (through loadProgram) and the language
// server read it with the same function. In grading (`robotsim test
// --spec`) a submission's directive is confined: resolveSubmissionCell.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "diag/result.h"
#include "diag/source_file.h"

namespace rs::launch {

struct CellDirective {
  std::string name;  ///< as written
  diag::Pos pos;     ///< of the name (columns in characters)
  std::size_t offset = 0;  ///< byte offset of the name in the text
};

/// The first "; KEY NAME" whole-line comment of a program's text (`key`
/// with its colon, ASCII case ignored).
std::optional<CellDirective> findDirective(std::string_view text, std::string_view key);

/// The first "; cell: NAME" whole-line comment of a program's text.
std::optional<CellDirective> findCellDirective(std::string_view text);

/// The first "; robot: LABEL" one: which robot of a cell of several the
/// program runs on (`--robot LABEL` wins over it; robot_choice.h).
std::optional<CellDirective> findRobotDirective(std::string_view text);

/// What a directive names, as --cell would take it: a description file
/// beside the program (`programFile`'s folder) when one exists by that
/// name, else the name itself (a library name, or a path from the working
/// directory).
std::string resolveCellName(const std::string& programFile, const std::string& name);

/// What a directive of a submission being graded may name, and nothing
/// more: a library robot or cell (`libraryName`: then looked up on the
/// library path only, never as a file from the working directory), or a
/// file inside the submission's own folder once every link is followed.
struct SubmissionCell {
  std::string name;  ///< the library name, or the file beside the program
  bool libraryName = false;
};

/// The directive of the submission `programFile` resolved as above, or an
/// error at the directive that quotes at most its name, made safe; nothing
/// it names outside the folder is opened.
diag::Result<SubmissionCell> resolveSubmissionCell(const std::string& programFile, const CellDirective& directive);

}  // namespace rs::launch
