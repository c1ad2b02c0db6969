// What a teach pendant shows, as one value: every UI (the web page, the
// terminal pendant) reads this snapshot and nothing else, so both show the
// same thing. pendantJson is the page's form of it (docs/teach.md lists
// the fields).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/workcell/model.h"
#include "vm/image.h"
#include "vm/io_lines.h"
#include "vm/machine.h"

namespace rs::runtime {
class CellDevices;
}

namespace rs::teach {

/// The gripper as the pendant names it: its motor at the range's min is
/// open, at its max closed (model/workcell/grasp.h), anywhere else between.
enum class GripperState : std::uint8_t { None, Open, Closed, Between };

struct PendantObject {
  std::string name;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< F_world_design now
  bool held = false;
  bool moved = false;
  bool present = true;  ///< in the cell (a feeder's empty slot, a part a sink took: not)
};

/// A device of the cell (runtime/cell/devices.h) as the pendant shows it:
/// a sensor ON (`on`) and how many times it turned ON (`count`), or a
/// conveyor running and how many parts it carried.
struct PendantDevice {
  std::string name;
  bool on = false;
  std::uint64_t count = 0;
};

struct PendantPoint {
  std::string name;
  std::vector<std::int32_t> values;
  std::size_t line = 0;  ///< 1-based line in the program file
  bool readable = true;
  bool pose = false;  ///< written as a tool pose (`AT ...`): go to resolves it, re-teach asks pose or counts
};

/// One moment of the last move, for UIs that animate it.
struct MotionFrame {
  vm::Micros at = 0;  ///< since the move began
  std::vector<std::int32_t> encoders;
  std::vector<Eigen::Isometry3d> objects;  ///< each object's F_world_design
};

/// An axis a world or tool jog moves along or turns about
/// (workcell::JogAxis, without its direction).
struct PendantJogAxis {
  std::string name;  ///< "X", "RZ", "PITCH"
  bool rotation = false;
  std::string help;
};

struct PendantState {
  std::uint64_t revision = 0;  ///< grows with every change
  std::string program;         ///< the program file
  std::string cell;
  std::string device;  ///< the serial device, "" in simulation
  std::vector<vm::MotorSpec> motors;
  std::vector<std::int32_t> encoders;
  std::optional<std::array<double, 3>> tcp;  ///< in the cell's world coordinates
  /// The tool's approach (z) and normal (x) in world coordinates (with a chain).
  std::optional<std::array<double, 3>> approach, normal;
  /// The axes of a world and of a tool jog at this pose (empty without a chain).
  std::vector<PendantJogAxis> worldAxes, toolAxes;
  GripperState gripper = GripperState::None;
  vm::IoMask inputs = 0, outputs = 0;  ///< bit 0 = line 1
  std::vector<PendantObject> objects;
  /// The cell's devices (none without them): a sensor's `count` is how often
  /// it turned ON, a conveyor's the parts it carried, a feeder's (never `on`)
  /// the parts it fed.
  std::vector<PendantDevice> sensors, conveyors, feeders;
  std::vector<PendantPoint> points;
  vm::Micros clock = 0;  ///< the machine's clock
  std::vector<MotionFrame> motion;  ///< the last move, time-stepped (empty after a non-move)
  std::string message;  ///< what the last operation did, or why it did not
  bool failed = false;  ///< the last operation was refused or failed
  /// The limit a refused move met: "range", "reach", "singularity", "step",
  /// "collision" (workcell::jogLimitName), "" otherwise.
  std::string limit;
  std::string fault;    ///< the device failed: every motor stopped, nothing more is sent
  std::uint64_t fileHash = 0;
};

std::string_view gripperName(GripperState g);
/// The gripper of a robot with `motors` standing at `encoders` (None when
/// no motor is a gripper).
GripperState gripperState(const std::vector<vm::MotorSpec>& motors, const std::vector<std::int32_t>& encoders);

/// The cell's sensors (on, times turned ON) and conveyors (running, parts
/// carried) as `devices` has them now, into `state`; nothing without devices.
void addDeviceStates(const workcell::Workcell& cell, const runtime::CellDevices* devices, PendantState& state);

/// The page's JSON: {"revision", "program", "cell", "device", "motors":
/// [{"letter", "kind", "min", "max", "speed"}], "encoders", "tcp" (or
/// null), "approach", "normal" (or null), "jogAxes": {"world": [{"name",
/// "rotation", "help"}], "tool": [...]}, "gripper", "inputs", "outputs" (arrays of eight booleans),
/// "objects": [{"name", "pose" (12 numbers, column-major 3x4: F_world ·
/// F_placed⁻¹, what takes the object's drawing from where the cell placed
/// it to where it is), "held", "moved", "present"}], "devices":
/// {"sensors": [{"name", "on", "count"}], "conveyors": [{"name",
/// "running", "carried"}]}, "points": [{"name", "values",
/// "line", "readable", "pose"}], "clock", "motion": [{"at", "encoders",
/// "objects"}], "message", "failed", "limit", "fault", "fileHash" (16 hex digits)}.
/// `placed` holds each object's F_world_design where the cell placed it.
nlohmann::ordered_json pendantJson(const PendantState& state, const std::vector<Eigen::Isometry3d>& placed);

}  // namespace rs::teach
