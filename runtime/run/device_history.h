// The cell's devices over a logged run (runtime/cell/devices.h), for the
// pictures and the chart: when each sensor was ON and each belt ran, and
// where each part rested at any time (a belt carries it, a feeder puts it,
// a sink takes it). Read from the log's device events, its part motions
// and its grasps; the same answers at any time, whatever the run did next.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/model.h"
#include "runtime/run/run_log.h"

namespace rs::runtime {

class DeviceHistory {
 public:
  /// `cell` is the run's (Rig::cell(): with its feeders' slots); both must
  /// outlive the history. In a cell of several robots, `robotLogs` holds
  /// each robot's log (by Workcell::robots index; null: it kept none), so
  /// that a belt another robot's output runs is seen running.
  DeviceHistory(const RunLog& log, const workcell::Workcell& cell, std::span<const RunLog* const> robotLogs = {});

  /// Sensor `s` (in Workcell::devices.sensors) is ON at `t` (after every edge due at t).
  bool sensorOn(std::size_t s, vm::Micros t) const;
  /// Conveyor `c`'s belt runs at `t`: its RUN signal is ON (ON, a robot's
  /// output, a sensor; another robot's output without its log is OFF).
  bool conveyorRunning(std::size_t c, vm::Micros t) const;
  /// Where object `o` rests at `t` (F_world_design), or nullopt while the
  /// gripper holds it (it goes with the gripper: its take's pose). Before
  /// anything moved it, where the cell placed it.
  std::optional<Eigen::Isometry3d> restingPose(std::size_t o, vm::Micros t) const;

 private:
  struct Edge {
    vm::Micros at = 0;
    bool on = false;
  };
  // One thing that put object o somewhere: a grasp record or a motion record.
  struct Entry {
    vm::Micros at = 0;
    const GraspRecord* grasp = nullptr;
    const MotionRecord* motion = nullptr;
  };
  bool signalAt(const workcell::Signal& s, vm::Micros t) const;

  const RunLog& log_;
  const workcell::Workcell& cell_;
  std::span<const RunLog* const> robotLogs_;
  std::vector<std::vector<Edge>> sensorEdges_;  // per sensor, in time order
  std::vector<std::vector<Entry>> entries_;     // per object, in the order they happened
};

/// Whether a pose is a parked one (runtime/cell/devices.h parkedPose: a
/// feeder's empty slot, a part a sink took): not in the cell, not drawn.
bool isParked(const Eigen::Isometry3d& pose);

}  // namespace rs::runtime
