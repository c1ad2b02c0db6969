// The server's state between messages: the open documents, the settings
// (which cell, which library folders), the workspace folder, and the
// analysis of each open program, redone only when its text changed.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "runtime/sim/collision_watch.h"
#include "tools/lsp/cell_context.h"
#include "tools/lsp/cell_run_plan.h"
#include "tools/lsp/document.h"
#include "tools/lsp/program_analysis.h"

namespace rs::lsp {

/// `robotsim.cell`, `robotsim.lib` and `robotsim.collisions`
/// (initializationOptions or workspace/didChangeConfiguration).
struct Settings {
  std::string cell;
  std::vector<std::string> libDirs;
  runtime::CollisionMode collisions = runtime::CollisionMode::Error;  ///< as --collisions
};

class Workspace {
 public:
  Document& open(const std::string& uri, Language language, std::int64_t version, std::string text);
  void close(const std::string& uri);
  Document* document(const std::string& uri);
  const std::map<std::string, Document>& documents() const { return docs_; }
  /// The document is about to change: the run of its last analysis is
  /// abandoned (a newer version is coming), and so are the analyses of the
  /// open programs whose cell runs read it (takeDependents()).
  void changing(const std::string& uri);
  /// The open programs whose analyses were dropped since the last call
  /// because another program their cell runs read changed: they are to be
  /// checked again.
  std::vector<std::string> takeDependents();
  /// Every run being made or waiting is abandoned (shutdown).
  void abandonRuns();

  /// The up-to-date analysis of an open program.
  std::shared_ptr<const ProgramAnalysis> program(const Document& doc);
  /// What the checked run of the open program `uri` runs with
  /// (cell_run_plan.h): in a cell where other robots have programs, each of
  /// them compiled for its robot, from its open document or else its file;
  /// inactive when the program runs alone. Remembers the files the run
  /// reads, for changing().
  CellRunPlan cellRunPlan(const std::string& uri, const ProgramAnalysis& analysis);
  /// The analysis of a program file that is not open (workspace symbols).
  std::shared_ptr<const ProgramAnalysis> programFile(const std::string& path, std::string text);

  void setSettings(Settings settings);
  const Settings& settings() const { return settings_; }
  void setRoot(std::string path) { root_ = std::move(path); }
  const std::string& root() const { return root_; }
  CellCache& cells() { return cells_; }
  /// Descriptions changed: cells are loaded again, programs checked again.
  void descriptionsChanged();
  /// A stimuli file changed: programs are checked (and run) again.
  void stimuliChanged();
  /// The options of a program's checked run: the collisions setting, and
  /// the stimuli file beside it (NAME.stim for NAME.rsp), as the editor
  /// holds it when open, else the saved file, if any.
  RunOptions runOptions(const std::string& programPath) const;

  /// The cell a program is checked against: its directive, else the
  /// setting, else "" (the default robot), resolved as --cell would be.
  std::string cellFor(const std::string& path, const std::optional<launch::CellDirective>& directive) const;
  /// Files under the workspace folder with this suffix (at most `limit`,
  /// skipping hidden and build folders), sorted.
  std::vector<std::string> files(std::string_view suffix, std::size_t limit = 2000) const;

 private:
  struct Cached {
    std::uint64_t revision = 0;
    std::shared_ptr<const ProgramAnalysis> analysis;
    std::vector<std::string> cellFiles;  ///< the programs its cell run reads (normal absolute paths)
  };
  /// A partner of a cell run: its open document checked as that robot
  /// (when `mayShow`: it then shows what the run finds in it), or its text
  /// compiled for that robot; `problem` when it cannot be.
  void partnerOf(CellPartner& p, const std::string& cellName, bool mayShow, std::string& problem);
  std::map<std::string, Document> docs_;
  std::map<std::string, Cached> programs_;
  /// Other robots' programs compiled for a cell run, by cell, robot and
  /// file: compiled again only when their text changes.
  std::map<std::string, std::shared_ptr<const ProgramAnalysis>> partnerFiles_;
  std::vector<std::string> dependents_;
  Settings settings_;
  std::string root_;
  CellCache cells_;
};

}  // namespace rs::lsp
