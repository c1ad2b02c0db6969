#include "launch/cell_programs.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/text.h"
#include "launch/robot_choice.h"

namespace rs::launch {

bool CellPrograms::ok() const {
  if (!cell || diag::hasErrors(cellLoad.diagnostics)) return false;
  for (const LoadedProgram& p : loaded)
    if (!p.ok()) return false;
  return !loaded.empty();
}

const diag::SourceFile* CellPrograms::sourceOf(const std::string& file) const {
  for (const LoadedProgram& p : loaded)
    if (const diag::SourceFile* s = p.sourceOf(file)) return s;
  return cellLoad.sourceOf(file);
}

std::vector<diag::Diagnostic> CellPrograms::allDiagnostics() const {
  std::vector<diag::Diagnostic> all = cellLoad.diagnostics;
  for (const LoadedProgram& l : loaded) all.insert(all.end(), l.diagnostics.begin(), l.diagnostics.end());
  return all;
}

std::vector<diag::Diagnostic> CellPrograms::diagnosticsOnce() const {
  std::vector<diag::Diagnostic> diags = cellLoad.diagnostics;
  for (const LoadedProgram& l : loaded)
    for (const diag::Diagnostic& d : l.diagnostics)
      if (std::none_of(diags.begin(), diags.end(), [&](const diag::Diagnostic& e) {
            return e.file == d.file && e.pos == d.pos && e.message == d.message;
          }))
        diags.push_back(d);
  return diags;
}

bool isProgramAssignment(std::string_view arg) {
  const std::size_t eq = arg.find('=');
  return eq != std::string_view::npos && eq > 0 && arg.substr(0, eq).find('/') == std::string_view::npos;
}

namespace {

// Where each robot's file comes from, in the cell's robot order ("" : none).
struct Assignment {
  std::string file;
  std::optional<LoadedProgram> loaded;  // the command line's program, compiled already
};

}  // namespace

bool assignCellPrograms(const ProgramRequest& request, std::span<const std::string> assignments, CellPrograms& into) {
  ProgramRequest cellOnly = request;
  cellOnly.file.clear(), cellOnly.robot.clear();
  into.cellLoad.maxErrors = request.maxErrors;
  into.cell = loadCell(cellOnly, into.cellLoad);
  if (!into.cell || diag::hasErrors(into.cellLoad.diagnostics)) return false;
  const workcell::Workcell& cell = *into.cell;
  std::vector<Assignment> files(cell.robots.size());
  for (std::size_t r = 0; r < cell.robots.size(); ++r) files[r].file = cell.robots[r].program;
  // A program for a cell where no other robot could run one: a run of one robot.
  const bool anyProgram = std::any_of(files.begin(), files.end(), [](const Assignment& a) { return !a.file.empty(); });
  if (!request.file.empty() && assignments.empty() && (cell.robots.size() < 2 || !anyProgram)) return true;
  if (!request.file.empty()) {
    // The program named runs on the robot it names: loadProgram chooses it
    // (robot_choice.h) and gives the cell back with that robot first.
    LoadedProgram first = loadProgram(request);
    const std::size_t r = first.cell && first.cell->drivenRobot()
                              ? cell.robotLabeled(first.cell->drivenRobot()->labelOf())
                              : workcell::kNoIndex;
    if (r == workcell::kNoIndex) {
      into.loaded.push_back(std::move(first));  // its diagnostics say why
      return false;
    }
    files[r] = {request.file, std::move(first)};
  }
  bool ok = true;
  for (const std::string& arg : assignments) {
    const std::size_t eq = arg.find('=');
    const std::string label = arg.substr(0, eq), file = eq == std::string::npos ? "" : arg.substr(eq + 1);
    const std::size_t r = cell.robotLabeled(label);
    if (!isProgramAssignment(arg) || file.empty() || r == workcell::kNoIndex) {
      diag::Diagnostic d{base::safeText(arg), {}, diag::Severity::Error,
                         r == workcell::kNoIndex && isProgramAssignment(arg)
                             ? fmt::format("workcell {} has no robot labelled `{}`", base::safeText(cell.name),
                                           base::safeText(label))
                             : std::string("a program for a robot of the cell is given as LABEL=FILE"),
                         "unknown-robot",
                         fmt::format("the cell's robots are {}", robotLabelsOf(cell))};
      into.cellLoad.diagnostics.push_back(std::move(d));
      ok = false;
      continue;
    }
    files[r] = {file, std::nullopt};
  }
  if (!ok) return false;
  for (std::size_t r = 0; r < files.size(); ++r) {
    if (files[r].file.empty()) continue;
    into.labels.push_back(cell.robots[r].labelOf());
    into.files.push_back(files[r].file);
    into.programs.push_back({r, nullptr});
    into.loaded.push_back(files[r].loaded ? std::move(*files[r].loaded) : LoadedProgram{});
  }
  if (into.programs.empty()) {
    into.cellLoad.diagnostics.push_back(
        {base::safeText(request.cell), {}, diag::Severity::Error,
         fmt::format("no ROBOT line of workcell {} names a PROGRAM", base::safeText(cell.name)), {},
         "give the programs as LABEL=FILE, or write PROGRAM FILE on a ROBOT line"});
    return false;
  }
  return true;
}

void compileAssignedPrograms(const ProgramRequest& request, CellPrograms& into) {
  for (std::size_t p = 0; p < into.programs.size(); ++p) {
    LoadedProgram& loaded = into.loaded[p];
    if (!loaded.image && loaded.diagnostics.empty()) {  // not the command line's, compiled already
      ProgramRequest one = request;
      one.file = into.files[p];
      one.robot = into.labels[p];
      loaded = loadProgram(one);
    }
    into.programs[p].image = loaded.image;
  }
}

}  // namespace rs::launch
