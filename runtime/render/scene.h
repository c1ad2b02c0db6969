// The workcell's lines in world coordinates for given motor positions: the
// paper's drawing rule. Each link is drawn at home in design coordinates
// and moves with its frame i:
//
//   p_world = F_world_i(q) · F_world_i(home)⁻¹ · F_world_design · p
//
// (link 0 never moves). The gripper's base moves with the end-effector
// frame n the same way; a finger point is first turned by its finger
// transform (in design coordinates), then moved like the base. Objects
// are drawn where the workcell placed them, or where setObjectPose says.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/kinematics/chain_data.h"
#include "model/workcell/model.h"

namespace rs::render {

/// What a line belongs to: for dumps, tests and the HTML page.
enum class PartKind : std::uint8_t { Link, GripperBase, Finger2, Finger3, Object, Axis, Sensor };

struct Part {
  PartKind kind = PartKind::Link;
  int owner = 0;  ///< robot index (object index for Object, sensor index for Sensor)
  int index = 0;  ///< link number; frame number for Axis
  int axis = 0;   ///< Axis only: 0 = x, 1 = y, 2 = z
};

/// One line of the picture in world coordinates.
struct Line3 {
  Eigen::Vector3d a, b;
  workcell::Color color = workcell::Color::White;
  Part part;
};

/// Colours of the drawn link frames (AXES ON): x, y, z.
inline constexpr workcell::Color kAxisColors[3] = {workcell::Color::LightRed, workcell::Color::LightGreen,
                                                   workcell::Color::LightBlue};
/// Length of each drawn frame axis, as a fraction of the fitted radius.
inline constexpr double kAxisLength = 0.08;

/// The colour of a sensor while it is ON (a broken beam, an occupied zone).
inline constexpr workcell::Color kSensorOnColor = workcell::Color::LightMagenta;

/// An object placed lower than this is not in the cell (a feeder's empty
/// slot, a part a sink took: runtime/cell/devices.h parks them at y = -1e7):
/// neither drawn nor fitted.
inline constexpr double kNotInCellBelow = -1e6;

/// Poses the robots of a workcell and lists its lines. Holds one
/// kinematics workspace per robot, built once; posing does not allocate.
class CellPoser {
 public:
  /// `cell` must outlive the poser. Every robot starts at home.
  explicit CellPoser(const workcell::Workcell& cell);

  const workcell::Workcell& cell() const { return *cell_; }
  /// Motors of robot `robot` as a program sees them (arm joints, then the
  /// gripper); missing trailing values count as 0.
  void setEncoders(std::size_t robot, std::span<const std::int32_t> encoders);
  std::span<const std::int32_t> encoders(std::size_t robot) const { return robots_[robot].encoders; }
  /// Where object `o` is drawn (F_world_design of its lines): where the
  /// workcell placed it until set, e.g. to where a gripper carried it.
  void setObjectPose(std::size_t o, const Eigen::Isometry3d& pose) { objects_[o] = pose; }
  /// Sensor `s` (the cell's devices.sensors) is ON: drawn, in
  /// kSensorOnColor (a beam as the line between its ends, a zone as its
  /// box). A sensor that is OFF is not drawn.
  void setSensorOn(std::size_t s, bool on) { sensorsOn_[s] = on; }

  /// Every line: each robot's links, gripper base and fingers, then the
  /// objects in the cell, then the sensors that are ON; with `axisLength` >
  /// 0 also each robot's frames 0..n.
  void lines(std::vector<Line3>& out, double axisLength = 0.0) const;

  /// Frame i (0..n) of robot `robot` in the world, at the current pose.
  const Eigen::Isometry3d& frame(std::size_t robot, std::size_t i) const { return robots_[robot].F_world_i[i]; }
  std::size_t frameCount(std::size_t robot) const { return robots_[robot].F_world_i.size(); }
  /// Origin of the last frame: the tool centre point when there is a gripper.
  Eigen::Vector3d tool(std::size_t robot) const { return robots_[robot].F_world_i.back().translation(); }
  /// Whether pictures mark robot `robot`'s tool centre point: it has a
  /// chain with a joint or a gripper (a bare base has no tool).
  bool hasToolMark(std::size_t robot) const;

  /// Both ends of every line at home (what pictures are fitted to).
  std::span<const Eigen::Vector3d> homePoints() const { return homePoints_; }

  /// F_world_i(home)⁻¹ · F_world_design for frame i: takes design points
  /// into frame i's coordinates (what the HTML page's model stores).
  const Eigen::Isometry3d& designInFrame(std::size_t robot, std::size_t i) const { return robots_[robot].M[i]; }

 private:
  struct RobotState {
    std::optional<kinematics::ChainModel> chain;  // placed in the world
    std::optional<kinematics::ChainData> data;
    std::vector<Eigen::Isometry3d> M;          // F_world_i(home)⁻¹ · F_world_design
    std::vector<Eigen::Isometry3d> F_world_i;  // current pose, frames 0..n
    std::vector<std::int32_t> encoders;
    std::vector<double> q;
  };
  void pose(std::size_t robot);

  const workcell::Workcell* cell_;
  std::vector<RobotState> robots_;
  std::vector<Eigen::Isometry3d> objects_;  // F_world_design of each object
  std::vector<bool> sensorsOn_;
  std::vector<Eigen::Vector3d> homePoints_;
};

}  // namespace rs::render
