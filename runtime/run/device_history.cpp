#include "runtime/run/device_history.h"

#include <algorithm>

#include "runtime/cell/devices.h"
#include "vm/io_lines.h"

namespace rs::runtime {

bool isParked(const Eigen::Isometry3d& pose) { return pose.translation().y() < parkedPose().translation().y() / 10; }

namespace {

// At one step and time, a let-go comes before the motion it starts (a part
// let go onto a running belt rides it), and a motion before a take (a part
// the belt brought is taken).
int orderAtOneTime(const GraspRecord* g) { return !g ? 1 : g->event.held ? 2 : 0; }

}  // namespace

DeviceHistory::DeviceHistory(const RunLog& log, const workcell::Workcell& cell, std::span<const RunLog* const> robotLogs)
    : log_(log), cell_(cell), robotLogs_(robotLogs) {
  sensorEdges_.resize(cell.devices.sensors.size());
  for (const DeviceRecord& r : log.devices) {
    const DeviceEvent& e = r.event;
    if (e.kind != DeviceEvent::Kind::SensorOn && e.kind != DeviceEvent::Kind::SensorOff) continue;
    if (e.device < sensorEdges_.size()) sensorEdges_[e.device].push_back({e.at, e.kind == DeviceEvent::Kind::SensorOn});
  }
  struct Keyed {
    std::uint32_t step;
    Entry entry;
  };
  std::vector<std::vector<Keyed>> keyed(cell.objects.size());
  for (const GraspRecord& g : log.grasps)
    if (g.event.object < keyed.size()) keyed[g.event.object].push_back({g.step, {g.event.at, &g, nullptr}});
  for (const MotionRecord& m : log.motions)
    if (m.motion.object < keyed.size()) keyed[m.motion.object].push_back({m.step, {m.motion.at, nullptr, &m}});
  entries_.resize(cell.objects.size());
  for (std::size_t o = 0; o < keyed.size(); ++o) {
    std::stable_sort(keyed[o].begin(), keyed[o].end(), [](const Keyed& a, const Keyed& b) {
      if (a.step != b.step) return a.step < b.step;
      if (a.entry.at != b.entry.at) return a.entry.at < b.entry.at;
      return orderAtOneTime(a.entry.grasp) < orderAtOneTime(b.entry.grasp);
    });
    for (const Keyed& k : keyed[o]) entries_[o].push_back(k.entry);
  }
}

bool DeviceHistory::sensorOn(std::size_t s, vm::Micros t) const {
  if (s >= sensorEdges_.size()) return false;
  const std::vector<Edge>& edges = sensorEdges_[s];
  const auto it = std::upper_bound(edges.begin(), edges.end(), t, [](vm::Micros v, const Edge& e) { return v < e.at; });
  return it != edges.begin() && (it - 1)->on;
}

bool DeviceHistory::signalAt(const workcell::Signal& s, vm::Micros t) const {
  const std::size_t robot = s.robot.empty() ? cell_.drivenRobotIndex() : cell_.robotLabeled(s.robot);
  const RunLog* outputs = robot < robotLogs_.size() ? robotLogs_[robot]
                          : robot == cell_.drivenRobotIndex() ? &log_
                                                              : nullptr;
  switch (s.kind) {
    case workcell::Signal::Kind::On: return true;
    case workcell::Signal::Kind::Off: return false;
    case workcell::Signal::Kind::Output:
      return outputs && !outputs->steps.empty() && vm::lineIsOn(stateAt(*outputs, t).outputs, s.number);
    case workcell::Signal::Kind::Input: return false;  // another robot's input: issue 36
    case workcell::Signal::Kind::Sensor: return sensorOn(s.sensor, t);
  }
  return false;
}

bool DeviceHistory::conveyorRunning(std::size_t c, vm::Micros t) const {
  return c < cell_.devices.conveyors.size() && signalAt(cell_.devices.conveyors[c].run, t);
}

std::optional<Eigen::Isometry3d> DeviceHistory::restingPose(std::size_t o, vm::Micros t) const {
  if (o >= entries_.size()) return std::nullopt;
  const std::vector<Entry>& list = entries_[o];
  const auto it = std::upper_bound(list.begin(), list.end(), t, [](vm::Micros v, const Entry& e) { return v < e.at; });
  if (it == list.begin()) return cell_.objects[o].F_world_design;
  const Entry& e = *(it - 1);
  if (e.motion) return e.motion->motion.poseAt(t);
  if (e.grasp->event.held) return std::nullopt;
  return e.grasp->event.pose;
}

}  // namespace rs::runtime
