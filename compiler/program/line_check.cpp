#include "compiler/program/line_check.h"

#include <optional>
#include <vector>

#include "model/workcell/line_path.h"

namespace rs::compiler {

void checkLinePaths(const vm::Image& image, const workcell::PlacedRobot& robot, diag::Diagnostics& diagnostics,
                    workcell::LinePlanCache* cache) {
  const std::size_t size = image.code.size();
  bool any = false;
  for (const vm::Instr& in : image.code) any = any || vm::has(in.op, vm::kStraight);
  if (!any) return;
  // Where control may arrive other than from the instruction before: a
  // jump's target, the instruction after a call (the subroutine moved).
  std::vector<bool> joined(size + 1, false);
  for (std::size_t i = 0; i < size; ++i) {
    const vm::Instr& in = image.code[i];
    if (vm::has(in.op, vm::kJumps)) joined[static_cast<std::size_t>(in.d)] = true;
    if (vm::has(in.op, vm::kCalls) || !vm::has(in.op, vm::kFallsThrough)) joined[i + 1] = true;
  }
  std::optional<workcell::LinePlanCache> own;
  if (!cache) cache = &own.emplace();
  const workcell::LinePlanner planner(robot, cache);
  workcell::LinePath path(planner);
  const std::size_t motors = image.motors.size();
  // Every motor starts at encoder 0.
  std::optional<std::vector<std::int32_t>> at(std::in_place, motors, 0);
  for (std::size_t i = 0; i < size; ++i) {
    const vm::Instr& in = image.code[i];
    if (joined[i]) at.reset();
    if (!vm::has(in.op, vm::kMovesMotors)) continue;
    const vm::Format format = vm::info(in.op).format;
    if (vm::has(in.op, vm::kStraight)) {
      if (!at) {
        if (format == vm::Format::Point) at = image.points[in.b].values;  // where it ends, unless it fails
        continue;
      }
      const std::optional<workcell::LineProblem> problem =
          format == vm::Format::Point
              ? planner.planTo(*at, image.points[in.b].values, path, vm::info(in.op).name)
              : planner.planAlongTool(*at, vm::has(in.op, vm::kStraightBack) ? -in.c : in.c, path,
                                      vm::info(in.op).name);
      if (problem) {
        diagnostics.error({image.lines[i], image.columns[i]}, problem->message, diag::Hint{problem->hint},
                          problem->code);
        at.reset();
      } else if (path.size() > 0) {
        const auto last = path.knot(path.size() - 1);
        at->assign(last.begin(), last.end());
      }
      continue;
    }
    if (format == vm::Format::MotorVector) {
      const std::int32_t* k = image.constants.data() + in.c;
      if (vm::has(in.op, vm::kRelative)) {
        if (at)
          for (std::size_t m = 0; m < motors; ++m) (*at)[m] += k[m];
      } else {
        at.emplace(k, k + motors);
      }
    } else if (format == vm::Format::Point) {
      at = image.points[in.b].values;
    } else {
      at.reset();  // a homing or RESET: not followed here
    }
  }
}

}  // namespace rs::compiler
