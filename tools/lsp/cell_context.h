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
  void clear() { cache_.clear(); }

 private:
  std::vector<std::string> libDirs_;
  std::map<std::string, std::shared_ptr<const CellContext>> cache_;
};

}  // namespace rs::lsp
