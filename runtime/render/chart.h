// A run over time as data (`robotsim plot`, the chart under the animation
// page's scrub bar): every motor, the tool centre point's x, y and z, the
// gripper, the eight inputs and outputs sampled at evenly spaced moments of
// a logged run, the source line in progress, and the moments to mark
// (collisions, warnings, a failed stop). chart_draw.h draws it with cairo;
// chartCsv writes the samples for a spreadsheet (docs/render.md, "Charts
// of a run").
//
// Why sampled from the log: runtime::stateAt answers any moment exactly as
// the simulated machine would (its rounding included), so a sample is the
// machine's own value, not an interpolation of the picture's.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "model/workcell/model.h"
#include "runtime/run/run_log.h"

namespace rs::render {

/// What a lane shows: one motor, one coordinate of the tool centre point
/// (x, y and z each a lane of its own, on its own scale: a lift of 60 shows
/// beside a reach of 1000), the gripper's motor, eight inputs or outputs
/// (on/off traces), and on a cell with devices a row per sensor (ON while
/// it sees a part) and per conveyor (ON while its belt runs).
enum class LaneKind : std::uint8_t { Motor, Tcp, Gripper, Inputs, Outputs, Sensors, Conveyors };

struct ChartSeries {
  std::string column;          ///< CSV header: "A", "tcp_x", "gripper", "in1", "out8"
  std::vector<double> values;  ///< one per sample
};

struct ChartLane {
  LaneKind kind = LaneKind::Motor;
  std::string label;           ///< "A revolute", "TCP x", "gripper E", "inputs", "outputs", "sensors", "conveyors"
  std::vector<std::size_t> series;  ///< indices into Chart::series
  int axis = 0;                ///< Tcp: the coordinate shown, 0 x, 1 y, 2 z
  std::vector<std::string> rows = {};  ///< Sensors, Conveyors: each row's name (inputs and outputs: numbered)
  /// The lane group it belongs to, titled above its first lane: in a chart
  /// of a cell of several robots, the robot's label ("cell" for the
  /// devices' lanes); "" in a chart of one robot.
  std::string group = {};
};

enum class MarkKind : std::uint8_t { Collision, Warning, Stop };

/// A moment to mark across the chart.
struct ChartMark {
  MarkKind kind = MarkKind::Warning;
  vm::Micros at = 0;
  std::string text;  ///< "link 2 (arm) hits object 1 (pallet)", shown beside the mark
};

/// From `at` on, source line `line` is in progress (0: none yet).
struct LineChange {
  vm::Micros at = 0;
  std::uint32_t line = 0;
};

struct ChartInput {
  const workcell::Workcell* cell = nullptr;  ///< robot `robot` of it ran the program; null: no TCP
  const runtime::RunLog* run = nullptr;
  std::span<const std::uint32_t> lineOf;     ///< the source line of each instruction (vm::Image::lines)
  std::vector<ChartMark> marks;
  vm::Micros every = 0;  ///< the sample interval; 0: chartInterval's
  std::string title;
  /// The robot of `cell` whose log `run` is (Workcell::drivenRobotIndex
  /// for a run of one), and the end of the time axis when it is a cell's,
  /// later than this robot's end (0: the log's end).
  std::size_t robot = 0;
  vm::Micros end = 0;
  /// In a cell of several robots, each robot's log by Workcell::robots
  /// index: a belt another robot's output runs (runtime/run/device_history.h).
  std::span<const runtime::RunLog* const> robotLogs;
};

struct Chart {
  std::string title;
  vm::Micros end = 0;             ///< the run's end; the time axis is 0..end
  std::vector<vm::Micros> times;  ///< 0, every, 2·every, ..., and the end
  std::vector<ChartSeries> series;
  std::vector<ChartLane> lanes;   ///< top to bottom
  std::vector<std::uint32_t> lines;     ///< the line in progress at each sample (0: none)
  std::vector<LineChange> lineChanges;  ///< every change of the line in progress, over all steps
  std::vector<ChartMark> marks;         ///< by time
};

/// The interval chartOf samples at by default: the smallest of 1, 2 and 5
/// times a power of ten microseconds that cuts 0..end into at most
/// `samples` intervals.
vm::Micros chartInterval(vm::Micros end, std::size_t samples = 1000);

/// The most samples a chart takes (a finer --every is refused).
inline constexpr std::size_t kMaxChartSamples = 1'000'000;

/// The chart of a logged run.
Chart chartOf(const ChartInput& input);

/// The samples as CSV: a header row ("time_s", the motors by letter,
/// "tcp_x", "tcp_y", "tcp_z", "gripper" when there is one, "in1".."in8",
/// "out1".."out8", then "sensor_NAME" per sensor and "belt_NAME" per
/// conveyor on a cell with devices, "line"), then one row a sample; times in seconds with
/// six decimals, lengths with three, counts and on/off (1/0) as integers.
std::string chartCsv(const Chart& chart);

}  // namespace rs::render
