// The chart of a cell of several robots (`robotsim plot --cell CELL`, the
// animation page of a cell): a lane group per robot, titled with its label
// (its motors, its tool centre point, its gripper, its inputs and outputs,
// each sampled from its own log), over one time axis to the cell's end.
// The source lines lane is the first robot's; the marks are every robot's,
// each named by its robot.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "runtime/render/chart.h"

namespace rs::render {

/// One robot of the cell and its run.
struct RobotChart {
  std::string label;                      ///< the robot's label in the cell (AS)
  std::size_t robot = 0;                  ///< its index in Workcell::robots
  const runtime::RunLog* run = nullptr;   ///< its log
  std::span<const std::uint32_t> lineOf;  ///< its program's source line of each instruction
  std::vector<ChartMark> marks;
};

struct CellChartInput {
  const workcell::Workcell* cell = nullptr;  ///< the run's (with its feeders' slots)
  std::vector<RobotChart> robots;            ///< in the cell's order
  vm::Micros every = 0;                      ///< the sample interval; 0: chartInterval's of the cell's end
  std::string title;
  /// Each robot's log by Workcell::robots index (null: none), for the belts
  /// a robot's output runs. The devices' lanes are sampled from the first
  /// robot's log: give it every robot's device events (runtime/run/cell_log.h).
  std::vector<const runtime::RunLog*> robotLogs;
};

/// The chart: each robot's lanes (ChartLane::group its label) and its CSV
/// columns prefixed with its label and a dot ("left.A", "right.out1"); a
/// cell with devices adds their lanes once, as the group "cell".
Chart cellChartOf(const CellChartInput& input);

}  // namespace rs::render
