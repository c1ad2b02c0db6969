// The machine a program is checked against in the editor, chosen as the
// CLI chooses it (launch/cell_directive.h): the program's "; cell: NAME"
// directive, else the workspace setting `robotsim.cell`, else the default
// robot. Loaded once per name and kept until the settings or a
// description change.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/program/codegen.h"
#include "launch/cell_directive.h"
#include "model/workcell/model.h"

namespace rs::lsp {

struct CellContext {
  std::string name;  ///< as resolved ("" = the default robot)
  compiler::Target target;
  std::shared_ptr<const workcell::Workcell> cell;  ///< when a cell or robot was named and loaded
  /// The robot whose tool centre point hover shows: the cell's first,
  /// placed; or the default robot as drawn.
  std::optional<workcell::PlacedRobot> robot;
  std::string problem;  ///< why the named cell could not be loaded ("" = it was)
  /// Why the program's `; robot: LABEL` names no robot of the cell ("" = it
  /// does, or there is none), and where the label stands.
  std::string robotProblem;
  diag::Pos robotProblemPos;
};

/// The description file a library name (or a file name) stands for on the
/// search path, or "" when none is found.
std::string findDescriptionFile(const std::string& name, const std::vector<std::filesystem::path>& searchPath);

class CellCache {
 public:
  void setLibDirs(std::vector<std::string> libDirs);
  std::vector<std::filesystem::path> searchPath() const;
  /// The context for a resolved name ("" = the default robot).
  std::shared_ptr<const CellContext> get(const std::string& name);
  /// The context for the program at `path` on that cell: in a cell of
  /// several robots, with the robot the program runs on first, as the CLI
  /// chooses it (launch/robot_choice.h: its `; robot:` line, else the robot
  /// whose PROGRAM it is, else the first).
  std::shared_ptr<const CellContext> forProgram(const std::string& name, const std::string& path,
                                                const std::optional<launch::CellDirective>& robot);
  void clear() { cache_.clear(); }

 private:
  std::vector<std::string> libDirs_;
  std::map<std::string, std::shared_ptr<const CellContext>> cache_;
};

}  // namespace rs::lsp
