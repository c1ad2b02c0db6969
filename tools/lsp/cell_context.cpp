#include "tools/lsp/cell_context.h"

#include <fmt/format.h>

#include <system_error>

#include "compiler/description/library.h"
#include "launch/program.h"
#include "launch/robot_choice.h"
#include "stdlib/default_robot.h"

namespace rs::lsp {

namespace fs = std::filesystem;

std::string findDescriptionFile(const std::string& name, const std::vector<fs::path>& searchPath) {
  std::error_code ec;
  if ((name.ends_with(".rsd") || name.ends_with(".urdf")) && fs::is_regular_file(name, ec))
    return fs::absolute(name, ec).string();
  for (const fs::path& dir : searchPath)
    for (const char* folder : {"", "workcells", "robots", "grippers", "objects", "links"}) {
      const fs::path candidate = dir / folder / (name + ".rsd");
      if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
    }
  return {};
}

void CellCache::setLibDirs(std::vector<std::string> libDirs) {
  libDirs_ = std::move(libDirs);
  cache_.clear();
}

std::vector<fs::path> CellCache::searchPath() const { return compiler::librarySearchPath(libDirs_); }

std::shared_ptr<const CellContext> CellCache::get(const std::string& name) {
  if (const auto it = cache_.find(name); it != cache_.end()) return it->second;
  auto context = std::make_shared<CellContext>();
  context->name = name;
  context->target = launch::defaultTarget();
  compiler::Library library(searchPath());
  if (!name.empty()) {
    if (std::optional<workcell::Workcell> cell = library.workcell(name); cell && !cell->robots.empty()) {
      context->cell = std::make_shared<const workcell::Workcell>(std::move(*cell));
      context->target = launch::cellTarget(*context->cell);
      const workcell::PlacedRobot& driven = *context->cell->drivenRobot();  // the cell has a robot
      if (driven.robot.chain) context->robot = driven;
    } else {
      context->problem = library.diagnostics().empty() ? std::string("the workcell has no robot")
                                                       : library.diagnostics().front().message;
      // A problem inside a URDF cell's XML says where.
      for (const diag::Diagnostic& d : library.diagnostics())
        if (d.severity == diag::Severity::Error && urdf::isUrdfName(d.file)) {
          context->problem = d.pos.line > 0 ? fmt::format("{} (at {}:{}:{})", d.message, d.file, d.pos.line, d.pos.col)
                                            : d.message;
          break;
        }
    }
  }
  if (!context->cell) {
    compiler::Library defaults(searchPath());
    if (std::optional<workcell::Robot> robot = defaults.robot(std::string(stdlib::rhinoScaraName()));
        robot && robot->chain)
      context->robot = workcell::PlacedRobot{std::move(*robot), Eigen::Isometry3d::Identity()};
  }
  // The straight lines' path check costs a plan of each line: it is made
  // with the run, on the run worker's thread (checked_run.h), not in the
  // compile every request waits for.
  context->target.checkLines = false;
  cache_[name] = context;
  return context;
}

std::shared_ptr<const CellContext> CellCache::forProgram(const std::string& name, const std::string& path,
                                                         const std::optional<launch::CellDirective>& robot) {
  std::shared_ptr<const CellContext> base = get(name);
  if (!base->cell || (base->cell->robots.size() <= 1 && !robot)) return base;
  const std::string key = name + '\n' + (robot ? robot->name : std::string()) + '\n' + path;
  if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
  launch::ProgramRequest request;
  request.file = path;
  launch::LoadedProgram scratch;
  const std::shared_ptr<const workcell::Workcell> cell = launch::driveProgramsRobot(base->cell, request, robot, scratch);
  auto context = std::make_shared<CellContext>(*base);
  if (!cell) {
    const diag::Diagnostic& d = scratch.diagnostics.front();
    context->robotProblem = d.hint.empty() ? d.message : fmt::format("{} ({})", d.message, d.hint);
    context->robotProblemPos = d.pos;
  } else if (cell != base->cell) {
    context->cell = cell;
    context->target = launch::cellTarget(*cell);
    context->target.checkLines = false;  // as get(): with the run
    const workcell::PlacedRobot& driven = *cell->drivenRobot();
    context->robot.reset();
    if (driven.robot.chain) context->robot = driven;
  }
  cache_[key] = context;
  return context;
}

}  // namespace rs::lsp
