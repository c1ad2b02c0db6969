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
  /// abandoned (a newer version is coming).
  void changing(const std::string& uri);
  /// Every run being made or waiting is abandoned (shutdown).
  void abandonRuns();

  /// The up-to-date analysis of an open program.
  std::shared_ptr<const ProgramAnalysis> program(const Document& doc);
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
  };
  std::map<std::string, Document> docs_;
  std::map<std::string, Cached> programs_;
  Settings settings_;
  std::string root_;
  CellCache cells_;
};

}  // namespace rs::lsp
