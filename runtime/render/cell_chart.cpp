#include "runtime/render/cell_chart.h"

#include <algorithm>

namespace rs::render {

Chart cellChartOf(const CellChartInput& input) {
  Chart chart;
  chart.title = input.title;
  for (const RobotChart& r : input.robots) chart.end = std::max(chart.end, r.run->end);
  const vm::Micros every = input.every > 0 ? input.every : chartInterval(chart.end);
  std::vector<ChartLane> cellLanes;  // the devices' lanes, once
  for (std::size_t i = 0; i < input.robots.size(); ++i) {
    const RobotChart& r = input.robots[i];
    ChartInput one;
    one.cell = input.cell;
    one.run = r.run;
    one.lineOf = r.lineOf;
    one.every = every;
    one.robot = r.robot;
    one.end = chart.end;
    one.robotLogs = input.robotLogs;
    for (ChartMark m : r.marks) {
      m.text = r.label + ": " + m.text;
      one.marks.push_back(std::move(m));
    }
    Chart c = chartOf(one);
    const std::size_t offset = chart.series.size();
    for (ChartSeries& s : c.series) {
      const bool device = s.column.starts_with("sensor_") || s.column.starts_with("belt_");
      if (!device) s.column = r.label + "." + s.column;
      chart.series.push_back(std::move(s));
    }
    for (ChartLane& lane : c.lanes) {
      for (std::size_t& s : lane.series) s += offset;
      const bool device = lane.kind == LaneKind::Sensors || lane.kind == LaneKind::Conveyors;
      if (device && i > 0) continue;  // the same devices: drawn once, from the first robot's samples
      lane.group = device ? "cell" : r.label;
      (device ? cellLanes : chart.lanes).push_back(std::move(lane));
    }
    if (i == 0) chart.times = c.times, chart.lines = c.lines, chart.lineChanges = c.lineChanges;
    chart.marks.insert(chart.marks.end(), c.marks.begin(), c.marks.end());
  }
  // A later robot's device columns repeat the first's: only the first robot's stay.
  std::vector<ChartSeries> kept;
  std::vector<std::size_t> index(chart.series.size(), 0);
  std::vector<std::string> seen;
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    const std::string& column = chart.series[s].column;
    const bool device = column.starts_with("sensor_") || column.starts_with("belt_");
    if (device && std::find(seen.begin(), seen.end(), column) != seen.end()) continue;
    if (device) seen.push_back(column);
    index[s] = kept.size();
    kept.push_back(std::move(chart.series[s]));
  }
  for (ChartLane& lane : chart.lanes)
    for (std::size_t& s : lane.series) s = index[s];
  for (ChartLane& lane : cellLanes) {
    for (std::size_t& s : lane.series) s = index[s];
    chart.lanes.push_back(std::move(lane));
  }
  chart.series = std::move(kept);
  std::stable_sort(chart.marks.begin(), chart.marks.end(),
                   [](const ChartMark& a, const ChartMark& b) { return a.at < b.at; });
  return chart;
}

}  // namespace rs::render
