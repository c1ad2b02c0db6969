#include "tools/lsp/workspace.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "base/ascii.h"
#include "tools/lsp/uri.h"

namespace rs::lsp {

namespace fs = std::filesystem;

void Workspace::changing(const std::string& uri) {
  if (const auto it = programs_.find(uri); it != programs_.end() && it->second.analysis)
    it->second.analysis->runControl().abandon();
}

void Workspace::abandonRuns() {
  for (const auto& [uri, cached] : programs_)
    if (cached.analysis) cached.analysis->runControl().abandon();
}

Document& Workspace::open(const std::string& uri, Language language, std::int64_t version, std::string text) {
  changing(uri);
  programs_.erase(uri);
  docs_.erase(uri);
  return docs_.try_emplace(uri, uri, language, version, std::move(text)).first->second;
}

void Workspace::close(const std::string& uri) {
  changing(uri);
  docs_.erase(uri);
  programs_.erase(uri);
}

Document* Workspace::document(const std::string& uri) {
  const auto it = docs_.find(uri);
  return it == docs_.end() ? nullptr : &it->second;
}

std::string Workspace::cellFor(const std::string& path, const std::optional<launch::CellDirective>& directive) const {
  if (directive) return launch::resolveCellName(path.empty() ? std::string("./x") : path, directive->name);
  if (settings_.cell.empty()) return {};
  std::error_code ec;
  if (!root_.empty() && fs::is_regular_file(fs::path(root_) / settings_.cell, ec))
    return (fs::path(root_) / settings_.cell).string();
  return settings_.cell;
}

std::shared_ptr<const ProgramAnalysis> Workspace::programFile(const std::string& path, std::string text) {
  std::optional<launch::CellDirective> directive = launch::findCellDirective(diag::withoutByteOrderMark(text));
  std::shared_ptr<const CellContext> cell =
      cells_.forProgram(cellFor(path, directive), path, launch::findRobotDirective(diag::withoutByteOrderMark(text)));
  // The stimuli file beside it, read here (it is small: the parse is
  // bounded as the CLI's) for the hovers and checks of inputs.
  StimuliBeside beside;
  const RunOptions options = runOptions(path);
  if (options.stimuliText || !options.stimuliPath.empty()) {
    beside.file = options.stimuliFile;
    diag::Result<stimuli::Stimuli> parsed = options.stimuliText
                                                ? stimuli::parseStimuli(*options.stimuliText, options.stimuliFile)
                                                : stimuli::loadStimuliFile(options.stimuliPath);
    if (parsed.ok()) beside.parsed = std::move(parsed).value();
  }
  return std::make_shared<const ProgramAnalysis>(path, std::move(text), std::move(cell), std::move(directive),
                                                 std::move(beside));
}

std::shared_ptr<const ProgramAnalysis> Workspace::program(const Document& doc) {
  Cached& cached = programs_[doc.uri()];
  if (!cached.analysis || cached.revision != doc.revision()) {
    if (cached.analysis) cached.analysis->runControl().abandon();
    const std::string path = pathOfUri(doc.uri());
    cached.analysis = programFile(path.empty() ? doc.uri() : path, doc.text());
    cached.revision = doc.revision();
  }
  return cached.analysis;
}

void Workspace::setSettings(Settings settings) {
  settings_ = std::move(settings);
  cells_.setLibDirs(settings_.libDirs);
  abandonRuns();
  programs_.clear();
}

void Workspace::descriptionsChanged() {
  cells_.clear();
  abandonRuns();
  programs_.clear();
}

void Workspace::stimuliChanged() {
  abandonRuns();
  programs_.clear();
}

RunOptions Workspace::runOptions(const std::string& programPath) const {
  RunOptions options;
  options.collisions = settings_.collisions;
  if (programPath.size() < 4 || !base::sameName(std::string_view(programPath).substr(programPath.size() - 4), ".rsp"))
    return options;
  const std::string stimuli = programPath.substr(0, programPath.size() - 4) + ".stim";
  options.stimuliFile = fs::path(stimuli).filename().string();
  for (const auto& [uri, doc] : docs_)
    if (doc.language() == Language::Stimuli && pathOfUri(uri) == stimuli) {
      options.stimuliText = doc.text();
      return options;
    }
  std::error_code ec;
  if (fs::is_regular_file(stimuli, ec)) options.stimuliPath = stimuli;  // read by the run, off this thread
  return options;
}

std::vector<std::string> Workspace::files(std::string_view suffix, std::size_t limit) const {
  std::vector<std::string> out;
  if (root_.empty()) return out;
  std::error_code ec;
  fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, ec), end;
  // At most this many entries looked at: a workspace opened at / costs a bounded time.
  std::size_t budget = 50'000;
  for (; !ec && it != end && out.size() < limit && budget > 0; it.increment(ec), --budget) {
    const std::string name = it->path().filename().string();
    if (it->is_directory(ec)) {
      if (name.starts_with(".") || name.starts_with("build") || name == "node_modules") it.disable_recursion_pending();
      continue;
    }
    if (name.ends_with(suffix) && it->is_regular_file(ec)) out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace rs::lsp
