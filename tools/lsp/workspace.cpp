#include "tools/lsp/workspace.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "base/ascii.h"
#include "base/file_io.h"
#include "launch/program.h"
#include "tools/lsp/uri.h"
#include "vm/image_file.h"

namespace rs::lsp {

namespace fs = std::filesystem;

namespace {

std::string normalPath(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? fs::path(path) : absolute).lexically_normal().string();
}

// Two resolved cell names for one cell: the same name, or the same file.
bool sameCell(const std::string& a, const std::string& b) {
  if (a == b) return true;
  std::error_code ec;
  return fs::is_regular_file(a, ec) && fs::is_regular_file(b, ec) && fs::equivalent(a, b, ec);
}

// The analysis is that robot of that cell's: its document shows that robot's run.
bool checkedAs(const ProgramAnalysis& a, const std::string& cellName, const std::string& label) {
  const CellContext& c = a.cell();
  return c.cell && c.robotProblem.empty() && sameCell(c.name, cellName) && c.cell->drivenRobot() &&
         base::sameName(c.cell->drivenRobot()->labelOf(), label);
}

}  // namespace

void Workspace::changing(const std::string& uri) {
  if (const auto it = programs_.find(uri); it != programs_.end() && it->second.analysis)
    it->second.analysis->runControl().abandon();
  const std::string path = pathOfUri(uri);
  if (path.empty()) return;
  const std::string changed = normalPath(path);
  for (auto it = programs_.begin(); it != programs_.end();) {
    const std::vector<std::string>& files = it->second.cellFiles;
    if (it->first == uri || std::find(files.begin(), files.end(), changed) == files.end()) {
      ++it;
      continue;
    }
    if (it->second.analysis) it->second.analysis->runControl().abandon();
    if (docs_.count(it->first)) dependents_.push_back(it->first);
    it = programs_.erase(it);
  }
}

std::vector<std::string> Workspace::takeDependents() {
  std::vector<std::string> out;
  out.swap(dependents_);
  return out;
}

void Workspace::partnerOf(CellPartner& p, const std::string& cellName, bool mayShow, std::string& problem) {
  const std::string file = normalPath(p.file);
  const std::string shown = fs::path(p.file).filename().string();
  std::optional<std::string> text;
  const auto open = std::find_if(docs_.begin(), docs_.end(), [&](const auto& entry) {
    return entry.second.language() == Language::Program && !pathOfUri(entry.first).empty() &&
           normalPath(pathOfUri(entry.first)) == file;
  });
  if (open != docs_.end()) {
    std::shared_ptr<const ProgramAnalysis> own = program(open->second);
    if (mayShow && checkedAs(*own, cellName, p.label)) p.analysis = std::move(own), p.uri = open->first;
    else text = open->second.text();
  } else {
    base::FileRead read = base::readFile(p.file, launch::kMaxInputBytes);
    if (!read.bytes) {
      if (problem.empty()) problem = fmt::format("robot {}'s program {} cannot be read: {}", p.label, shown, read.error);
      return;
    }
    if (vm::looksLikeImage(*read.bytes)) {  // the cell's loader checked it fits the robot
      diag::Result<vm::Image> image = vm::loadImage(*read.bytes, p.file);
      if (image) p.image = std::make_shared<const vm::Image>(std::move(image).value());
      else if (problem.empty()) problem = fmt::format("robot {}'s program {} is a damaged image", p.label, shown);
      return;
    }
    text = std::move(*read.bytes);
  }
  if (text) {
    std::shared_ptr<const ProgramAnalysis>& cached = partnerFiles_[cellName + '\n' + p.label + '\n' + file];
    if (!cached || cached->source().text() != diag::withoutByteOrderMark(*text))
      cached = std::make_shared<const ProgramAnalysis>(
          p.file, std::move(*text), cells_.forProgram(cellName, p.file, launch::CellDirective{p.label, {}}),
          std::nullopt);
    p.analysis = cached;
  }
  if (!p.analysis->ok() && problem.empty())
    problem = fmt::format("robot {}'s program {} has errors", p.label, shown);
  p.image = p.analysis->image();
}

CellRunPlan Workspace::cellRunPlan(const std::string& uri, const ProgramAnalysis& analysis) {
  CellRunPlan plan;
  const CellContext& context = analysis.cell();
  if (!context.cell || context.cell->robots.size() < 2 || !context.robotProblem.empty()) return plan;
  plan.cell = cells_.get(context.name)->cell;  // as written: the run's robots in the cell's order
  if (!plan.cell) return plan;
  plan.robot = plan.cell->robotLabeled(context.cell->drivenRobot()->labelOf());
  if (plan.robot == workcell::kNoIndex) return {};
  std::vector<std::string> files{normalPath(analysis.source().name())};
  // Another document shows this run's findings in it only when this
  // program is its robot's PROGRAM: that document's own check runs the
  // cell's PROGRAMs, not a program put in one's place.
  const std::string& written = plan.cell->robots[plan.robot].program;
  const bool mayShow = !written.empty() && normalPath(written) == files.front();
  for (std::size_t r = 0; r < plan.cell->robots.size(); ++r) {
    const workcell::PlacedRobot& robot = plan.cell->robots[r];
    if (r == plan.robot || robot.program.empty()) continue;
    CellPartner& p = plan.partners.emplace_back();
    p.robot = r, p.label = robot.labelOf(), p.file = robot.program;
    files.push_back(normalPath(robot.program));
    partnerOf(p, context.name, mayShow, plan.problem);
  }
  // A change to any of these files runs each of these open programs again.
  if (const auto it = programs_.find(uri); it != programs_.end()) it->second.cellFiles = files;
  for (const CellPartner& p : plan.partners)
    if (!p.uri.empty())
      if (const auto it = programs_.find(p.uri); it != programs_.end()) it->second.cellFiles = files;
  return plan;
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
    cached.cellFiles.clear();
  }
  return cached.analysis;
}

void Workspace::setSettings(Settings settings) {
  settings_ = std::move(settings);
  cells_.setLibDirs(settings_.libDirs);
  abandonRuns();
  programs_.clear();
  partnerFiles_.clear();
}

void Workspace::descriptionsChanged() {
  cells_.clear();
  abandonRuns();
  programs_.clear();
  partnerFiles_.clear();
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
