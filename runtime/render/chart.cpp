#include "runtime/render/chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string_view>

#include "model/workcell/tool_tracker.h"
#include "runtime/run/device_history.h"

namespace rs::render {

namespace {

// The sample times: 0, every, 2·every, ... up to the end, and the end.
std::vector<vm::Micros> sampleTimes(vm::Micros end, vm::Micros every) {
  std::vector<vm::Micros> times;
  const auto count = static_cast<std::size_t>(end / every) + 2;
  times.reserve(count);
  for (vm::Micros t = 0; t < end; t += every) times.push_back(t);
  times.push_back(end);
  return times;
}

const char* jointKindWord(vm::JointKind kind) {
  switch (kind) {
    case vm::JointKind::Gripper: return "gripper";
    case vm::JointKind::Prismatic: return "prismatic";
    case vm::JointKind::Revolute: break;
  }
  return "revolute";
}

// The object the gripper holds (1-based, 0: none) at times that only
// grow: the last take or let-go that had happened by then.
class HeldObject {
 public:
  explicit HeldObject(const runtime::RunLog& log) : grasps_(log.grasps) {}
  std::uint32_t at(vm::Micros t) {
    for (; next_ < grasps_.size() && grasps_[next_].event.at <= t; ++next_)
      held_ = grasps_[next_].event.held ? static_cast<std::uint32_t>(grasps_[next_].event.object + 1) : 0;
    return held_;
  }

