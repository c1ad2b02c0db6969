#include "launch/robot_choice.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "base/text.h"

namespace rs::launch {
namespace {

// The robot whose PROGRAM is `file` (the same file once both are made
// absolute and normal), or kNoIndex.
std::size_t robotRunning(const workcell::Workcell& cell, const std::string& file) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::absolute(file, ec).lexically_normal();
  if (ec) return workcell::kNoIndex;
  for (std::size_t i = 0; i < cell.robots.size(); ++i) {
    if (cell.robots[i].program.empty()) continue;
    const std::filesystem::path theirs = std::filesystem::absolute(cell.robots[i].program, ec).lexically_normal();
    if (!ec && theirs == self) return i;
  }
  return workcell::kNoIndex;
}

}  // namespace

std::string robotLabelsOf(const workcell::Workcell& cell) {
  std::string out;
  for (const workcell::PlacedRobot& r : cell.robots)
    out += fmt::format("{}`{}`", out.empty() ? "" : ", ", base::safeText(r.labelOf()));
  return out;
}

std::shared_ptr<const workcell::Workcell> driveProgramsRobot(std::shared_ptr<const workcell::Workcell> cell,
                                                             const ProgramRequest& request,
                                                             const std::optional<CellDirective>& directive,
                                                             LoadedProgram& into) {
  if (!cell) return cell;
  std::size_t chosen = workcell::kNoIndex;
  if (!request.robot.empty() || directive) {
    const std::string& label = !request.robot.empty() ? request.robot : directive->name;
    chosen = cell->robotLabeled(label);
    if (chosen == workcell::kNoIndex) {
      const bool option = !request.robot.empty();
      into.diagnostics.push_back(
          {option ? std::string("--robot") : request.file, option ? diag::Pos{} : directive->pos,
           diag::Severity::Error,
           fmt::format("{} names robot `{}`, but workcell {} has no robot labelled so",
                       option ? "--robot" : "this program's '; robot:' line", base::safeText(label),
                       base::safeText(cell->name)),
           "unknown-robot",
           fmt::format("the cell's robots are {} (a ROBOT line's AS LABEL, or the description's name)",
                       robotLabelsOf(*cell))});
      return nullptr;
    }
  } else if (cell->robots.size() > 1) {
    chosen = robotRunning(*cell, request.file);
  }
  if (chosen == workcell::kNoIndex || chosen == cell->drivenRobotIndex()) return cell;
  auto moved = std::make_shared<workcell::Workcell>(*cell);
  const auto first = moved->robots.begin();
  std::rotate(first, first + static_cast<std::ptrdiff_t>(chosen), first + static_cast<std::ptrdiff_t>(chosen) + 1);
  return moved;
}

}  // namespace rs::launch