 private:
  const std::vector<runtime::GraspRecord>& grasps_;
  std::size_t next_ = 0;
  std::uint32_t held_ = 0;
};

// Every change of the source line in progress: a step starts a new line
// when its line differs from the step before.
std::vector<LineChange> lineChangesOf(const runtime::RunLog& log, std::span<const std::uint32_t> lineOf) {
  std::vector<LineChange> out;
  std::uint32_t last = 0;
  for (const runtime::StepRecord& s : log.steps) {
    const std::uint32_t line = s.index < lineOf.size() ? lineOf[s.index] : 0;
    if (line == last) continue;
    if (!out.empty() && out.back().at == s.start)
      out.back().line = line;  // instructions that took no time: the last one at that moment stands
    else
      out.push_back({s.start, line});
    last = line;
  }
  return out;
}

// A value with `decimals` decimals, never "-0.000".
std::string csvNumber(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

// Microseconds as seconds with six decimals, exactly.
std::string csvSeconds(vm::Micros t) { return fmt::format("{}.{:06}", t / 1'000'000, t % 1'000'000); }

}  // namespace

vm::Micros chartInterval(vm::Micros end, std::size_t samples) {
  const auto n = static_cast<vm::Micros>(std::max<std::size_t>(samples, 1));
  for (vm::Micros power = 1; power <= INT64_MAX / 50 / n; power *= 10)
    for (const vm::Micros m : {1, 2, 5})
      if (end <= m * power * n) return m * power;
  return end / n + 1;
}

Chart chartOf(const ChartInput& input) {
  const runtime::RunLog& log = *input.run;
  Chart chart;
  chart.title = input.title;
  chart.end = std::max(log.end, input.end);
  const vm::Micros every = input.every > 0 ? input.every : chartInterval(chart.end);
  chart.times = sampleTimes(chart.end, every);
  const std::size_t n = chart.times.size();

  // Columns: each motor, the TCP, what the gripper holds, inputs, outputs.
  const std::size_t motors = log.motors.size();
  for (const vm::MotorSpec& m : log.motors) chart.series.push_back({std::string(1, m.letter), {}});
  const workcell::PlacedRobot* driven =
      input.cell && input.robot < input.cell->robots.size() ? &input.cell->robots[input.robot] : nullptr;
  const workcell::PlacedRobot* robot = driven && driven->robot.chain ? driven : nullptr;
  const std::size_t tcp = chart.series.size();
  if (robot)
    for (const char* c : {"tcp_x", "tcp_y", "tcp_z"}) chart.series.push_back({c, {}});
  std::optional<std::size_t> gripper;
  for (std::size_t m = 0; m < motors; ++m)
    if (log.motors[m].kind == vm::JointKind::Gripper) gripper = m;
  const std::size_t held = chart.series.size();
  if (gripper) chart.series.push_back({"held", {}});
  const std::size_t inputs = chart.series.size();
  for (int i = 1; i <= vm::kIoCount; ++i) chart.series.push_back({fmt::format("in{}", i), {}});
  const std::size_t outputs = chart.series.size();
  for (int i = 1; i <= vm::kIoCount; ++i) chart.series.push_back({fmt::format("out{}", i), {}});
  // The cell's devices: a series per sensor and per conveyor.
  const workcell::Devices* devices = input.cell && !input.cell->devices.empty() ? &input.cell->devices : nullptr;
  const std::size_t sensors = chart.series.size();
  if (devices)
    for (const workcell::Sensor& s : devices->sensors) chart.series.push_back({"sensor_" + s.name, {}});
  const std::size_t conveyors = chart.series.size();
  if (devices)
    for (const workcell::Conveyor& c : devices->conveyors) chart.series.push_back({"belt_" + c.name, {}});
  std::optional<runtime::DeviceHistory> history;
  if (devices) history.emplace(log, *input.cell, input.robotLogs);
  for (ChartSeries& s : chart.series) s.values.reserve(n);
  chart.lines.reserve(n);

  HeldObject heldObject(log);
  std::optional<workcell::ToolTracker> tracker;
  if (robot) tracker.emplace(*robot);
  for (const vm::Micros t : chart.times) {
    const runtime::RunState state = runtime::stateAt(log, t);
    for (std::size_t m = 0; m < motors; ++m) chart.series[m].values.push_back(state.encoders[m]);
    if (tracker) {
      const std::array<double, 3> p = tracker->tcp(state.encoders);
      for (std::size_t a = 0; a < 3; ++a) chart.series[tcp + a].values.push_back(p[a]);
    }
    if (gripper) chart.series[held].values.push_back(heldObject.at(t));
    for (int i = 0; i < vm::kIoCount; ++i) {
      chart.series[inputs + static_cast<std::size_t>(i)].values.push_back((state.inputs >> i) & 1);
      chart.series[outputs + static_cast<std::size_t>(i)].values.push_back((state.outputs >> i) & 1);
    }
    if (history) {
      for (std::size_t s = 0; s < devices->sensors.size(); ++s) chart.series[sensors + s].values.push_back(history->sensorOn(s, t));
      for (std::size_t c = 0; c < devices->conveyors.size(); ++c)
        chart.series[conveyors + c].values.push_back(history->conveyorRunning(c, t));
    }
    const std::uint32_t index = state.step ? log.steps[*state.step].index : UINT32_MAX;
    chart.lines.push_back(index < input.lineOf.size() ? input.lineOf[index] : 0);
  }

  // Lanes, top to bottom: the arm's motors, the TCP, the gripper, inputs, outputs.
  for (std::size_t m = 0; m < motors; ++m)
    if (!gripper || m != *gripper)
      chart.lanes.push_back({LaneKind::Motor, fmt::format("{} {}", log.motors[m].letter, jointKindWord(log.motors[m].kind)), {m}});
  if (robot)
    for (int a = 0; a < 3; ++a)
      chart.lanes.push_back({LaneKind::Tcp, fmt::format("TCP {}", "xyz"[a]), {tcp + static_cast<std::size_t>(a)}, a});
  if (gripper) chart.lanes.push_back({LaneKind::Gripper, fmt::format("{} gripper", log.motors[*gripper].letter), {*gripper}});
  ChartLane in{LaneKind::Inputs, fmt::format("inputs 1-{}", vm::kIoCount), {}},
      out{LaneKind::Outputs, fmt::format("outputs 1-{}", vm::kIoCount), {}};
  for (std::size_t i = 0; i < static_cast<std::size_t>(vm::kIoCount); ++i) in.series.push_back(inputs + i), out.series.push_back(outputs + i);
  chart.lanes.push_back(std::move(in));
  chart.lanes.push_back(std::move(out));
  if (devices && !devices->sensors.empty()) {
    ChartLane lane{LaneKind::Sensors, "sensors", {}};
    for (std::size_t s = 0; s < devices->sensors.size(); ++s)
      lane.series.push_back(sensors + s), lane.rows.push_back(devices->sensors[s].name);
    chart.lanes.push_back(std::move(lane));
  }
  if (devices && !devices->conveyors.empty()) {
    ChartLane lane{LaneKind::Conveyors, "conveyors", {}};
    for (std::size_t c = 0; c < devices->conveyors.size(); ++c)
      lane.series.push_back(conveyors + c), lane.rows.push_back(devices->conveyors[c].name);
    chart.lanes.push_back(std::move(lane));
  }

  chart.lineChanges = lineChangesOf(log, input.lineOf);
  chart.marks = input.marks;
  std::stable_sort(chart.marks.begin(), chart.marks.end(),
                   [](const ChartMark& a, const ChartMark& b) { return a.at < b.at; });
  return chart;
}

std::string chartCsv(const Chart& chart) {
  std::string out = "time_s";
  for (const ChartSeries& s : chart.series) out += ',' + s.column;
  out += ",line\n";
  for (std::size_t i = 0; i < chart.times.size(); ++i) {
    out += csvSeconds(chart.times[i]);
    for (const ChartSeries& s : chart.series) {
      // "tcp_x", or in a cell's chart "left.tcp_x" (cell_chart.h).
      const bool length = std::string_view(s.column).substr(s.column.find('.') + 1).starts_with("tcp_");
      out += ',' + csvNumber(s.values[i], length ? 3 : 0);
    }
    out += fmt::format(",{}\n", chart.lines[i]);
  }
  return out;
}

}  // namespace rs::render
